// Recording a motion from the telemetry stream.
#include "motionrecorder.h"

#include <algorithm>
#include <cmath>

namespace feetech {

void MotionRecorder::start(const QVector<MotionJoint> &joints, qint32 baud)
{
    m_recording = {};
    m_recording.joints = joints;
    m_baud = baud;
    m_latest = QVector<std::optional<qint32>>(joints.size());
    m_fresh = QVector<bool>(joints.size(), false);
    m_frameUs.reset();
    m_startUs.reset();
}

void MotionRecorder::addSamples(const QVector<FeedbackSample> &samples)
{
    for (const FeedbackSample &sample : samples) {
        const auto position = sample.value(Quantity::Position);
        if (!position || sample.baud != m_baud)
            continue;
        const auto joint = std::find_if(
            m_recording.joints.cbegin(), m_recording.joints.cend(),
            [&sample](const MotionJoint &candidate) { return candidate.id == sample.id; });
        if (joint == m_recording.joints.cend())
            continue;
        const int index = int(joint - m_recording.joints.cbegin());
        if (m_fresh.at(index))
            closeFrame(); // a new cycle began before every joint answered in the last
        if (!m_frameUs)
            m_frameUs = sample.steadyUs;
        m_latest[index] = qint32(std::lround(*position));
        m_fresh[index] = true;
        if (std::all_of(m_fresh.cbegin(), m_fresh.cend(), [](bool fresh) { return fresh; }))
            closeFrame();
    }
}

void MotionRecorder::closeFrame()
{
    const qint64 frameUs = m_frameUs.value_or(0);
    m_frameUs.reset();
    std::fill(m_fresh.begin(), m_fresh.end(), false);
    QVector<qint32> frame;
    for (const auto &position : std::as_const(m_latest)) {
        if (!position)
            return; // a joint has not answered yet: no frame can say where it stands
        frame.append(*position);
    }
    if (!m_startUs)
        m_startUs = frameUs;
    // Rounded as the file keeps it, so a recording saved and read back is the same.
    const double seconds = std::round(double(frameUs - *m_startUs) / 1e3) / 1e3;
    if (!m_recording.times.isEmpty() && seconds < m_recording.times.last())
        return;
    m_recording.times.append(seconds);
    m_recording.frames.append(frame);
}

} // namespace feetech
