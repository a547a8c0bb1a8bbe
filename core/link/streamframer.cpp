// Generic resynchronising framer shared by the PTK and Feetech codecs.
#include "link/streamframer.h"

namespace seriallink {

StreamFramer::StreamFramer(const FrameFormat &format, BadChecksumPolicy policy)
    : m_format(format)
    , m_policy(policy)
{ }

void StreamFramer::append(const QByteArray &bytes)
{
    m_buffer.append(bytes);
}

StreamItem StreamFramer::take(StreamItem::Kind kind, int length)
{
    StreamItem item {kind, m_buffer.left(length), m_bufferOffset};
    m_buffer.remove(0, length);
    m_bufferOffset += length;
    return item;
}

std::optional<StreamItem> StreamFramer::next()
{
    // Garbage is gathered until a byte that could start a frame, so one item covers one run.
    int garbage = 0;
    while (garbage < m_buffer.size()) {
        const int length = m_format.frameLength(QByteArrayView(m_buffer).sliced(garbage));
        if (length < 0) {
            ++garbage;
            continue;
        }
        if (garbage > 0)
            break; // report the garbage first; the frame comes with the next call
        if (length == 0 || length > m_buffer.size())
            return std::nullopt; // need more
        const QByteArray frame = m_buffer.left(length);
        if (m_format.checksumValid(frame)) {
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
        StreamItem item {StreamItem::Kind::BadChecksum, frame, m_bufferOffset};
        m_buffer.remove(0, 1);
        ++m_bufferOffset;
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
    if (m_buffer.isEmpty())
        return std::nullopt;
    m_bytesDiscarded += m_buffer.size();
    return take(StreamItem::Kind::Incomplete, int(m_buffer.size()));
}

int StreamFramer::discardPending()
{
    const int dropped = int(m_buffer.size());
    m_bytesDiscarded += dropped;
    m_bufferOffset += dropped;
    m_buffer.clear();
    return dropped;
}

} // namespace seriallink
