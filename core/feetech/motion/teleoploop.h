// The teleoperation loop, whoever runs it (servoctl feetech teleop, Robot > Teleoperate…): each
// complete cycle of the leader's positions becomes one SYNC WRITE of the follower's goals, each
// step limited to a speed, one write on the wire and only the newest waiting behind it.
#pragma once

#include "busoperation.h"
#include "bustypes.h"
#include "motionrecording.h"
#include "telemetry.h"
#include "teleopmapping.h"

#include <QElapsedTimer>
#include <QVector>

#include <optional>

namespace feetech {

class TeleopLoop
{
public:
    static constexpr double kDefaultRateHz = 50.0;
    static constexpr double kDefaultMaxSpeed = 90.0; // degrees per second

    // The follower's and the leader's servos in the mapping's joint order; `standing` the
    // follower's present positions, its first goals (it holds there before the loop starts).
    TeleopLoop(const TeleopMapping &mapping, const QVector<ServoInfo> &follower,
               const QVector<ServoInfo> &leader, const QVector<qint32> &standing,
               double maxSpeedDegreesPerSecond);

    // A leader telemetry cycle: the follower's SYNC WRITE to submit now, or nothing (a joint
    // missing from the cycle, or a write still on the wire: these goals wait for it).
    std::optional<BusOperation> takeLeaderCycle(const QVector<FeedbackSample> &samples);
    // The SYNC WRITE on the wire has ended: the write of the goals that waited, if any.
    std::optional<BusOperation> takeWriteFinished();
    // Nothing more is sent: the goals waiting are dropped, and so are cycles that come later
    // (a write on the wire still ends).
    void stop();

    bool isWriting() const { return m_writing; }
    qint64 cycles() const { return m_writes; }
    // From the leader's sample to the end of the follower's write, in milliseconds.
    double medianLatencyMs() const;
    double lastLatencyMs() const;
    // Each joint in LeRobot's normalised units: the leader's last position, the follower's last
    // goal sent.
    const QVector<double> &leaderNormalised() const { return m_leaderNormalised; }
    QVector<double> followerGoalsNormalised() const;
    // The follower's goals as sent, timed from the first: what `feetech replay` plays back.
    const MotionRecording &recording() const { return m_recording; }

private:
    BusOperation send(const QVector<qint32> &targets, qint64 sampleUs);

    TeleopMapping m_mapping;
    QVector<ServoInfo> m_follower;
    QVector<ServoInfo> m_leader;
    QVector<qint32> m_standing;
    double m_stepsPerSecond = 0;
    QVector<double> m_sent;
    QVector<double> m_leaderNormalised;
    std::optional<QVector<qint32>> m_waiting;
    qint64 m_waitingSampleUs = 0;
    bool m_writing = false;
    bool m_stopped = false;
    qint64 m_writes = 0;
    qint64 m_writeSampleUs = 0;
    QVector<qint64> m_latencies;
    QElapsedTimer m_sinceWrite;
    QElapsedTimer m_recordingClock;
    MotionRecording m_recording;
};

} // namespace feetech
