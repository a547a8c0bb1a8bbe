// Generic resynchronising framer shared by the PTK and Feetech codecs.
#include "link/streamframer.h"

namespace seriallink {

StreamFramer::StreamFramer(const FrameFormat &format, BadChecksumPolicy policy)
    : m_format(format)
    , m_policy(policy)
{ }

void StreamFramer::append(const QByteArray &bytes)
{
    // Consumed bytes are dropped here, once per delivery, rather than once per frame: what is
    // left is at most the start of one frame, so the move is short and the capacity is reused.
    if (m_start > 0) {
        m_buffer.erase(m_buffer.begin(), m_buffer.begin() + m_start);
        m_frameEnd -= m_start;
        m_start = 0;
    }
    m_buffer.insert(m_buffer.end(), bytes.cbegin(), bytes.cend());
}

StreamItem StreamFramer::take(StreamItem::Kind kind, qsizetype length)
{
    StreamItem item {kind, QByteArray(m_buffer.data() + m_start, length), m_bufferOffset};
    m_start += length;
    m_bufferOffset += length;
    return item;
}

std::optional<StreamItem> StreamFramer::next()
{
    if (qsizetype(m_buffer.size()) < m_frameEnd)
        return std::nullopt; // the frame being received is still short: nothing new to tell
    const QByteArrayView pending(m_buffer.data() + m_start, qsizetype(m_buffer.size()) - m_start);
    // Garbage is gathered until a byte that could start a frame, so one item covers one run.
    qsizetype garbage = 0;
    while (garbage < pending.size()) {
        const int length = m_format.frameLength(pending.sliced(garbage));
        if (length < 0) {
            ++garbage;
            continue;
        }
        if (garbage > 0)
            break; // report the garbage first; the frame comes with the next call
        if (length == 0)
            return std::nullopt; // need more to tell
        if (length > pending.size()) {
            // A frame's length never changes as more of it arrives, so it is asked once.
            m_frameEnd = m_start + length;
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
    m_buffer.clear();
    m_start = 0;
    m_frameEnd = 0;
    return dropped;
}

} // namespace seriallink
