// Simulated Feetech servo (spec/feetech-protocol.md §2, §5-§10): registers and instructions.
#include "virtualfeetechservo.h"

#include "simulatordata.h"

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

constexpr int kPositionSteps4096 = ServoMotion::kFullCircleSteps;
constexpr qint32 kMiddlePosition = 2048;
constexpr int kSmsMinimumReturnDelay = 50; // values below behave as 50 (100 µs), spec §5.2

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
    , m_motor(*m_table, model.family == Family::Hls ? kDefaultHlsSupplyVolts : kDefaultSupplyVolts)
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
    m_keys.maxTorque = find(u"max_torque");
    m_keys.protectionCurrent = find(u"protection_current");
    m_keys.offset = find(u"position_offset");
    m_keys.mode = find(u"mode");
    m_keys.torqueEnable = find(u"torque_enable");
    m_keys.goalPosition = find(u"goal_position");
    m_keys.goalTime = m_table->at(44);
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
    powerCycle();
}

// ---- register access ------------------------------------------------------------------------

qint32 VirtualFeetechServo::get(const Register *reg) const
{
    return registerValue(*m_table, m_registers, reg);
}

void VirtualFeetechServo::put(const Register *reg, qint32 value)
{
    putRegisterValue(*m_table, m_registers, reg, value);
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
    if (persist)
        keepInImage(*reg);
}

void VirtualFeetechServo::keepInImage(const Register &reg)
{
    if (m_image.mid(reg.address, reg.size) != m_registers.mid(reg.address, reg.size)) {
        putRegisterBytes(reg, m_registers, m_image);
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
        m_motor.report(m_registers);
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

void VirtualFeetechServo::storeValue(QStringView key, qint32 value)
{
    const Register *reg = m_table->find(key);
    Q_ASSERT_X(reg, "VirtualFeetechServo::storeValue", "no such register in the family's table");
    put(reg, value);
    if (reg->storage == Storage::Eeprom)
        keepInImage(*reg);
    m_motor.report(m_registers);
}

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
    m_motor.motion().stop();

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
    m_motor.report(m_registers);
    // A servo wakes up holding where it is, not jumping to goal 0 when torque comes on.
    put(m_keys.goalPosition, get(m_keys.presentPosition));
    m_motor.report(m_registers);
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
    if (length <= 0 || address < 0 || address + length > kRegisterFileSize || length > m_longestRead
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
        m_motor.motion().clearOverload();
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
    m_motor.report(m_registers);
    if (!replies(packet.code, broadcast))
        return std::nullopt;
    return statusReply(replyId);
}

void VirtualFeetechServo::applySyncWrite(quint8 address, const QByteArray &data)
{
    applyWrite(address, data);
    m_motor.report(m_registers);
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
            m_motor.motion().clearOverload(); // re-arming torque clears an overload trip
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
    int offset =
        ServoMotion::wrapFullCircle(int(std::lround(m_motor.motion().position())) - target);
    if (offset > kPositionSteps4096 / 2)
        offset -= kPositionSteps4096;
    offset = std::clamp(offset, m_keys.offset->minimum, m_keys.offset->maximum);
    store(m_keys.offset, offset);
    m_motor.report(m_registers);
}

// ---- time and environment -------------------------------------------------------------------

void VirtualFeetechServo::advanceTo(qint64 nowUs)
{
    if (nowUs <= m_nowUs)
        return;
    m_motor.advance(m_registers, m_nowUs, nowUs);
    m_nowUs = nowUs;
}

void VirtualFeetechServo::setSupplyVoltage(double volts)
{
    m_motor.motion().setSupplyVoltage(volts);
    m_motor.report(m_registers);
}

void VirtualFeetechServo::setAmbientTemperature(double celsius)
{
    m_motor.motion().setAmbientTemperature(celsius);
}

void VirtualFeetechServo::setExternalLoad(int permille)
{
    m_motor.motion().setExternalLoad(permille);
}

void VirtualFeetechServo::setOverloadLatched(bool latched)
{
    m_motor.motion().setOverloadLatched(latched);
    m_motor.report(m_registers);
}

void VirtualFeetechServo::setTemperature(double celsius)
{
    m_motor.motion().setTemperature(celsius);
    m_motor.report(m_registers);
}

void VirtualFeetechServo::setPhysicalPosition(double steps)
{
    m_motor.motion().setPosition(steps);
    m_motor.report(m_registers);
}

void VirtualFeetechServo::turnByHand(double steps, double stepsPerSecond)
{
    m_motor.motion().turnByHand(steps, stepsPerSecond);
    m_motor.report(m_registers);
}

} // namespace sim
