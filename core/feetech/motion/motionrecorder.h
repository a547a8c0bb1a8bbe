// Recording a motion from the telemetry stream: one frame per cycle that saw every joint,
// positions in steps, times from the first frame.
#pragma once

#include "motionrecording.h"
#include "telemetry.h"

#include <QVector>

#include <optional>

namespace feetech {

// Fed with the samples of the stream (Session::telemetry, TelemetryHub::samplesReceived);
// samples of servos that are not joints are left out. Torque is none of its business: the
// joints are moved by hand, or by whatever drives them.
class MotionRecorder
{
public:
    // Starts a new recording of `joints` (each servo at `baud`), dropping the last one.
    void start(const QVector<MotionJoint> &joints, qint32 baud);
    void addSamples(const QVector<FeedbackSample> &samples);

    const MotionRecording &recording() const { return m_recording; }

private:
    // The frame being gathered is complete, or a joint answered twice before the others did:
    // it goes into the recording once every joint has a position.
    void closeFrame();

    MotionRecording m_recording;
    qint32 m_baud = 0;
    QVector<std::optional<qint32>> m_latest; // each joint's newest position
    QVector<bool> m_fresh; // which joints answered since the last frame
    std::optional<qint64> m_frameUs; // the first answer of the frame being gathered
    std::optional<qint64> m_startUs; // the first frame's
};

} // namespace feetech
