// Feetech FT-SCS packets: instruction packets, status packets and the stream format.
#pragma once

#include "streamframer.h"

#include <QByteArray>
#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

constexpr quint8 kBroadcastId = 0xFE;
constexpr quint8 kMaxServoId = 253; // 0..253 are unicast IDs
constexpr int kMaxPacketSize = 250; // the SDKs' TXPACKET_MAX_LEN / RXPACKET_MAX_LEN
constexpr int kMinimumPacketSize = 6;

enum class Instruction : quint8 {
    Ping = 0x01,
    Read = 0x02,
    Write = 0x03,
    RegWrite = 0x04,
    Action = 0x05,
    Recovery = 0x06, // "parameter recovery": factory values except the ID (seed: "RESET")
    Reboot = 0x08,
    Backup = 0x09,
    Reset = 0x0A, // clears status and the multi-turn count
    Calibrate = 0x0B, // offset calibration: current position becomes the middle (or a value)
    SyncRead = 0x82,
    SyncWrite = 0x83,
};

// "PING", "READ", ... ; nothing for an unknown code.
std::optional<QString> instructionName(quint8 code);

// Checksum over ID, LEN, instruction/error and parameters: ~sum & 0xFF.
quint8 checksum(QByteArrayView packetWithoutChecksum);

// A decoded packet: `code` is the instruction of an instruction packet or the error byte of a
// status packet; the bytes alone cannot tell which.
struct Packet
{
    quint8 id = 0;
    quint8 code = 0;
    QByteArray parameters;
};

QByteArray encodePacket(quint8 id, quint8 code, const QByteArray &parameters = {});
std::optional<Packet> decodePacket(QByteArrayView frame); // header, length and checksum checked

// Instruction packets. Callers check IDs; these only build bytes.
QByteArray ping(quint8 id);
QByteArray read(quint8 id, quint8 address, quint8 length);
QByteArray write(quint8 id, quint8 address, const QByteArray &data);
QByteArray regWrite(quint8 id, quint8 address, const QByteArray &data);
QByteArray action(quint8 id = kBroadcastId);
QByteArray recovery(quint8 id);
QByteArray reboot(quint8 id);
QByteArray reset(quint8 id);
QByteArray calibrate(quint8 id, const QByteArray &position = {}); // position in family order

struct SyncWriteEntry
{
    quint8 id = 0;
    QByteArray data; // exactly the common length
};
// SYNC WRITE always goes to the broadcast ID; every entry must carry `length` bytes.
std::optional<QByteArray> syncWrite(quint8 address, quint8 length,
                                    const QVector<SyncWriteEntry> &entries);
QByteArray syncRead(quint8 address, quint8 length, const QVector<quint8> &ids);

QByteArray status(quint8 id, quint8 error, const QByteArray &data = {});

// Names of the status (error) byte's bits, lowest first (spec §7.1, STS/SMS naming).
QStringList statusBitNames(quint8 error);
// The same bits as stable keys for JSON ("voltage", "overload", "bit_6").
QStringList statusBitKeys(quint8 error);

class FrameFormat final : public seriallink::FrameFormat
{
public:
    int frameLength(QByteArrayView buffer) const override;
    bool checksumValid(QByteArrayView frame) const override;
    QByteArrayView framePrefix() const override { return QByteArrayView("\xFF\xFF", 2); }
};

} // namespace feetech
