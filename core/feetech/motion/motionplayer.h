// Playing a motion recording on the servos a bus client found: one replay operation, its
// reply, and Stop, which leaves the arm held where it stands.
#pragma once

#include "motionrecording.h"
#include "motionreplay.h"
#include "refusal.h"

#include <QObject>
#include <QPointer>

namespace feetech {

class BusClient;
class OperationReply;

class MotionPlayer : public QObject
{
    Q_OBJECT

public:
    explicit MotionPlayer(BusClient *client, QObject *parent = nullptr);

    // Submits the replay of `recording` on the servos found at its joints' IDs, with the speed,
    // ease, loops and release of `settings` (its servos and frames are the recording's): the
    // reply (progress details are ReplayPositions), or nullptr and *refusal, nothing sent.
    OperationReply *play(const MotionRecording &recording, const ReplayPlan &settings,
                         Refusal *refusal = nullptr);
    // Asks the running replay to stop: its reply finishes (Stopped) once the arm is held.
    void stop();
    bool isPlaying() const { return !m_reply.isNull(); }

private:
    QPointer<BusClient> m_client;
    QPointer<OperationReply> m_reply;
};

} // namespace feetech
