// The simulated Feetech servo's motor: what its registers ask of the motion model
// (servomotion.h) and what the motor reports back into them.
#include "virtualfeetechmotor.h"

#include <algorithm>
#include <cmath>

namespace sim {

using feetech::Family;
using feetech::Register;
using feetech::RegisterTable;

VirtualFeetechMotor::VirtualFeetechMotor(const feetech::RegisterTable &table, double supplyVolts)
    : m_table(&table)
    , m_motion(table.family() != Family::Scs, supplyVolts)
{
    const auto find = [&table](QStringView key) {
        return table.find(key);
    };
    m_keys.minAngle = find(u"min_angle_limit");
    m_keys.maxAngle = find(u"max_angle_limit");
    m_keys.maxTemperature = find(u"max_temperature");
    m_keys.maxVoltage = find(u"max_voltage");
    m_keys.minVoltage = find(u"min_voltage");
    m_keys.maxTorque = find(u"max_torque");
    m_keys.cwDeadZone = find(u"cw_dead_zone");
    m_keys.ccwDeadZone = find(u"ccw_dead_zone");
    m_keys.offset = find(u"position_offset");
    m_keys.mode = find(u"mode");
    m_keys.holdingTorque = find(u"holding_torque");
    m_keys.protectionTime = find(u"protection_time");
    m_keys.overloadTorque = find(u"overload_torque");
    m_keys.torqueEnable = find(u"torque_enable");
    m_keys.acceleration = family() == Family::Scs ? nullptr : find(u"acceleration");
    m_keys.goalPosition = find(u"goal_position");
    m_keys.goalTime = table.at(44);
    m_keys.goalSpeed = find(u"goal_speed");
    m_keys.torqueLimit = find(u"torque_limit");
    m_keys.presentPosition = find(u"present_position");
    m_keys.presentSpeed = find(u"present_speed");
    m_keys.presentLoad = find(u"present_load");
    m_keys.presentVoltage = find(u"present_voltage");
    m_keys.presentTemperature = find(u"present_temperature");
    m_keys.status = find(u"status");
    m_keys.moving = find(u"moving");
    m_keys.currentGoal = find(u"current_goal_position");
    m_keys.presentCurrent = find(u"present_current");
}

qint32 registerValue(const RegisterTable &table, const QByteArray &registers, const Register *reg)
{
    if (!reg)
        return 0;
    return feetech::decodeValue(QByteArrayView(registers).sliced(reg->address, reg->size),
                                table.format(*reg));
}

void putRegisterValue(const RegisterTable &table, QByteArray &registers, const Register *reg,
                      qint32 value)
{
    if (!reg)
        return;
    const feetech::ValueFormat format = table.format(*reg);
    value = std::clamp(value, feetech::minimumValue(format), feetech::maximumMagnitude(format));
    registers.replace(reg->address, reg->size, *feetech::encodeValue(value, format));
}

qint32 VirtualFeetechMotor::get(const QByteArray &registers, const Register *reg) const
{
    return registerValue(*m_table, registers, reg);
}

void VirtualFeetechMotor::put(QByteArray &registers, const Register *reg, qint32 value) const
{
    putRegisterValue(*m_table, registers, reg, value);
}

MotionControl VirtualFeetechMotor::control(const QByteArray &registers) const
{
    if (family() == Family::Scs)
        return get(registers, m_keys.minAngle) == 0 && get(registers, m_keys.maxAngle) == 0
            ? MotionControl::OpenLoop
            : MotionControl::Position;
    switch (get(registers, m_keys.mode)) {
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

double VirtualFeetechMotor::clampedGoal(const QByteArray &registers) const
{
    double goal = get(registers, m_keys.goalPosition);
    const qint32 minimum = get(registers, m_keys.minAngle);
    const qint32 maximum = get(registers, m_keys.maxAngle);
    if (minimum != 0 || maximum != 0)
        goal = std::clamp(goal, double(minimum), double(std::max(minimum, maximum)));
    return std::clamp(
        goal, 0.0,
        double(is4096() ? ServoMotion::kFullCircleSteps - 1 : ServoMotion::kScsMaxPosition));
}

MotionCommand VirtualFeetechMotor::motionCommand(const QByteArray &registers) const
{
    MotionCommand command;
    command.torqueEnable = get(registers, m_keys.torqueEnable);
    command.control = control(registers);
    command.goal = clampedGoal(registers);
    command.offset = is4096() ? get(registers, m_keys.offset) : 0;
    // Speed 0 and acceleration 0 mean "the model's maximum".
    const double modelMax = m_motion.maxSpeed();
    const qint32 goalSpeed = std::abs(get(registers, m_keys.goalSpeed));
    command.maxSpeed = goalSpeed == 0 ? modelMax : std::min(double(goalSpeed), modelMax);
    const qint32 acceleration = get(registers, m_keys.acceleration);
    command.acceleration =
        acceleration == 0 ? ServoMotion::kFastAcceleration : acceleration * kAccelerationUnit;
    if (command.control == MotionControl::Wheel) {
        command.openLoopSpeed = std::clamp(double(get(registers, m_keys.goalSpeed)),
                                           -command.maxSpeed, command.maxSpeed);
    } else if (command.control == MotionControl::OpenLoop) {
        double duty;
        if (family() == Family::Hls && get(registers, m_keys.mode) == 2) {
            duty = get(registers, m_keys.goalTime) / 2047.0; // constant current ≈ speed
        } else {
            const quint16 raw = quint16(
                feetech::decodeRaw(QByteArrayView(registers).sliced(m_keys.goalTime->address, 2),
                                   m_table->byteOrder()));
            duty = feetech::fromSignMagnitude(raw & 0x7FF, 10) / 1000.0;
        }
        command.openLoopSpeed = std::clamp(duty, -1.0, 1.0) * modelMax;
    }
    // Registers in percent (holding, overload torque) and 10 ms (protection time) to permille
    // and seconds.
    command.torqueLimit =
        m_keys.torqueLimit ? get(registers, m_keys.torqueLimit) : get(registers, m_keys.maxTorque);
    if (m_keys.holdingTorque)
        command.holdingTorque = get(registers, m_keys.holdingTorque) * 10.0;
    if (m_keys.overloadTorque && m_keys.protectionTime) {
        command.overloadTorque = get(registers, m_keys.overloadTorque) * 10.0;
        command.protectionSeconds = get(registers, m_keys.protectionTime) * 0.01;
    }
    if (m_keys.maxTemperature)
        command.maxTemperature = get(registers, m_keys.maxTemperature);
    return command;
}

quint8 VirtualFeetechMotor::statusBits(const QByteArray &registers) const
{
    quint8 bits = 0;
    const qint32 maxVoltage = get(registers, m_keys.maxVoltage);
    const qint32 minVoltage = get(registers, m_keys.minVoltage);
    const qint32 voltage = get(registers, m_keys.presentVoltage);
    if ((maxVoltage != 0 || minVoltage != 0) && (voltage > maxVoltage || voltage < minVoltage))
        bits |= 0x01;
    if (m_keys.maxTemperature
        && get(registers, m_keys.presentTemperature) >= get(registers, m_keys.maxTemperature))
        bits |= 0x04;
    if (m_motion.overloaded())
        bits |= 0x20;
    return bits;
}

void VirtualFeetechMotor::report(QByteArray &registers) const
{
    const int physical = int(std::lround(m_motion.position()));
    const int present = is4096()
        ? ServoMotion::wrapFullCircle(physical - get(registers, m_keys.offset))
        : std::clamp(physical, 0, ServoMotion::kScsMaxPosition);
    put(registers, m_keys.presentPosition, present);
    put(registers, m_keys.presentSpeed, int(std::lround(m_motion.velocity())));
    put(registers, m_keys.presentLoad, int(std::lround(m_motion.loadPermille())));
    put(registers, m_keys.presentCurrent, int(std::lround(m_motion.amps() / kCurrentUnitAmps)));
    put(registers, m_keys.presentVoltage, int(std::lround(m_motion.terminalVolts() * 10.0)));
    put(registers, m_keys.presentTemperature, int(std::lround(m_motion.temperature())));

    const bool turning = m_motion.turning();
    bool away = false; // more than the dead zone from the goal
    if (get(registers, m_keys.torqueEnable) == 1 && control(registers) == MotionControl::Position) {
        const double deadZone =
            std::max(get(registers, m_keys.cwDeadZone), get(registers, m_keys.ccwDeadZone));
        const double goal = clampedGoal(registers);
        away = std::abs(goal
                        - m_motion.presentCoordinate(is4096() ? get(registers, m_keys.offset) : 0))
            > deadZone;
        put(registers, m_keys.currentGoal, int(std::lround(goal)));
    }
    // HLS splits the flag: bit 0 above the speed threshold, bit 1 not yet at the target.
    if (family() == Family::Hls)
        put(registers, m_keys.moving, (turning ? 1 : 0) | (away ? 2 : 0));
    else
        put(registers, m_keys.moving, turning || away ? 1 : 0);
    put(registers, m_keys.status, statusBits(registers));
}

void VirtualFeetechMotor::advance(QByteArray &registers, qint64 fromUs, qint64 toUs)
{
    qint64 at = std::max(fromUs, toUs - kMaxCatchUpUs);
    while (at < toUs) {
        const qint64 stepUs = std::min(kMaxStepUs, toUs - at);
        if (m_motion.step(motionCommand(registers), double(stepUs) / 1e6))
            put(registers, m_keys.torqueEnable, 0); // overheated
        at += stepUs;
    }
    report(registers);
}

} // namespace sim
