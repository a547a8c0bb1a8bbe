// Teleoperation from the GUI thread: the window's connected bus is the follower, a leader arm on
// a port of its own (its session in its own thread) drives it joint by joint through the two
// LeRobot calibration files, with the safe start and the holding stop of servoctl feetech teleop.
#pragma once

#include "teleopbus.h"
#include "teleoploop.h"
#include "teleopmapping.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>

#include <deque>
#include <memory>

namespace feetech {

class BusClient;

struct TeleopSettings
{
    QString leaderPort;
    QString followerCalibration;
    QString leaderCalibration;
    double rateHz = TeleopLoop::kDefaultRateHz;
    double maxSpeed = TeleopLoop::kDefaultMaxSpeed; // degrees per second
    TeleopMapping::NormMode normMode = TeleopMapping::kDefaultNormMode;
};

// Start refuses what cannot work before anything is sent; then both arms are checked against
// their files (reads only), the follower holds where it stands (goal = present, then torque on)
// and follows. Stop, a lost leader and destruction leave the follower holding where it is.
class Teleoperation : public QObject
{
    Q_OBJECT

public:
    enum class State { Idle, Starting, Running, Stopping };
    enum class Problem {
        None,
        NoFollower, // the window has no bus open, or not every joint of the file on it
        SamePort, // the leader's port is the follower's
        UnreadableFile,
        DifferentJoints, // the two files name different joints
        LeaderUnreachable, // the leader's port or one of its joints does not answer
        NotCalibrated, // an arm does not hold what its file says
        BusFailed, // a read or write of the start or stop failed
        LinkLost, // a bus went down while running
    };
    static constexpr qint32 kBaud = 1000000; // LeRobot's arms

    explicit Teleoperation(BusClient *follower, QObject *parent = nullptr);
    ~Teleoperation() override;

    // False, with problem() and message(), when refused (nothing sent); false and nothing
    // changed while a run has not ended.
    bool start(const TeleopSettings &settings);
    // Ends the loop; the follower holds where it is once ended() comes.
    void stop();

    State state() const { return m_state; }
    Problem problem() const { return m_problem; }
    // What went wrong, or how the last run ended, for the user.
    const QString &message() const { return m_message; }
    // The joints, from start on.
    const TeleopMapping &mapping() const { return m_mapping; }
    // The loop's goals, positions and latency while it runs (null before).
    const TeleopLoop *loop() const { return m_loop.get(); }
    // Follower writes completed per second, over the last second.
    double rateHz() const;

signals:
    void stateChanged(feetech::Teleoperation::State state);
    // A step of the start is done ("the leader's joints answer").
    void progress(const QString &text);
    // A write of goals ended: new leader positions, goals and latency to show.
    void cycled();
    // Back to Idle: `held` when the follower was left holding; message() says what happened.
    void ended(bool held);

private:
    using Memory = TeleopBus::Memory;

    void setState(State state);
    bool refuse(Problem problem, const QString &message);
    void fail(Problem problem, const QString &message);
    void onLeaderStatus(const seriallink::ConnectionStatus &status);
    void onFollowerStatus(const seriallink::ConnectionStatus &status);
    // The start, step by step.
    void identifyLeader(int joint);
    void checkCalibration(TeleopBus *bus, const ServoInfo &servo, const LeRobotMotor &motor,
                          const QString &file, std::function<void()> next);
    void checkFollower(int joint);
    void readFollower(int joint, QVector<qint32> positions,
                      std::function<void(QVector<qint32>)> done);
    void hold(const QVector<qint32> &positions, std::function<void(bool)> done);
    void startLoop(const QVector<qint32> &standing);
    void onLeaderCycle(const QVector<FeedbackSample> &samples);
    void sendGoals(const BusOperation &write);
    // Running no more: no new goals; the follower holds once the write on the wire ended.
    void windDown();
    void holdAndEnd();
    void end(bool held);

    QPointer<BusClient> m_client;
    std::unique_ptr<TeleopBus> m_follower;
    std::unique_ptr<TeleopBus> m_leader;
    std::unique_ptr<TeleopLoop> m_loop;
    TeleopSettings m_settings;
    TeleopMapping m_mapping;
    QVector<ServoInfo> m_followerServos;
    QVector<ServoInfo> m_leaderServos;
    State m_state = State::Idle;
    Problem m_problem = Problem::None;
    QString m_message;
    bool m_leaderOpen = false;
    bool m_torqueOn = false; // the follower holds: a stop must leave it holding
    QElapsedTimer m_clock;
    std::deque<qint64> m_writesEnded; // m_clock's milliseconds, the last second's
};

} // namespace feetech
