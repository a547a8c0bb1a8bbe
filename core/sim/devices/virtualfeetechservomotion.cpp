// The simulated Feetech servo's side of its physics: what its registers ask of the motor
// (sim/servomotion.h) and what the motor reports back into them.
#include "virtualfeetechservo.h"

#include <algorithm>
#include <cmath>

namespace sim {

using feetech::Family;

// ---- driving the motion model ---------------------------------------------------------------

MotionControl VirtualFeetechServo::control() const
{
    if (family() == Family::Scs)
        return get(m_keys.minAngle) == 0 && get(m_keys.maxAngle) == 0 ? MotionControl::OpenLoop
                                                                      : MotionControl::Position;
    switch (get(m_keys.mode)) {
    case 1:
        return MotionControl::Wheel;
    case 2:
        return MotionControl::OpenLoop;
    case 3:
        // HLS: PWM open loop; STS step mode is not simulated and behaves as position mode.
        return family() == Family::Hls ? MotionControl::OpenLoop : MotionControl::Position;
    default:
        return MotionControl::Position;
    }
}

double VirtualFeetechServo::clampedGoal() const
{
    double goal = get(m_keys.goalPosition);
    const qint32 minimum = get(m_keys.minAngle);
    const qint32 maximum = get(m_keys.maxAngle);
    if (minimum != 0 || maximum != 0)
        goal = std::clamp(goal, double(minimum), double(std::max(minimum, maximum)));
    return std::clamp(
        goal, 0.0,
        double(is4096() ? ServoMotion::kFullCircleSteps - 1 : ServoMotion::kScsMaxPosition));
}

MotionCommand VirtualFeetechServo::motionCommand() const
{
    MotionCommand command;
    command.torqueEnable = get(m_keys.torqueEnable);
    command.control = control();
    command.goal = clampedGoal();
    command.offset = is4096() ? get(m_keys.offset) : 0;
    // Speed 0 and acceleration 0 mean "the model's maximum".
    const double modelMax = m_motion.maxSpeed();
    const qint32 goalSpeed = std::abs(get(m_keys.goalSpeed));
    command.maxSpeed = goalSpeed == 0 ? modelMax : std::min(double(goalSpeed), modelMax);
    const qint32 acceleration = get(m_keys.acceleration);
    command.acceleration =
        acceleration == 0 ? ServoMotion::kFastAcceleration : acceleration * kAccelerationUnit;
    if (command.control == MotionControl::Wheel) {
        command.openLoopSpeed =
            std::clamp(double(get(m_keys.goalSpeed)), -command.maxSpeed, command.maxSpeed);
    } else if (command.control == MotionControl::OpenLoop) {
        double duty;
        if (family() == Family::Hls && get(m_keys.mode) == 2) {
            duty = get(m_keys.goalTime) / 2047.0; // constant current ≈ speed
        } else {
            const quint16 raw = quint16(
                feetech::decodeRaw(QByteArrayView(m_registers).sliced(m_keys.goalTime->address, 2),
                                   m_table->byteOrder()));
            duty = feetech::fromSignMagnitude(raw & 0x7FF, 10) / 1000.0;
        }
        command.openLoopSpeed = std::clamp(duty, -1.0, 1.0) * modelMax;
    }
    // Registers in percent (holding, overload torque) and 10 ms (protection time) to permille
    // and seconds.
    command.torqueLimit = m_keys.torqueLimit ? get(m_keys.torqueLimit) : get(m_keys.maxTorque);
    if (m_keys.holdingTorque)
        command.holdingTorque = get(m_keys.holdingTorque) * 10.0;
    if (m_keys.overloadTorque && m_keys.protectionTime) {
        command.overloadTorque = get(m_keys.overloadTorque) * 10.0;
        command.protectionSeconds = get(m_keys.protectionTime) * 0.01;
    }
    if (m_keys.maxTemperature)
        command.maxTemperature = get(m_keys.maxTemperature);
    return command;
}

quint8 VirtualFeetechServo::statusBits() const
{
    quint8 bits = 0;
    const qint32 maxVoltage = get(m_keys.maxVoltage);
    const qint32 minVoltage = get(m_keys.minVoltage);
    const qint32 voltage = get(m_keys.presentVoltage);
    if ((maxVoltage != 0 || minVoltage != 0) && (voltage > maxVoltage || voltage < minVoltage))
        bits |= 0x01;
    if (m_keys.maxTemperature && get(m_keys.presentTemperature) >= get(m_keys.maxTemperature))
        bits |= 0x04;
    if (m_motion.overloaded())
        bits |= 0x20;
    return bits;
}

void VirtualFeetechServo::refreshRegisters()
{
    const int physical = int(std::lround(m_motion.position()));
    const int present = is4096() ? ServoMotion::wrapFullCircle(physical - get(m_keys.offset))
                                 : std::clamp(physical, 0, ServoMotion::kScsMaxPosition);
    put(m_keys.presentPosition, present);
    put(m_keys.presentSpeed, int(std::lround(m_motion.velocity())));
    put(m_keys.presentLoad, int(std::lround(m_motion.loadPermille())));
    put(m_keys.presentCurrent, int(std::lround(m_motion.amps() / kCurrentUnitAmps)));
    put(m_keys.presentVoltage, int(std::lround(m_motion.terminalVolts() * 10.0)));
    put(m_keys.presentTemperature, int(std::lround(m_motion.temperature())));

    const bool turning = m_motion.turning();
    bool away = false; // more than the dead zone from the goal
    if (get(m_keys.torqueEnable) == 1 && control() == MotionControl::Position) {
        const double deadZone = std::max(get(m_keys.cwDeadZone), get(m_keys.ccwDeadZone));
        const double goal = clampedGoal();
        away = std::abs(goal - m_motion.presentCoordinate(is4096() ? get(m_keys.offset) : 0))
            > deadZone;
        put(m_keys.currentGoal, int(std::lround(goal)));
    }
    // HLS splits the flag: bit 0 above the speed threshold, bit 1 not yet at the target.
    if (family() == Family::Hls)
        put(m_keys.moving, (turning ? 1 : 0) | (away ? 2 : 0));
    else
        put(m_keys.moving, turning || away ? 1 : 0);
    put(m_keys.status, statusBits());
}

void VirtualFeetechServo::advanceTo(qint64 nowUs)
{
    if (nowUs <= m_nowUs)
        return;
    qint64 at = std::max(m_nowUs, nowUs - kMaxCatchUpUs);
    while (at < nowUs) {
        const qint64 stepUs = std::min(kMaxStepUs, nowUs - at);
        if (m_motion.step(motionCommand(), double(stepUs) / 1e6))
            put(m_keys.torqueEnable, 0); // overheated
        at += stepUs;
    }
    m_nowUs = nowUs;
    refreshRegisters();
}

// ---- environment ----------------------------------------------------------------------------

void VirtualFeetechServo::setSupplyVoltage(double volts)
{
    m_motion.setSupplyVoltage(volts);
    refreshRegisters();
}

void VirtualFeetechServo::setAmbientTemperature(double celsius)
{
    m_motion.setAmbientTemperature(celsius);
}

void VirtualFeetechServo::setExternalLoad(int permille)
{
    m_motion.setExternalLoad(permille);
}

void VirtualFeetechServo::setOverloadLatched(bool latched)
{
    m_motion.setOverloadLatched(latched);
    refreshRegisters();
}

void VirtualFeetechServo::setTemperature(double celsius)
{
    m_motion.setTemperature(celsius);
    refreshRegisters();
}

void VirtualFeetechServo::setPhysicalPosition(double steps)
{
    m_motion.setPosition(steps);
    refreshRegisters();
}

} // namespace sim
