// Playing a motion recording on the servos a bus client found.
#include "motionplayer.h"

#include "busclient.h"
#include "busoperations.h"
#include "feetechsession.h"
#include "operationreply.h"
#include "servolist.h"

namespace feetech {

MotionPlayer::MotionPlayer(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{ }

OperationReply *MotionPlayer::play(const MotionRecording &recording, const ReplayPlan &settings,
                                   Refusal *refusal)
{
    if (!m_client || !m_client->link()->isConnected()) {
        refused(Refusal(Refusal::Code::NotConnected), refusal);
        return nullptr;
    }
    if (m_client->isBusy() || isPlaying()) {
        refused(Refusal(Refusal::Code::Busy), refusal);
        return nullptr;
    }
    if (recording.isEmpty()) {
        refused(Refusal(Refusal::Code::NothingToMove), refusal);
        return nullptr;
    }
    ReplayPlan plan = settings;
    plan.servos.clear();
    plan.times = recording.times;
    plan.frames = recording.frames;
    const ServoList &servos = *m_client->servos();
    for (const MotionJoint &joint : recording.joints) {
        // The servo list keeps the fastest rate first: a joint's ID there is its servo.
        int found = -1;
        for (int i = 0; i < servos.count() && found < 0; ++i) {
            if (servos.at(i).info.id == joint.id)
                found = i;
        }
        if (found < 0) {
            refused(Refusal::jointNotFound(joint.id), refusal);
            return nullptr;
        }
        const ServoInfo &servo = servos.at(found).info;
        if (!servo.hasTable()) {
            refused(Refusal::unknownModel(joint.id), refusal);
            return nullptr;
        }
        if (servo.sharedId) {
            refused(Refusal::sharedId(joint.id), refusal);
            return nullptr;
        }
        plan.servos.append(servo);
    }
    const ServoInfo &first = plan.servos.first();
    m_reply = m_client->submit(operations::replayMotion(plan), first.id, first.baud,
                               BusClient::Work::Foreground);
    if (m_reply)
        connect(m_reply, &OperationReply::finished, this, [this] { m_reply.clear(); });
    return m_reply;
}

void MotionPlayer::stop()
{
    if (!m_client || !isPlaying())
        return;
    m_client->runInSession([](Session &session) { session.cancel(Operation::Replay); });
}

} // namespace feetech
