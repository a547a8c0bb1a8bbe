// Recording a motion on a bus client through its telemetry hub.
#include "motioncapture.h"

#include "busclient.h"
#include "servolist.h"
#include "telemetryhub.h"

namespace feetech {

MotionCapture::MotionCapture(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    connect(client->telemetry(), &TelemetryHub::samplesReceived, this, &MotionCapture::onSamples);
    connect(client->telemetry(), &TelemetryHub::streamingChanged, this, [this](bool streaming) {
        if (!streaming && m_recording) {
            m_recording = false;
            emit stopped();
        }
    });
}

bool MotionCapture::start(const QVector<int> &indexes, double rateHz, Refusal *refusal)
{
    if (!m_client || !m_client->link()->isConnected())
        return !refused(Refusal(Refusal::Code::NotConnected), refusal);
    if (indexes.isEmpty())
        return !refused(Refusal(Refusal::Code::NoServoToMonitor), refusal);
    QVector<MotionJoint> joints;
    const ServoList &servos = *m_client->servos();
    qint32 baud = 0;
    for (const int index : indexes) {
        if (index < 0 || index >= servos.count())
            return !refused(Refusal(Refusal::Code::NoServo), refusal);
        const ServoInfo &servo = servos.at(index).info;
        if (baud != 0 && servo.baud != baud)
            return !refused(Refusal(Refusal::Code::SeveralRates), refusal);
        baud = servo.baud;
        joints.append({QString(), servo.id});
    }
    if (!m_client->telemetry()->subscribe(this, indexes, rateHz, refusal))
        return false;
    m_recorder.start(joints, baud);
    m_recording = true;
    return true;
}

void MotionCapture::stop()
{
    if (!m_recording)
        return;
    m_recording = false;
    if (m_client)
        m_client->telemetry()->unsubscribe(this);
    emit stopped();
}

void MotionCapture::onSamples(const QVector<FeedbackSample> &samples)
{
    if (!m_recording)
        return;
    const int before = int(m_recorder.recording().frames.size());
    m_recorder.addSamples(samples);
    const int after = int(m_recorder.recording().frames.size());
    if (after != before)
        emit framesRecorded(after);
}

} // namespace feetech
