// PTK wire frames: 10-byte requests (queries and writes) and 9-byte replies, big-endian.
#pragma once

#include "streamframer.h"

#include <QByteArray>
#include <QtGlobal>

#include <optional>

namespace ptk {

constexpr quint8 kHeader0 = 0xAF;
constexpr quint8 kHeader1 = 0xFA;
constexpr quint8 kRequestLength = 0x0A;
constexpr quint8 kReplyLength = 0x09;
constexpr int kRequestSize = 10;
constexpr int kReplySize = 9;

// Sum of every byte after the two header bytes, modulo 256.
quint8 checksum(QByteArrayView frameWithoutChecksum);

// A request carries a command and two 16-bit words (payload bytes 0-1 and 2-3).
struct Request
{
    quint8 command = 0;
    quint16 word0 = 0;
    quint16 word1 = 0;
};

// A reply carries no command byte: only two words.
struct Reply
{
    quint16 word0 = 0;
    quint16 word1 = 0;
};

// The big-endian 16-bit word at `index` of a frame (no checks: callers know the frame's size).
quint16 wordAt(QByteArrayView frame, int index);

QByteArray encodeRequest(const Request &request);
QByteArray encodeQuery(quint8 command);
QByteArray encodeReply(const Reply &reply);

// Decode a whole frame (header, length and checksum checked); nothing when it is not one.
std::optional<Request> decodeRequest(QByteArrayView frame);
std::optional<Reply> decodeReply(QByteArrayView frame);

// Frame boundaries for seriallink::StreamFramer. Both the servo's replies and the host's own echoed
// requests are frames; callers tell them apart by size.
class FrameFormat final : public seriallink::FrameFormat
{
public:
    int frameLength(QByteArrayView buffer) const override;
    bool checksumValid(QByteArrayView frame) const override;
    QByteArrayView framePrefix() const override { return QByteArrayView("\xAF\xFA\x00", 3); }
};

} // namespace ptk
