// Generic resynchronising framer shared by the PTK and Feetech codecs.
#include "streamframer.h"

#include <algorithm>
#include <cstdint>

namespace seriallink {

StreamFramer::StreamFramer(const FrameFormat &format, BadChecksumPolicy policy)
    : m_format(format)
    , m_policy(policy)
{
    const QByteArrayView prefix = format.framePrefix();
    m_prefixSize = std::min<qsizetype>(prefix.size(), qsizetype(m_prefix.size()));
    std::copy_n(prefix.data(), m_prefixSize, m_prefix.begin());
}

quint32 sumOfBytes(QByteArrayView bytes)
{
    // Eight bytes at a time: add the bytes pairwise into 16-bit lanes, then all lanes at once
    // with one multiplication (no lane can carry into the next).
    constexpr std::uint64_t kLowBytes = 0x00FF00FF00FF00FFull;
    constexpr std::uint64_t kLanes = 0x0001000100010001ull;
    const char *at = bytes.data();
    const char *const end = at + bytes.size();
    quint32 sum = 0;
    for (; end - at >= 8; at += 8) {
        std::uint64_t word;
        std::memcpy(&word, at, sizeof word);
        const std::uint64_t pairs = (word & kLowBytes) + ((word >> 8) & kLowBytes);
        sum += quint32((pairs * kLanes) >> 48);
    }
    if (end - at >= 4) {
        quint32 word;
        std::memcpy(&word, at, sizeof word);
        const quint32 pairs = (word & 0x00FF00FFu) + ((word >> 8) & 0x00FF00FFu);
        sum += (pairs & 0xFFFFu) + (pairs >> 16);
        at += 4;
    }
    for (; at < end; ++at)
        sum += quint8(*at);
    return sum;
}

void StreamFramer::dropConsumed()
{
    // Consumed bytes are dropped once per delivery, rather than once per frame: what is left is
    // at most the start of one frame, so the move is short and the capacity is reused.
    const qsizetype rest = m_end - m_start;
    if (rest > 0)
        std::memmove(m_buffer.data(), m_buffer.data() + m_start, std::size_t(rest));
    m_frameEnd -= m_start;
    m_frameStart -= m_start;
    m_end = rest;
    m_start = 0;
}

void StreamFramer::grow(qsizetype more)
{
    m_buffer.resize(std::max<std::size_t>(2 * m_buffer.size(), std::size_t(m_end + more)));
}

StreamItem StreamFramer::take(StreamItem::Kind kind, qsizetype length)
{
    const char *from = m_buffer.data() + m_start;
    if (m_lastItem.isDetached()) {
        m_lastItem.resize(length); // keeps the allocation; nobody else sees these bytes
        std::memcpy(m_lastItem.data(), from, std::size_t(length));
    } else {
        m_lastItem = QByteArray(from, length);
    }
    StreamItem item {kind, m_lastItem, m_bufferOffset};
    m_start += length;
    m_bufferOffset += length;
    return item;
}

std::optional<StreamItem> StreamFramer::nextItem()
{
    const char *const data = m_buffer.data() + m_start;
    const qsizetype size = m_end - m_start;
    const QByteArrayView pending(data, size);
    // Garbage is gathered until a byte that could start a frame, so one item covers one run.
    qsizetype garbage = 0;
    while (garbage < size) {
        if (m_prefixSize > 0 && data[garbage] != m_prefix[0]) {
            const void *lead =
                std::memchr(data + garbage, quint8(m_prefix[0]), std::size_t(size - garbage));
            garbage = lead ? static_cast<const char *>(lead) - data : size;
            continue;
        }
        const qsizetype length = garbage == 0 && m_frameStart == m_start
            ? m_frameEnd - m_start
            : m_format.frameLength(pending.sliced(garbage));
        if (length < 0) {
            ++garbage;
            continue;
        }
        if (garbage > 0)
            break; // report the garbage first; the frame comes with the next call
        if (length == 0)
            return std::nullopt; // need more to tell
        if (length > size) {
            // A frame's length never changes as more of it arrives, so it is asked once.
            m_frameEnd = m_start + length;
            m_frameStart = m_start;
            return std::nullopt;
        }
        if (m_format.checksumValid(pending.first(length))) {
            ++m_framesAccepted;
            return take(StreamItem::Kind::Frame, length);
        }
        ++m_checksumErrors;
        if (m_policy == BadChecksumPolicy::ConsumeFrame) {
            m_bytesDiscarded += length;
            return take(StreamItem::Kind::BadChecksum, length);
        }
        // Resync: report the candidate, but drop only its first byte so that a real header
        // hidden inside it is still found.
        StreamItem item = take(StreamItem::Kind::BadChecksum, length);
        m_start -= length - 1;
        m_bufferOffset -= length - 1;
        ++m_bytesDiscarded;
        return item;
    }
    if (garbage == 0)
        return std::nullopt;
    m_bytesDiscarded += garbage;
    return take(StreamItem::Kind::Garbage, garbage);
}

std::optional<StreamItem> StreamFramer::flush()
{
    const qsizetype rest = pendingBytes();
    if (rest == 0)
        return std::nullopt;
    m_bytesDiscarded += rest;
    return take(StreamItem::Kind::Incomplete, rest);
}

int StreamFramer::discardPending()
{
    const int dropped = pendingBytes();
    m_bytesDiscarded += dropped;
    m_bufferOffset += dropped;
    m_start = 0;
    m_end = 0;
    m_frameEnd = 0;
    m_frameStart = -1;
    return dropped;
}

} // namespace seriallink
