// Splits a received byte stream into frames of one protocol, resynchronising on bad input.
#pragma once

#include <QByteArray>
#include <QByteArrayView>

#include <optional>
#include <vector>

namespace seriallink {

// What a protocol tells the framer about its frames.
class FrameFormat
{
public:
    virtual ~FrameFormat() = default;

    // Length of the frame that would start at buffer[0]: 0 when more bytes are needed to tell,
    // -1 when buffer[0] cannot start a frame.
    virtual int frameLength(QByteArrayView buffer) const = 0;
    virtual bool checksumValid(QByteArrayView frame) const = 0;
};

// One piece of the stream: a frame, a frame whose checksum failed, or bytes that are no frame.
struct StreamItem
{
    enum class Kind { Frame, BadChecksum, Garbage, Incomplete };
    Kind kind = Kind::Frame;
    QByteArray bytes;
    qint64 offset = 0; // position of the first byte in the whole stream
};

// Appends received bytes and extracts every complete frame. On a bad header it drops one byte and
// tries again; on a bad checksum it either does the same (receivers: a false header inside noise
// must not swallow the real frame after it) or consumes the whole candidate (decoders showing
// what was on the wire). Everything dropped is counted.
class StreamFramer
{
public:
    enum class BadChecksumPolicy { Resync, ConsumeFrame };

    explicit StreamFramer(const FrameFormat &format,
                          BadChecksumPolicy policy = BadChecksumPolicy::Resync);

    void append(const QByteArray &bytes);

    // The next item, or nothing when the buffer holds only the start of a frame ("need more").
    std::optional<StreamItem> next();

    // Hands out whatever is left (end of input) as one Incomplete item.
    std::optional<StreamItem> flush();

    // Drops all buffered bytes (counted as discarded), e.g. before a new request goes out.
    int discardPending();

    int pendingBytes() const { return int(m_buffer.size() - m_start); }
    qint64 framesAccepted() const { return m_framesAccepted; }
    qint64 checksumErrors() const { return m_checksumErrors; }
    qint64 bytesDiscarded() const { return m_bytesDiscarded; }

private:
    StreamItem take(StreamItem::Kind kind, qsizetype length);

    const FrameFormat &m_format;
    BadChecksumPolicy m_policy;
    // A plain vector: appending a few bytes and dropping a consumed prefix stay inline, with none
    // of QByteArray's sharing checks (the framer sees every delivery the port makes).
    std::vector<char> m_buffer;
    qsizetype m_start = 0; // bytes of m_buffer already handed out, dropped on the next append
    qsizetype m_frameEnd = 0; // end of the frame being received, once its length is known
    qint64 m_bufferOffset = 0;
    qint64 m_framesAccepted = 0;
    qint64 m_checksumErrors = 0;
    qint64 m_bytesDiscarded = 0;
};

} // namespace seriallink
