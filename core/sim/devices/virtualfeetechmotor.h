// The motor of a simulated Feetech servo: what its registers ask of the motion model
// (servomotion.h) and what the motor reports back into them. Pure logic: time passes through
// advance().
#pragma once

#include "registertable.h"
#include "servomotion.h"

#include <QByteArray>

namespace sim {

// A register of a simulated servo's register file in register units (0 for a register the table
// lacks), and a value put into one, clamped to what its format holds (nothing for none).
qint32 registerValue(const feetech::RegisterTable &table, const QByteArray &registers,
                     const feetech::Register *reg);
void putRegisterValue(const feetech::RegisterTable &table, QByteArray &registers,
                      const feetech::Register *reg, qint32 value);

// Reads and writes the servo's register file, which the servo passes in on every call (the
// servo is a value, copied with its registers; the motor keeps no pointer to them).
class VirtualFeetechMotor
{
public:
    // Integration of the motion model.
    static constexpr qint64 kMaxStepUs = 1000; // integration sub-step
    static constexpr qint64 kMaxCatchUpUs =
        600'000'000; // longer gaps integrate only the last 10 min
    static constexpr double kCurrentUnitAmps = 0.0065; // register 69 unit
    static constexpr double kAccelerationUnit = 100.0; // register 41 unit, step/s²

    VirtualFeetechMotor(const feetech::RegisterTable &table, double supplyVolts);

    // The physics itself, for the servo's environment hooks; report() afterwards puts what
    // changed into the registers.
    ServoMotion &motion() { return m_motion; }
    const ServoMotion &motion() const { return m_motion; }

    // Runs the motion model from `fromUs` to `toUs` as the registers ask, then reports.
    void advance(QByteArray &registers, qint64 fromUs, qint64 toUs);
    // The present position, speed, load, current, voltage, temperature, the moving flag and the
    // status bits into the registers.
    void report(QByteArray &registers) const;

private:
    // The registers the motor reads and writes.
    struct Keys
    {
        const feetech::Register *minAngle = nullptr;
        const feetech::Register *maxAngle = nullptr;
        const feetech::Register *maxTemperature = nullptr;
        const feetech::Register *maxVoltage = nullptr;
        const feetech::Register *minVoltage = nullptr;
        const feetech::Register *maxTorque = nullptr;
        const feetech::Register *cwDeadZone = nullptr;
        const feetech::Register *ccwDeadZone = nullptr;
        const feetech::Register *offset = nullptr;
        const feetech::Register *mode = nullptr;
        const feetech::Register *holdingTorque = nullptr;
        const feetech::Register *protectionTime = nullptr;
        const feetech::Register *overloadTorque = nullptr;
        const feetech::Register *torqueEnable = nullptr;
        const feetech::Register *acceleration = nullptr;
        const feetech::Register *goalPosition = nullptr;
        const feetech::Register *goalTime = nullptr; // 44: time / PWM / HLS goal current
        const feetech::Register *goalSpeed = nullptr;
        const feetech::Register *torqueLimit = nullptr;
        const feetech::Register *presentPosition = nullptr;
        const feetech::Register *presentSpeed = nullptr;
        const feetech::Register *presentLoad = nullptr;
        const feetech::Register *presentVoltage = nullptr;
        const feetech::Register *presentTemperature = nullptr;
        const feetech::Register *status = nullptr;
        const feetech::Register *moving = nullptr;
        const feetech::Register *currentGoal = nullptr;
        const feetech::Register *presentCurrent = nullptr;
    };

    feetech::Family family() const { return m_table->family(); }
    bool is4096() const { return family() != feetech::Family::Scs; }
    qint32 get(const QByteArray &registers, const feetech::Register *reg) const;
    // Clamps to what the register's format holds.
    void put(QByteArray &registers, const feetech::Register *reg, qint32 value) const;

    MotionControl control(const QByteArray &registers) const;
    double clampedGoal(const QByteArray &registers) const;
    // What the registers ask of the motor now.
    MotionCommand motionCommand(const QByteArray &registers) const;
    quint8 statusBits(const QByteArray &registers) const;

    const feetech::RegisterTable *m_table = nullptr;
    Keys m_keys;
    ServoMotion m_motion;
};

} // namespace sim
