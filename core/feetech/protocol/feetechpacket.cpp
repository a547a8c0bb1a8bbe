// Feetech packet encoding and decoding (spec/feetech-protocol.md §2 and the seed document).
#include "feetechpacket.h"

#include <QCoreApplication>

#include <functional>

namespace feetech {

std::optional<QString> instructionName(quint8 code)
{
    switch (Instruction(code)) {
    case Instruction::Ping:
        return QStringLiteral("PING");
    case Instruction::Read:
        return QStringLiteral("READ");
    case Instruction::Write:
        return QStringLiteral("WRITE");
    case Instruction::RegWrite:
        return QStringLiteral("REG WRITE");
    case Instruction::Action:
        return QStringLiteral("ACTION");
    case Instruction::Recovery:
        return QStringLiteral("RECOVERY");
    case Instruction::Reboot:
        return QStringLiteral("REBOOT");
    case Instruction::Backup:
        return QStringLiteral("BACKUP");
    case Instruction::Reset:
        return QStringLiteral("RESET");
    case Instruction::Calibrate:
        return QStringLiteral("CALIBRATE");
    case Instruction::SyncRead:
        return QStringLiteral("SYNC READ");
    case Instruction::SyncWrite:
        return QStringLiteral("SYNC WRITE");
    }
    return std::nullopt;
}

quint8 checksum(QByteArrayView packetWithoutChecksum)
{
    const quint32 sum = packetWithoutChecksum.size() > 2
        ? seriallink::sumOfBytes(packetWithoutChecksum.sliced(2))
        : 0;
    return quint8(~sum & 0xFF);
}

QByteArray encodePacket(quint8 id, quint8 code, const QByteArray &parameters)
{
    QByteArray out;
    out.reserve(parameters.size() + kMinimumPacketSize);
    out.append(char(0xFF));
    out.append(char(0xFF));
    out.append(char(id));
    out.append(char(parameters.size() + 2));
    out.append(char(code));
    out.append(parameters);
    out.append(char(checksum(out)));
    return out;
}

std::optional<Packet> decodePacket(QByteArrayView frame)
{
    const FrameFormat format;
    const int length = format.frameLength(frame);
    if (length <= 0 || length != frame.size() || !format.checksumValid(frame))
        return std::nullopt;
    return Packet {quint8(frame[2]), quint8(frame[4]),
                   frame.sliced(5, frame.size() - kMinimumPacketSize).toByteArray()};
}

static QByteArray bytes(std::initializer_list<quint8> values)
{
    QByteArray out;
    for (const quint8 value : values)
        out.append(char(value));
    return out;
}

QByteArray ping(quint8 id)
{
    return encodePacket(id, quint8(Instruction::Ping));
}

QByteArray read(quint8 id, quint8 address, quint8 length)
{
    return encodePacket(id, quint8(Instruction::Read), bytes({address, length}));
}

QByteArray write(quint8 id, quint8 address, const QByteArray &data)
{
    return encodePacket(id, quint8(Instruction::Write), char(address) + data);
}

QByteArray regWrite(quint8 id, quint8 address, const QByteArray &data)
{
    return encodePacket(id, quint8(Instruction::RegWrite), char(address) + data);
}

QByteArray action(quint8 id)
{
    return encodePacket(id, quint8(Instruction::Action));
}

QByteArray recovery(quint8 id)
{
    return encodePacket(id, quint8(Instruction::Recovery));
}

QByteArray reboot(quint8 id)
{
    return encodePacket(id, quint8(Instruction::Reboot));
}

QByteArray reset(quint8 id)
{
    return encodePacket(id, quint8(Instruction::Reset));
}

QByteArray calibrate(quint8 id, const QByteArray &position)
{
    return encodePacket(id, quint8(Instruction::Calibrate), position);
}

std::optional<QByteArray> syncWrite(quint8 address, quint8 length,
                                    const QVector<SyncWriteEntry> &entries)
{
    QByteArray parameters = bytes({address, length});
    for (const SyncWriteEntry &entry : entries) {
        if (entry.data.size() != length)
            return std::nullopt;
        parameters.append(char(entry.id));
        parameters.append(entry.data);
    }
    if (parameters.size() + kMinimumPacketSize > kMaxPacketSize)
        return std::nullopt;
    return encodePacket(kBroadcastId, quint8(Instruction::SyncWrite), parameters);
}

QByteArray syncRead(quint8 address, quint8 length, const QVector<quint8> &ids)
{
    QByteArray parameters = bytes({address, length});
    for (const quint8 id : ids)
        parameters.append(char(id));
    return encodePacket(kBroadcastId, quint8(Instruction::SyncRead), parameters);
}

QByteArray status(quint8 id, quint8 error, const QByteArray &data)
{
    return encodePacket(id, error, data);
}

namespace {

// The status error bits, bit 0 first: the names the user reads, the keys JSON carries.
const char *const kStatusBitNames[8] = {
    QT_TRANSLATE_NOOP("feetech", "voltage"),     QT_TRANSLATE_NOOP("feetech", "encoder"),
    QT_TRANSLATE_NOOP("feetech", "temperature"), QT_TRANSLATE_NOOP("feetech", "current"),
    QT_TRANSLATE_NOOP("feetech", "angle"),       QT_TRANSLATE_NOOP("feetech", "overload"),
    QT_TRANSLATE_NOOP("feetech", "bit 6"),       QT_TRANSLATE_NOOP("feetech", "bit 7"),
};
const char *const kStatusBitKeys[8] = {"voltage", "encoder",  "temperature", "current",
                                       "angle",   "overload", "bit_6",       "bit_7"};

QStringList statusBits(quint8 error, const std::function<QString(int bit)> &name)
{
    QStringList names;
    for (int bit = 0; bit < 8; ++bit) {
        if (error & (1u << bit))
            names.append(name(bit));
    }
    return names;
}

} // namespace

QStringList statusBitNames(quint8 error)
{
    return statusBits(error, [](int bit) {
        return QCoreApplication::translate("feetech", kStatusBitNames[bit]);
    });
}

QStringList statusBitKeys(quint8 error)
{
    return statusBits(error, [](int bit) { return QString::fromLatin1(kStatusBitKeys[bit]); });
}

int FrameFormat::frameLength(QByteArrayView buffer) const
{
    if (buffer.isEmpty())
        return 0;
    if (quint8(buffer[0]) != 0xFF)
        return -1;
    if (buffer.size() < 2)
        return 0;
    if (quint8(buffer[1]) != 0xFF)
        return -1;
    if (buffer.size() < 3)
        return 0;
    // FF FF FF ...: the first FF is noise (or a third header byte); resync one byte on.
    if (quint8(buffer[2]) == 0xFF)
        return -1;
    if (buffer.size() < 4)
        return 0;
    const int length = quint8(buffer[3]);
    if (length < 2 || length + 4 > kMaxPacketSize)
        return -1;
    return length + 4;
}

bool FrameFormat::checksumValid(QByteArrayView frame) const
{
    return checksum(frame.first(frame.size() - 1)) == quint8(frame.back());
}

} // namespace feetech
