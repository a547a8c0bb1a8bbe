// Simulated Feetech servo (spec/feetech-protocol.md §2, §5-§10): registers, instructions, physics.
#include "sim/virtualfeetechservo.h"

#include "sim/simulatordata.h"

#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sim {

using feetech::Family;
using feetech::Instruction;
using feetech::Register;
using feetech::Storage;

namespace {

constexpr int kPositionSteps4096 = 4096;
constexpr int kScsMaxPosition = 1023;
constexpr qint32 kMiddlePosition = 2048;
constexpr int kSmsMinimumReturnDelay = 50; // values below behave as 50 (100 µs), spec §5.2
constexpr double kStoppedSpeed = 0.5; // step/s: below this the horn counts as standing still

double wrap4096(double position)
{
    double wrapped = std::fmod(position, double(kPositionSteps4096));
    if (wrapped < 0)
        wrapped += kPositionSteps4096;
    return wrapped;
}

int wrap4096(int position)
{
    return ((position % kPositionSteps4096) + kPositionSteps4096) % kPositionSteps4096;
}

int sign(double value)
{
    return value > 0 ? 1 : (value < 0 ? -1 : 0);
}

} // namespace

std::optional<int> VirtualFeetechServo::baudCode(qint32 baud)
{
    return feetech::baudCode(baud);
}

qint32 VirtualFeetechServo::baudForCode(int code)
{
    return feetech::baudForCode(code);
}

qint32 VirtualFeetechServo::defaultBaud(Family family)
{
    return feetech::defaultBaud(family);
}

VirtualFeetechServo::VirtualFeetechServo(const feetech::ModelInfo &model, quint8 id, qint32 baud)
    : m_table(&feetech::RegisterTable::forFamily(model.family.value_or(Family::Sts)))
    , m_model(model)
{
    Q_ASSERT(model.family);
    for (const Register &reg : m_table->registers()) {
        for (int address = reg.address; address < reg.end() && address < kRegisterFileSize;
             ++address)
            m_byAddress[address] = &reg;
    }
    const auto find = [this](QStringView key) {
        return m_table->find(key);
    };
    m_keys.id = find(u"id");
    m_keys.baud = find(u"baud_rate");
    m_keys.returnDelay = find(u"return_delay");
    m_keys.secondaryId = find(u"secondary_id");
    m_keys.responseLevel = find(u"response_level");
    m_keys.minAngle = find(u"min_angle_limit");
    m_keys.maxAngle = find(u"max_angle_limit");
    m_keys.maxTemperature = find(u"max_temperature");
    m_keys.maxVoltage = find(u"max_voltage");
    m_keys.minVoltage = find(u"min_voltage");
    m_keys.maxTorque = find(u"max_torque");
    m_keys.cwDeadZone = find(u"cw_dead_zone");
    m_keys.ccwDeadZone = find(u"ccw_dead_zone");
    m_keys.protectionCurrent = find(u"protection_current");
    m_keys.offset = find(u"position_offset");
    m_keys.mode = find(u"mode");
    m_keys.holdingTorque = find(u"holding_torque");
    m_keys.protectionTime = find(u"protection_time");
    m_keys.overloadTorque = find(u"overload_torque");
    m_keys.torqueEnable = find(u"torque_enable");
    m_keys.acceleration = family() == Family::Scs ? nullptr : find(u"acceleration");
    m_keys.goalPosition = find(u"goal_position");
    m_keys.goalTime = m_table->at(44);
    m_keys.goalSpeed = find(u"goal_speed");
    m_keys.torqueLimit = find(u"torque_limit");
    m_keys.lock = find(u"lock");
    m_keys.presentPosition = find(u"present_position");
    m_keys.presentSpeed = find(u"present_speed");
    m_keys.presentLoad = find(u"present_load");
    m_keys.presentVoltage = find(u"present_voltage");
    m_keys.presentTemperature = find(u"present_temperature");
    m_keys.asyncFlag = find(u"async_write_flag");
    m_keys.status = find(u"status");
    m_keys.moving = find(u"moving");
    m_keys.currentGoal = find(u"current_goal_position");
    m_keys.presentCurrent = find(u"present_current");

    // Factory state: table defaults, then identity.
    const SimulatorData &data = SimulatorData::builtIn();
    for (const Register &reg : m_table->registers())
        put(&reg, reg.defaultValue.value_or(data.fallbackDefault(family(), reg.key).value_or(0)));
    put(find(u"firmware_major"), data.firmware(family()).major);
    put(find(u"firmware_minor"), data.firmware(family()).minor);
    put(find(u"byte_order"), m_table->byteOrder() == feetech::ByteOrder::Big ? 1 : 0);
    put(find(u"model_major"), model.major);
    put(find(u"model_minor"), model.minor);
    put(m_keys.id, qMin<int>(id, feetech::kMaxServoId));
    put(m_keys.baud, baudCode(baud).value_or(*baudCode(defaultBaud(family()))));
    if (m_keys.secondaryId)
        put(m_keys.secondaryId, 0);

    for (const Register &reg : m_table->registers()) {
        QByteArray &target = reg.storage == Storage::Eeprom ? m_image : m_powerOnRam;
        putRegisterBytes(reg, m_registers, target);
    }
    m_factory = m_image;

    m_supplyVolts = family() == Family::Hls ? kDefaultHlsSupplyVolts : kDefaultSupplyVolts;
    m_position = is4096() ? kMiddlePosition : (kScsMaxPosition + 1) / 2;
    powerCycle();
}

// ---- register access ------------------------------------------------------------------------

qint32 VirtualFeetechServo::get(const Register *reg) const
{
    if (!reg)
        return 0;
    return feetech::decodeValue(QByteArrayView(m_registers).sliced(reg->address, reg->size),
                                m_table->format(*reg));
}

void VirtualFeetechServo::put(const Register *reg, qint32 value)
{
    if (!reg)
        return;
    const feetech::ValueFormat format = m_table->format(*reg);
    value = std::clamp(value, feetech::minimumValue(format), feetech::maximumMagnitude(format));
    const QByteArray bytes = *feetech::encodeValue(value, format);
    m_registers.replace(reg->address, reg->size, bytes);
}

void VirtualFeetechServo::putRegisterBytes(const Register &reg, const QByteArray &from,
                                           QByteArray &to)
{
    to.replace(reg.address, reg.size, from.mid(reg.address, reg.size));
}

bool VirtualFeetechServo::unlocked() const
{
    return get(m_keys.lock) == 0;
}

void VirtualFeetechServo::store(const Register *reg, qint32 value)
{
    if (!reg)
        return;
    const bool persist = reg->storage == Storage::Eeprom && unlocked();
    put(reg, value);
    if (persist
        && m_image.mid(reg->address, reg->size) != m_registers.mid(reg->address, reg->size)) {
        putRegisterBytes(*reg, m_registers, m_image);
        ++m_eepromRevision;
    }
}

qint32 VirtualFeetechServo::value(QStringView key) const
{
    const Register *reg = m_table->find(key);
    Q_ASSERT_X(reg, "VirtualFeetechServo::value", "no such register in the family's table");
    return get(reg);
}

void VirtualFeetechServo::setValue(QStringView key, qint32 value)
{
    const Register *reg = m_table->find(key);
    Q_ASSERT_X(reg, "VirtualFeetechServo::setValue", "no such register in the family's table");
    put(reg, value);
    // Derived registers keep what the test put there until time passes; the rest (offset,
    // supply limits, ...) show their effect at once.
    const bool derived = reg == m_keys.presentPosition || reg == m_keys.presentSpeed
        || reg == m_keys.presentLoad || reg == m_keys.presentVoltage
        || reg == m_keys.presentTemperature || reg == m_keys.status || reg == m_keys.moving
        || reg == m_keys.currentGoal || reg == m_keys.presentCurrent;
    if (!derived)
        refreshRegisters();
}

quint8 VirtualFeetechServo::id() const
{
    return quint8(get(m_keys.id));
}

qint32 VirtualFeetechServo::baudRate() const
{
    return baudForCode(get(m_keys.baud));
}

std::optional<quint8> VirtualFeetechServo::secondaryId() const
{
    if (!m_keys.secondaryId)
        return std::nullopt;
    const qint32 secondary = get(m_keys.secondaryId);
    if (secondary == 0 || secondary == id() || secondary > feetech::kMaxServoId)
        return std::nullopt;
    return quint8(secondary);
}

qint64 VirtualFeetechServo::returnDelayUs() const
{
    if (!m_keys.returnDelay)
        return 0;
    qint32 delay = get(m_keys.returnDelay);
    if (family() == Family::Sms)
        delay = qMax(delay, kSmsMinimumReturnDelay);
    return qint64(delay) * 2;
}

// ---- EEPROM image and power -----------------------------------------------------------------

bool VirtualFeetechServo::setEepromImage(const QByteArray &image)
{
    if (image.size() != kRegisterFileSize)
        return false;
    const QByteArray before = m_image;
    for (const Register &reg : m_table->registers()) {
        if (reg.storage == Storage::Eeprom && reg.writable())
            putRegisterBytes(reg, image, m_image);
    }
    if (m_image != before)
        ++m_eepromRevision;
    return true;
}

void VirtualFeetechServo::powerCycle()
{
    for (const Register &reg : m_table->registers())
        putRegisterBytes(reg, reg.storage == Storage::Eeprom ? m_image : m_powerOnRam, m_registers);
    m_pending.reset();
    m_velocity = 0.0;
    m_appliedAcceleration = 0.0;
    m_loadPermille = 0.0;
    m_amps = kIdleAmps;
    m_overloaded = false;
    m_overloadSeconds = 0.0;

    put(m_keys.lock, 1);
    put(m_keys.torqueEnable, 0);
    put(m_keys.asyncFlag, 0);
    if (m_keys.torqueLimit)
        put(m_keys.torqueLimit, get(m_keys.maxTorque));
    if (family() == Family::Hls) {
        put(m_keys.goalTime, get(m_keys.protectionCurrent)); // goal current from 28
        put(m_table->find(u"live_p_gain"), get(m_table->find(u"p_gain")));
        put(m_table->find(u"live_d_gain"), get(m_table->find(u"d_gain")));
        put(m_table->find(u"live_i_gain"), get(m_table->find(u"i_gain")));
    }
    refreshRegisters();
    // A servo wakes up holding where it is, not jumping to goal 0 when torque comes on.
    put(m_keys.goalPosition, get(m_keys.presentPosition));
    refreshRegisters();
}

// ---- instructions ---------------------------------------------------------------------------

bool VirtualFeetechServo::replies(quint8 instruction, bool broadcast) const
{
    if (instruction == quint8(Instruction::Ping))
        return true;
    if (broadcast)
        return false;
    switch (Instruction(instruction)) {
    case Instruction::Action:
    case Instruction::Reboot:
    case Instruction::SyncRead:
    case Instruction::SyncWrite:
        return false;
    case Instruction::Read:
        return true;
    default:
        break;
    }
    return get(m_keys.responseLevel) != 0;
}

QByteArray VirtualFeetechServo::statusReply(quint8 replyId, const QByteArray &data) const
{
    return feetech::status(replyId, quint8(get(m_keys.status)), data);
}

std::optional<QByteArray> VirtualFeetechServo::readReply(int address, int length) const
{
    if (length <= 0 || address < 0 || address + length > kRegisterFileSize
        || length + feetech::kMinimumPacketSize > feetech::kMaxPacketSize)
        return std::nullopt;
    return statusReply(id(), m_registers.mid(address, length));
}

std::optional<QByteArray> VirtualFeetechServo::execute(const feetech::Packet &packet,
                                                       bool broadcast)
{
    const quint8 replyId = id(); // an ID change answers with the ID the host addressed
    const QByteArray &parameters = packet.parameters;
    switch (Instruction(packet.code)) {
    case Instruction::Ping:
        break;
    case Instruction::Read:
        if (broadcast || parameters.size() != 2)
            return std::nullopt;
        return readReply(quint8(parameters[0]), quint8(parameters[1]));
    case Instruction::Write:
        if (parameters.size() < 2)
            return std::nullopt;
        applyWrite(quint8(parameters[0]), QByteArrayView(parameters).sliced(1));
        break;
    case Instruction::RegWrite:
        if (parameters.size() < 2)
            return std::nullopt;
        m_pending = PendingWrite {quint8(parameters[0]), parameters.sliced(1)};
        put(m_keys.asyncFlag, 1);
        break;
    case Instruction::Action:
        if (m_pending) {
            const PendingWrite pending = *m_pending;
            m_pending.reset();
            put(m_keys.asyncFlag, 0);
            applyWrite(pending.address, pending.data);
        }
        break;
    case Instruction::Recovery:
        recover();
        break;
    case Instruction::Reboot:
        powerCycle();
        return std::nullopt;
    case Instruction::Backup: {
        QByteArray backup(kRegisterFileSize, '\0');
        for (const Register &reg : m_table->registers()) {
            if (reg.storage == Storage::Eeprom)
                putRegisterBytes(reg, m_registers, backup);
        }
        m_backup = backup;
        break;
    }
    case Instruction::Reset:
        // Clears the alarm latches; multi-turn counts are not simulated. Conditions that still
        // hold (voltage, temperature) show again at once.
        m_overloaded = false;
        m_overloadSeconds = 0.0;
        put(m_keys.status, 0);
        break;
    case Instruction::Calibrate:
        if (!calibrate(parameters))
            return std::nullopt;
        break;
    case Instruction::SyncRead:
    case Instruction::SyncWrite:
    default:
        return std::nullopt;
    }
    refreshRegisters();
    if (!replies(packet.code, broadcast))
        return std::nullopt;
    return statusReply(replyId);
}

void VirtualFeetechServo::applySyncWrite(quint8 address, const QByteArray &data)
{
    applyWrite(address, data);
    refreshRegisters();
}

bool VirtualFeetechServo::acceptable(const Register &reg, qint32 value) const
{
    if (&reg == m_keys.torqueEnable) {
        if (value == 128)
            return family() == Family::Sts || family() == Family::Sms;
        return value >= 0 && value <= 2;
    }
    // Registers whose nonsense values would make the servo unreachable or undefined.
    const bool guarded = &reg == m_keys.id || &reg == m_keys.baud || &reg == m_keys.lock
        || &reg == m_keys.responseLevel || &reg == m_keys.mode || &reg == m_keys.secondaryId;
    return !guarded || (value >= reg.minimum && value <= reg.maximum);
}

void VirtualFeetechServo::applyWrite(int address, QByteArrayView data)
{
    const bool persist = unlocked(); // the lock as it is when the write arrives
    QByteArray next = m_registers;
    QVector<const Register *> touched;
    for (qsizetype i = 0; i < data.size(); ++i) {
        const int at = address + int(i);
        if (at >= kRegisterFileSize)
            break;
        const Register *reg = m_byAddress[at];
        if (!reg || !reg->writable())
            continue; // undefined or read-only: ignored
        next[at] = data[i];
        if (touched.isEmpty() || touched.last() != reg)
            touched.append(reg);
    }
    for (const Register *reg : std::as_const(touched)) {
        const qint32 value = feetech::decodeValue(
            QByteArrayView(next).sliced(reg->address, reg->size), m_table->format(*reg));
        if (!acceptable(*reg, value))
            continue;
        if (reg == m_keys.torqueEnable) {
            m_overloaded = false; // re-arming torque clears an overload trip
            m_overloadSeconds = 0.0;
            if (value == 128) { // STS / SMS: current position becomes the middle, torque off
                calibratePresentTo(kMiddlePosition);
                put(m_keys.torqueEnable, 0);
                continue;
            }
        }
        putRegisterBytes(*reg, next, m_registers);
        if (reg->storage == Storage::Eeprom && persist
            && m_image.mid(reg->address, reg->size) != next.mid(reg->address, reg->size)) {
            putRegisterBytes(*reg, next, m_image);
            ++m_eepromRevision;
        }
        if (reg == m_keys.id && m_keys.secondaryId)
            store(m_keys.secondaryId, value); // HLS: writing the main ID updates the secondary
    }
}

void VirtualFeetechServo::recover()
{
    const QByteArray &source = m_backup ? *m_backup : m_factory;
    const bool persist = unlocked();
    const QByteArray before = m_image;
    for (const Register &reg : m_table->registers()) {
        if (reg.storage != Storage::Eeprom || !reg.writable() || &reg == m_keys.id)
            continue;
        putRegisterBytes(reg, source, m_registers);
        if (persist)
            putRegisterBytes(reg, source, m_image);
    }
    if (m_image != before)
        ++m_eepromRevision;
}

bool VirtualFeetechServo::calibrate(const QByteArray &parameters)
{
    const int firmware =
        get(m_table->find(u"firmware_major")) * 1000 + get(m_table->find(u"firmware_minor"));
    bool withoutValue = false;
    bool withValue = false;
    if (family() == Family::Sts) {
        withoutValue = withValue = firmware >= 3010;
    } else if (family() == Family::Hls) {
        withoutValue = true;
        withValue = firmware >= 3043;
    }
    qint32 target = kMiddlePosition;
    if (parameters.isEmpty()) {
        if (!withoutValue)
            return false;
    } else if (parameters.size() == 2) {
        if (!withValue)
            return false;
        target = feetech::decodeRaw(parameters, m_table->byteOrder());
        if (target >= kPositionSteps4096)
            return false;
    } else {
        return false;
    }
    calibratePresentTo(target);
    return true;
}

void VirtualFeetechServo::calibratePresentTo(qint32 target)
{
    if (!m_keys.offset)
        return;
    // LeRobot convention: present = physical − offset, so offset = physical − target, taken
    // as the shortest way round the 4096-step circle.
    int offset = wrap4096(int(std::lround(m_position)) - target);
    if (offset > kPositionSteps4096 / 2)
        offset -= kPositionSteps4096;
    offset = std::clamp(offset, m_keys.offset->minimum, m_keys.offset->maximum);
    store(m_keys.offset, offset);
    refreshRegisters();
}

// ---- physics --------------------------------------------------------------------------------

VirtualFeetechServo::Control VirtualFeetechServo::control() const
{
    if (family() == Family::Scs)
        return get(m_keys.minAngle) == 0 && get(m_keys.maxAngle) == 0 ? Control::Pwm
                                                                      : Control::Position;
    switch (get(m_keys.mode)) {
    case 1:
        return Control::Wheel;
    case 2:
        return Control::Pwm;
    case 3:
        // HLS: PWM open loop; STS step mode is not simulated and behaves as position mode.
        return family() == Family::Hls ? Control::Pwm : Control::Position;
    default:
        return Control::Position;
    }
}

double VirtualFeetechServo::maxSpeed() const
{
    const double modelMax = is4096() ? kMaxSpeed4096 : kMaxSpeedScs;
    const qint32 goal = std::abs(get(m_keys.goalSpeed));
    return goal == 0 ? modelMax : std::min(double(goal), modelMax);
}

double VirtualFeetechServo::accelerationLimit() const
{
    const qint32 acceleration = get(m_keys.acceleration);
    return acceleration == 0 ? kFastAcceleration : acceleration * kAccelerationUnit;
}

double VirtualFeetechServo::torqueCapPermille() const
{
    double cap = m_keys.torqueLimit ? get(m_keys.torqueLimit) : get(m_keys.maxTorque);
    if (m_overloaded && m_keys.holdingTorque)
        cap = std::min(cap, get(m_keys.holdingTorque) * 10.0);
    return cap;
}

double VirtualFeetechServo::presentCoordinate() const
{
    if (!is4096())
        return m_position;
    return wrap4096(m_position - get(m_keys.offset));
}

double VirtualFeetechServo::clampedGoal() const
{
    double goal = get(m_keys.goalPosition);
    const qint32 minimum = get(m_keys.minAngle);
    const qint32 maximum = get(m_keys.maxAngle);
    if (minimum != 0 || maximum != 0)
        goal = std::clamp(goal, double(minimum), double(std::max(minimum, maximum)));
    return std::clamp(goal, 0.0, double(is4096() ? kPositionSteps4096 - 1 : kScsMaxPosition));
}

void VirtualFeetechServo::step(double dt)
{
    const qint32 torque = get(m_keys.torqueEnable);
    const double previous = m_velocity;
    double limit = kFastAcceleration;

    if (torque == 1) {
        const double cap = torqueCapPermille();
        const bool blocked = cap <= 0 || std::abs(m_externalLoad) >= cap;
        const double vmax = maxSpeed();
        const Control mode = control();
        limit = mode == Control::Pwm ? kFastAcceleration : accelerationLimit();
        const double maxChange = limit * dt;
        if (mode == Control::Position) {
            const double here = presentCoordinate();
            const double target = clampedGoal();
            const double distance = target - here;
            const double desired =
                sign(distance) * std::min(vmax, std::sqrt(2.0 * limit * std::abs(distance)));
            m_velocity = blocked
                ? 0.0
                : m_velocity + std::clamp(desired - m_velocity, -maxChange, maxChange);
            double next = here + m_velocity * dt;
            // Reaching or passing the target ends the move there.
            if (!blocked && (distance == 0.0 || (next - target) * sign(distance) >= 0.0)
                && std::abs(distance) <= std::abs(m_velocity * dt) + 1e-9) {
                next = target;
                m_velocity = 0.0;
            }
            m_position = is4096() ? wrap4096(next + get(m_keys.offset)) : next;
        } else {
            double desired = 0.0;
            if (mode == Control::Wheel) {
                desired = std::clamp(double(get(m_keys.goalSpeed)), -vmax, vmax);
            } else {
                double duty;
                if (family() == Family::Hls && get(m_keys.mode) == 2) {
                    duty = get(m_keys.goalTime) / 2047.0; // constant current ≈ speed
                } else {
                    const quint16 raw = quint16(feetech::decodeRaw(
                        QByteArrayView(m_registers).sliced(m_keys.goalTime->address, 2),
                        m_table->byteOrder()));
                    duty = feetech::fromSignMagnitude(raw & 0x7FF, 10) / 1000.0;
                }
                desired = std::clamp(duty, -1.0, 1.0) * (is4096() ? kMaxSpeed4096 : kMaxSpeedScs);
            }
            m_velocity = blocked
                ? 0.0
                : m_velocity + std::clamp(desired - m_velocity, -maxChange, maxChange);
            m_position += m_velocity * dt;
        }
    } else if (torque == 2) {
        m_velocity *= std::exp(-dt / kDampingTimeConstantS);
        if (std::abs(m_velocity) < 1.0)
            m_velocity = 0.0;
        m_position += m_velocity * dt;
    } else {
        m_velocity = 0.0; // free: the horn stays where it is (nobody turns it)
    }

    if (is4096()) {
        m_position = wrap4096(m_position);
    } else if (m_position < 0.0 || m_position > kScsMaxPosition) {
        m_position = std::clamp(m_position, 0.0, double(kScsMaxPosition));
        m_velocity = 0.0; // end stop
    }
    m_appliedAcceleration = std::clamp((m_velocity - previous) / dt, -limit, limit);

    // Load: what the motor has to push, capped at what it may push.
    if (torque == 0) {
        m_loadPermille = 0.0;
    } else {
        double load = kLoadPerAcceleration * m_appliedAcceleration + m_externalLoad;
        if (std::abs(m_velocity) > kStoppedSpeed)
            load += sign(m_velocity) * (kFrictionLoad + kViscousLoad * std::abs(m_velocity));
        const double cap = torque == 1 ? std::min(1000.0, torqueCapPermille()) : 1000.0;
        m_loadPermille = std::clamp(load, -cap, cap);
    }
    m_amps = kIdleAmps + std::abs(m_loadPermille) / 1000.0 * kStallAmps;

    const double steady = m_ambient + kThermalRiseCelsiusPerAmp * m_amps;
    m_temperature += (steady - m_temperature) * (1.0 - std::exp(-dt / kThermalTimeConstantS));

    // Overload: |load| at or above the overload torque for the protection time trips it.
    if (torque != 0 && m_keys.overloadTorque && m_keys.protectionTime) {
        if (std::abs(m_loadPermille) >= get(m_keys.overloadTorque) * 10.0) {
            m_overloadSeconds += dt;
            if (m_overloadSeconds >= get(m_keys.protectionTime) * 0.01 - 1e-9)
                m_overloaded = true;
        } else {
            m_overloadSeconds = 0.0;
        }
    } else {
        m_overloadSeconds = 0.0;
    }

    // Overheating switches the torque off.
    if (torque != 0 && m_keys.maxTemperature
        && std::lround(m_temperature) >= get(m_keys.maxTemperature)) {
        put(m_keys.torqueEnable, 0);
        m_velocity = 0.0;
    }
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
    if (m_overloaded)
        bits |= 0x20;
    return bits;
}

void VirtualFeetechServo::refreshRegisters()
{
    const int physical = int(std::lround(m_position));
    const int present = is4096() ? wrap4096(physical - get(m_keys.offset))
                                 : std::clamp(physical, 0, kScsMaxPosition);
    put(m_keys.presentPosition, present);
    put(m_keys.presentSpeed, int(std::lround(m_velocity)));
    put(m_keys.presentLoad, int(std::lround(m_loadPermille)));
    put(m_keys.presentCurrent, int(std::lround(m_amps / kCurrentUnitAmps)));
    put(m_keys.presentVoltage,
        int(std::lround((m_supplyVolts - m_amps * kSupplyResistanceOhms) * 10.0)));
    put(m_keys.presentTemperature, int(std::lround(m_temperature)));

    const bool turning = std::abs(m_velocity) > kStoppedSpeed;
    bool away = false; // more than the dead zone from the goal
    if (get(m_keys.torqueEnable) == 1 && control() == Control::Position) {
        const double deadZone = std::max(get(m_keys.cwDeadZone), get(m_keys.ccwDeadZone));
        const double goal = clampedGoal();
        away = std::abs(goal - presentCoordinate()) > deadZone;
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
        step(double(stepUs) / 1e6);
        at += stepUs;
    }
    m_nowUs = nowUs;
    refreshRegisters();
}

// ---- environment ----------------------------------------------------------------------------

void VirtualFeetechServo::setSupplyVoltage(double volts)
{
    m_supplyVolts = volts;
    refreshRegisters();
}

void VirtualFeetechServo::setAmbientTemperature(double celsius)
{
    m_ambient = celsius;
}

void VirtualFeetechServo::setExternalLoad(int permille)
{
    m_externalLoad = std::clamp(permille, -1000, 1000);
}

void VirtualFeetechServo::setTemperature(double celsius)
{
    m_temperature = celsius;
    refreshRegisters();
}

void VirtualFeetechServo::setPhysicalPosition(double steps)
{
    m_position = is4096() ? wrap4096(steps) : std::clamp(steps, 0.0, double(kScsMaxPosition));
    refreshRegisters();
}

} // namespace sim
