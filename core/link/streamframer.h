// Splits a received byte stream into frames of one protocol, resynchronising on bad input.
#pragma once

#include <QByteArray>
#include <QByteArrayView>

#include <array>
#include <cstring>
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
    // The bytes every frame starts with (at most four; none when frames have no fixed start):
    // frameLength must be 0 for these bytes or a first part of them (they never tell the
    // length alone) and -1 for a buffer that starts otherwise. The framer then skips noise
    // with memchr and waits out the prefix by itself, instead of asking at every byte.
    virtual QByteArrayView framePrefix() const { return {}; }
};

// The sum of the bytes (the PTK and Feetech checksums are this, modulo 256, from byte 2 on).
quint32 sumOfBytes(QByteArrayView bytes);

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

    // Inline: with a port that delivers a byte at a time, this and next() run for every byte.
    void append(QByteArrayView bytes)
    {
        if (Q_UNLIKELY(m_start > 0))
            dropConsumed();
        if (Q_UNLIKELY(m_end + bytes.size() > qsizetype(m_buffer.size())))
            grow(bytes.size());
        if (bytes.size() == 1) // a slow port delivers a byte at a time: no memcpy call for it
            m_buffer[std::size_t(m_end)] = bytes.front();
        else if (!bytes.isEmpty())
            std::memcpy(m_buffer.data() + m_end, bytes.data(), std::size_t(bytes.size()));
        m_end += bytes.size();
    }

    void append(const QByteArray &bytes) { append(QByteArrayView(bytes)); }

    // The next item, or nothing when the buffer holds only the start of a frame ("need more").
    std::optional<StreamItem> next()
    {
        if (m_end < m_frameEnd)
            return std::nullopt; // the frame being received is still short: nothing new to tell
        if (m_end - m_start <= m_prefixSize && startsLikeAFrame())
            return std::nullopt; // only the frame prefix so far (or nothing at all)
        return nextItem();
    }

    // Hands out whatever is left (end of input) as one Incomplete item.
    std::optional<StreamItem> flush();

    // Drops all buffered bytes (counted as discarded), e.g. before a new request goes out.
    int discardPending();

    int pendingBytes() const { return int(m_end - m_start); }
    qint64 framesAccepted() const { return m_framesAccepted; }
    qint64 checksumErrors() const { return m_checksumErrors; }
    qint64 bytesDiscarded() const { return m_bytesDiscarded; }

private:
    bool startsLikeAFrame() const
    {
        for (qsizetype i = m_start; i < m_end; ++i) {
            if (m_buffer[std::size_t(i)] != m_prefix[std::size_t(i - m_start)])
                return false;
        }
        return true;
    }
    std::optional<StreamItem> nextItem();
    StreamItem take(StreamItem::Kind kind, qsizetype length);
    void dropConsumed();
    void grow(qsizetype more);

    const FrameFormat &m_format;
    BadChecksumPolicy m_policy;
    std::array<char, 4> m_prefix {};
    qsizetype m_prefixSize = 0;
    // A plain vector used as storage only (bytes [m_start, m_end) are pending): appending a few
    // bytes is a bounds check and a copy, with none of QByteArray's sharing checks.
    std::vector<char> m_buffer;
    qsizetype m_start = 0; // bytes of m_buffer already handed out, dropped on the next append
    qsizetype m_end = 0; // bytes of m_buffer received
    qsizetype m_frameEnd = 0; // end of the frame being received, once its length is known
    qsizetype m_frameStart = -1; // where that frame starts (its length is not asked again)
    // The bytes of the last item handed out. When its receiver has let go of it (the common
    // case: a frame decoded and dropped), the next item reuses its allocation instead of
    // allocating anew; a receiver that keeps it shares it, and the next item gets a fresh one.
    QByteArray m_lastItem;
    qint64 m_bufferOffset = 0;
    qint64 m_framesAccepted = 0;
    qint64 m_checksumErrors = 0;
    qint64 m_bytesDiscarded = 0;
};

} // namespace seriallink
