// Recording a motion on a bus client: the servos chosen streamed through the telemetry hub,
// their positions gathered into frames, torque left as it is.
#pragma once

#include "motionrecorder.h"
#include "refusal.h"

#include <QObject>
#include <QPointer>
#include <QVector>

namespace feetech {

class BusClient;

class MotionCapture : public QObject
{
    Q_OBJECT

public:
    static constexpr double kDefaultRateHz = 50.0;

    explicit MotionCapture(BusClient *client, QObject *parent = nullptr);

    // Starts a new recording of the servos at `indexes` (BusClient's numbering, all at one
    // rate), dropping the last one; false and *refusal when they cannot be streamed.
    bool start(const QVector<int> &indexes, double rateHz = kDefaultRateHz,
               Refusal *refusal = nullptr);
    // Ends the recording (its stream too, unless another subscriber wants it).
    void stop();
    bool isRecording() const { return m_recording; }
    const MotionRecording &recording() const { return m_recorder.recording(); }

signals:
    void framesRecorded(int frames);
    // The recording ended: stopped, or its stream ended (the link went down).
    void stopped();

private:
    void onSamples(const QVector<feetech::FeedbackSample> &samples);

    QPointer<BusClient> m_client;
    MotionRecorder m_recorder;
    bool m_recording = false;
};

} // namespace feetech
