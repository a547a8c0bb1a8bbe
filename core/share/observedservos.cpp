// What a shared bus's traffic has shown of each servo: memory copies filled from reads and writes.
#include "observedservos.h"

#include "feetechpacket.h"

#include <algorithm>

namespace share {

namespace {

constexpr int kDataFrom = 5; // a status frame's data follows header, ID, length and error
constexpr int kParametersFrom = 5; // a request's parameters follow header, ID, length, code
constexpr int kModelAddress = 3;

QByteArray statusData(const QByteArray &frame)
{
    return frame.size() > kDataFrom + 1 ? frame.mid(kDataFrom, frame.size() - kDataFrom - 1)
                                        : QByteArray();
}

QByteArray parameters(const QByteArray &frame)
{
    return frame.size() > kParametersFrom + 1
        ? frame.mid(kParametersFrom, frame.size() - kParametersFrom - 1)
        : QByteArray();
}

} // namespace

QVector<quint8> ObservedServos::ids() const
{
    QVector<quint8> ids;
    for (auto it = m_servos.cbegin(); it != m_servos.cend(); ++it) {
        if (it->answered)
            ids.append(it.key());
    }
    return ids;
}

bool ObservedServos::answered(quint8 id) const
{
    const auto it = m_servos.constFind(id);
    return it != m_servos.cend() && it->answered;
}

ObservedServos::Servo &ObservedServos::servo(quint8 id, qint32 baud)
{
    Servo &servo = m_servos[id];
    if (baud > 0)
        servo.baud = baud;
    return servo;
}

void ObservedServos::learn(SharedTransaction &transaction, qint32 baud)
{
    using feetech::Instruction;
    const quint8 code = transaction.instruction();
    const QByteArray params = parameters(transaction.request);
    for (const QByteArray &reply : std::as_const(transaction.replies)) {
        if (reply.size() > 2)
            servo(quint8(reply.at(2)), baud).answered = true;
    }
    if (code == quint8(Instruction::Read) && params.size() >= 2) {
        for (const QByteArray &reply : std::as_const(transaction.replies))
            store(transaction, quint8(reply.at(2)), quint8(params.at(0)), statusData(reply), false);
    } else if (code == quint8(Instruction::SyncRead) && params.size() >= 2) {
        for (const QByteArray &reply : std::as_const(transaction.replies))
            store(transaction, quint8(reply.at(2)), quint8(params.at(0)), statusData(reply), false);
    } else if ((code == quint8(Instruction::Write) || code == quint8(Instruction::RegWrite))
               && params.size() >= 2 && transaction.id() != feetech::kBroadcastId) {
        servo(transaction.id(), baud);
        store(transaction, transaction.id(), quint8(params.at(0)), params.mid(1), true);
    } else if (code == quint8(Instruction::SyncWrite) && params.size() >= 2) {
        const int address = quint8(params.at(0));
        const int length = quint8(params.at(1));
        for (int at = 2; length > 0 && at + 1 + length <= params.size(); at += 1 + length) {
            const quint8 id = quint8(params.at(at));
            servo(id, baud);
            store(transaction, id, address, params.mid(at + 1, length), true);
        }
    }
    // A later part of the same transaction (a second answer from one ID, a SYNC WRITE naming
    // it twice) may have written model bytes no table knows: what was decoded of that servo
    // with the model before is not said.
    transaction.registers.erase(
        std::remove_if(transaction.registers.begin(), transaction.registers.end(),
                       [this](const RegisterAccess &access) { return !table(access.id); }),
        transaction.registers.end());
}

void ObservedServos::store(SharedTransaction &transaction, quint8 id, int address,
                           const QByteArray &bytes, bool written)
{
    Servo &target = servo(id, 0);
    const int count = qMin(int(bytes.size()), 256 - address);
    for (int i = 0; i < count; ++i) {
        target.memory[address + i] = bytes.at(i);
        target.seen.setBit(address + i);
    }
    const feetech::RegisterTable *known = table(id);
    if (!known)
        return;
    for (const feetech::Register &reg : known->registers()) {
        if (reg.address < address || reg.end() > address + count)
            continue;
        const qint32 raw = feetech::decodeValue(
            QByteArrayView(bytes).sliced(reg.address - address, reg.size), known->format(reg));
        transaction.registers.append({id, reg.key, raw, written});
    }
}

bool ObservedServos::known(quint8 id, int address, int size) const
{
    const auto it = m_servos.constFind(id);
    if (it == m_servos.cend() || address < 0 || address + size > 256)
        return false;
    for (int i = address; i < address + size; ++i) {
        if (!it->seen.testBit(i))
            return false;
    }
    return true;
}

const feetech::RegisterTable *ObservedServos::table(quint8 id) const
{
    if (!known(id, kModelAddress, 2))
        return nullptr;
    const QByteArray &memory = m_servos.value(id).memory;
    const feetech::ModelInfo model = feetech::ModelTable::builtIn().identify(
        quint8(memory.at(kModelAddress)), quint8(memory.at(kModelAddress + 1)));
    return model.family ? &feetech::RegisterTable::forFamily(*model.family) : nullptr;
}

std::optional<feetech::ServoInfo> ObservedServos::info(quint8 id) const
{
    if (!known(id, feetech::kIdentityAddress, feetech::kIdentitySize))
        return std::nullopt;
    const Servo &servo = m_servos.value(id);
    return feetech::servoInfoFromIdentity(
        id, servo.baud, QByteArrayView(servo.memory).sliced(0, feetech::kIdentitySize));
}

std::optional<feetech::ServoInfo> ObservedServos::knownServo(quint8 id) const
{
    if (std::optional<feetech::ServoInfo> whole = info(id))
        return whole;
    if (!table(id))
        return std::nullopt;
    const Servo &servo = m_servos.value(id);
    feetech::ServoInfo known;
    known.id = id;
    known.baud = servo.baud;
    known.modelMajor = quint8(servo.memory.at(kModelAddress));
    known.modelMinor = quint8(servo.memory.at(kModelAddress + 1));
    known.model = feetech::ModelTable::builtIn().identify(known.modelMajor, known.modelMinor);
    return known;
}

std::optional<qint32> ObservedServos::value(quint8 id, QStringView key) const
{
    const feetech::RegisterTable *known = table(id);
    const feetech::Register *reg = known ? known->find(key) : nullptr;
    if (!reg || !this->known(id, reg->address, reg->size))
        return std::nullopt;
    return feetech::decodeValue(
        QByteArrayView(m_servos.value(id).memory).sliced(reg->address, reg->size),
        known->format(*reg));
}

std::optional<double> ObservedServos::scaled(quint8 id, QStringView key) const
{
    const std::optional<qint32> raw = value(id, key);
    if (!raw)
        return std::nullopt;
    return *raw * table(id)->find(key)->scale;
}

std::optional<feetech::FeedbackSample> ObservedServos::feedback(quint8 id, qint64 steadyUs) const
{
    const feetech::RegisterTable *known = table(id);
    if (!known)
        return std::nullopt;
    const feetech::Block block = known->feedbackBlock();
    if (!this->known(id, block.address, block.size))
        return std::nullopt;
    const Servo &servo = m_servos.value(id);
    return feetech::decodeFeedback(*known, id, servo.baud, steadyUs,
                                   QByteArrayView(servo.memory).sliced(block.address, block.size),
                                   0);
}

} // namespace share
