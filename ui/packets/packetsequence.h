// Frames built in the packet window: how each is answered, what makes one risky, and the
// sequence files that keep them.
#pragma once

#include "fileerror.h"

#include <QByteArray>
#include <QString>
#include <QVector>

#include <optional>

struct PacketFrame
{
    enum class Protocol { Feetech, Ptk };

    Protocol protocol = Protocol::Feetech;
    QByteArray bytes; // the whole frame, checksum included
    qint32 baud = 0; // Feetech: the rate it is sent at
    std::optional<quint8> replyId; // Feetech: the one servo that answers it, if one does
    int replyDataSize = 0; // Feetech: the data bytes of that answer
    bool expectsReply = false; // PTK: a query

    bool operator==(const PacketFrame &other) const;
};

namespace packetsequence {

// A whole Feetech frame sent at `baud`, with its answer worked out from the instruction: a
// unicast PING, READ, WRITE, REG WRITE, RECOVERY, RESET or CALIBRATE is answered by its servo;
// anything broadcast, a SYNC READ (several answers) or an unknown instruction is listened to.
// Nothing when the bytes are not one whole frame.
std::optional<PacketFrame> feetechFrame(const QByteArray &bytes, qint32 baud);
// A whole PTK request; a query command expects a reply.
std::optional<PacketFrame> ptkFrame(const QByteArray &bytes);

// Why the frame must be confirmed before it is sent (it writes EEPROM: the ID, the baud rate,
// the lock, a limit...; restores factory values; calibrates); empty when it only reads or
// drives RAM.
QString riskOf(const PacketFrame &frame);

// What the frame is, in words (the decoder's explanation).
QString describe(const PacketFrame &frame);

bool save(const QString &path, const QVector<PacketFrame> &frames, util::FileError *error);
// Every frame checked as feetechFrame/ptkFrame would build it; nothing and *error naming the
// file and the entry at fault otherwise.
std::optional<QVector<PacketFrame>> load(const QString &path, util::FileError *error);

} // namespace packetsequence
