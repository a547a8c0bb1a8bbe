// PTK frame encoding and decoding (spec/ptk-protocol.md, "Frames").
#include "ptkframe.h"

namespace ptk {

quint8 checksum(QByteArrayView frameWithoutChecksum)
{
    if (frameWithoutChecksum.size() <= 2)
        return 0;
    return quint8(seriallink::sumOfBytes(frameWithoutChecksum.sliced(2)) & 0xFF);
}

static void appendWord(QByteArray &out, quint16 word)
{
    out.append(char(word >> 8));
    out.append(char(word & 0xFF));
}

quint16 wordAt(QByteArrayView frame, int index)
{
    return quint16((quint8(frame[index]) << 8) | quint8(frame[index + 1]));
}

// Header, length byte, the command (requests only), two words, checksum.
static QByteArray encodeFrame(quint8 length, std::optional<quint8> command, quint16 word0,
                              quint16 word1)
{
    QByteArray out;
    out.reserve(kRequestSize);
    out.append(char(kHeader0));
    out.append(char(kHeader1));
    out.append(char(0));
    out.append(char(length));
    if (command)
        out.append(char(*command));
    appendWord(out, word0);
    appendWord(out, word1);
    out.append(char(checksum(out)));
    return out;
}

QByteArray encodeRequest(const Request &request)
{
    return encodeFrame(kRequestLength, request.command, request.word0, request.word1);
}

QByteArray encodeQuery(quint8 command)
{
    return encodeRequest({command, 0, 0});
}

QByteArray encodeReply(const Reply &reply)
{
    return encodeFrame(kReplyLength, std::nullopt, reply.word0, reply.word1);
}

static bool wellFormed(QByteArrayView frame, quint8 length, int size)
{
    return frame.size() == size && quint8(frame[0]) == kHeader0 && quint8(frame[1]) == kHeader1
        && frame[2] == 0 && quint8(frame[3]) == length
        && checksum(frame.first(size - 1)) == quint8(frame[size - 1]);
}

std::optional<Request> decodeRequest(QByteArrayView frame)
{
    if (!wellFormed(frame, kRequestLength, kRequestSize))
        return std::nullopt;
    return Request {quint8(frame[4]), wordAt(frame, 5), wordAt(frame, 7)};
}

std::optional<Reply> decodeReply(QByteArrayView frame)
{
    if (!wellFormed(frame, kReplyLength, kReplySize))
        return std::nullopt;
    return Reply {wordAt(frame, 4), wordAt(frame, 6)};
}

int FrameFormat::frameLength(QByteArrayView buffer) const
{
    if (buffer.isEmpty())
        return 0;
    if (quint8(buffer[0]) != kHeader0)
        return -1;
    if (buffer.size() < 2)
        return 0;
    if (quint8(buffer[1]) != kHeader1)
        return -1;
    if (buffer.size() < 3)
        return 0;
    if (buffer[2] != 0)
        return -1;
    if (buffer.size() < 4)
        return 0;
    switch (quint8(buffer[3])) {
    case kRequestLength:
        return kRequestSize;
    case kReplyLength:
        return kReplySize;
    default:
        return -1;
    }
}

bool FrameFormat::checksumValid(QByteArrayView frame) const
{
    return checksum(frame.first(frame.size() - 1)) == quint8(frame.back());
}

} // namespace ptk
