// feetech::TeleopLoop on its own: a leader cycle becomes one write of the follower's goals, only
// complete cycles count, one write on the wire with the newest goals waiting, goals eased toward
// the leader's pose without passing it, Stop dropping what waits.
#include "teleoploop.h"

#include "modeltable.h"
#include "registertable.h"

#include <QtTest>

namespace {

feetech::ServoInfo sts3215(quint8 id)
{
    feetech::ServoInfo servo;
    servo.id = id;
    servo.baud = 1000000;
    servo.model = *feetech::ModelTable::builtIn().findByName(u"STS3215");
    servo.modelMajor = quint8(servo.model.major);
    servo.modelMinor = quint8(servo.model.minor);
    return servo;
}

feetech::FeedbackSample position(quint8 id, double steps)
{
    feetech::FeedbackSample sample;
    sample.id = id;
    sample.baud = 1000000;
    sample.steadyUs = feetech::steadyMicroseconds();
    sample.values[int(feetech::Quantity::Position)] = steps;
    return sample;
}

} // namespace

class TestTeleopLoop : public QObject
{
    Q_OBJECT

private:
    // Follower joints at IDs 1-2 over 1000…3000, leader joints at IDs 11-12 over the whole
    // encoder; the follower stands at 2000 and 1500.
    static feetech::TeleopLoop makeLoop(double maxSpeed)
    {
        const QVector<feetech::LeRobotMotor> follower = {
            {QStringLiteral("shoulder_pan"), 1, 0, 0, 1000, 3000},
            {QStringLiteral("gripper"), 2, 0, 0, 1000, 3000}};
        const QVector<feetech::LeRobotMotor> leader = {
            {QStringLiteral("shoulder_pan"), 11, 0, 0, 0, 4095},
            {QStringLiteral("gripper"), 12, 0, 0, 0, 4095}};
        const auto mapping = feetech::TeleopMapping::match(follower, leader, nullptr);
        return feetech::TeleopLoop(*mapping, {sts3215(1), sts3215(2)}, {sts3215(11), sts3215(12)},
                                   {2000, 1500}, maxSpeed);
    }

private slots:
    void onlyACompleteCycleIsWritten()
    {
        feetech::TeleopLoop loop = makeLoop(720);
        QVERIFY(!loop.takeLeaderCycle({position(11, 4095)}));
        QVERIFY(!loop.takeLeaderCycle({}));
        QVERIFY(!loop.isWriting());
        const auto write = loop.takeLeaderCycle({position(11, 4095), position(12, 0)});
        QVERIFY(write);
        QCOMPARE(write->kind, feetech::Operation::SyncWrite);
        QVERIFY(loop.isWriting());
        // The leader's pose in LeRobot's units: the top of the pan's range, the gripper shut.
        QCOMPARE(loop.leaderNormalised(), (QVector<double> {100.0, 0.0}));
        QCOMPARE(loop.recording().frames.size(), 1);
        QCOMPARE(loop.recording().joints.size(), 2);
        QCOMPARE(loop.recording().joints.at(0).id, quint8(1));
    }

    void oneWriteOnTheWireAndOnlyTheNewestWaits()
    {
        feetech::TeleopLoop loop = makeLoop(720);
        QVERIFY(loop.takeLeaderCycle({position(11, 2048), position(12, 2048)}));
        QVERIFY(!loop.takeLeaderCycle({position(11, 3000), position(12, 2048)}));
        QVERIFY(!loop.takeLeaderCycle({position(11, 4095), position(12, 2048)}));
        QCOMPARE(loop.recording().frames.size(), 1);
        const auto next = loop.takeWriteFinished();
        QVERIFY(next);
        QCOMPARE(loop.cycles(), 1);
        QCOMPARE(loop.recording().frames.size(), 2);
        // The newest cycle was sent: its pan is at the top, so the goal went up, not down.
        QVERIFY(loop.recording().frames.at(1).at(0) > loop.recording().frames.at(0).at(0));
        QVERIFY(!loop.takeWriteFinished());
        QCOMPARE(loop.cycles(), 2);
        QVERIFY(!loop.isWriting());
        QVERIFY(loop.medianLatencyMs() >= 0.0);
    }

    void goalsEaseTowardTheLeaderWithoutPassingIt()
    {
        feetech::TeleopLoop loop = makeLoop(1);
        // The leader's pan at the top of its range: the follower's 3000, far from its 2000.
        for (int cycle = 0; cycle < 5; ++cycle) {
            QVERIFY(loop.takeLeaderCycle({position(11, 4095), position(12, 2048)}));
            QVERIFY(!loop.takeWriteFinished());
        }
        qint32 previous = 2000;
        for (const QVector<qint32> &frame : loop.recording().frames) {
            QVERIFY(frame.at(0) >= previous);
            QVERIFY(frame.at(0) < 3000); // 1°/s: nowhere near in a few cycles
            previous = frame.at(0);
        }
        // A fast limit reaches it and stays there.
        feetech::TeleopLoop fast = makeLoop(1e9);
        QVERIFY(fast.takeLeaderCycle({position(11, 4095), position(12, 2048)}));
        QCOMPARE(fast.recording().frames.last().at(0), 3000);
        QCOMPARE(fast.followerGoalsNormalised().at(0), 100.0);
    }

    void stopDropsTheGoalsWaiting()
    {
        feetech::TeleopLoop loop = makeLoop(720);
        QVERIFY(loop.takeLeaderCycle({position(11, 2048), position(12, 2048)}));
        QVERIFY(!loop.takeLeaderCycle({position(11, 4095), position(12, 2048)}));
        loop.stop();
        QVERIFY(!loop.takeWriteFinished());
        QVERIFY(!loop.isWriting());
        QCOMPARE(loop.recording().frames.size(), 1);
    }

    void aCycleThatComesAfterTheStopIsNotWritten()
    {
        // The leader's stream hands over its last batch as it stops: those goals must not go
        // out after whatever the stop itself writes (torque off with --release).
        feetech::TeleopLoop loop = makeLoop(720);
        QVERIFY(loop.takeLeaderCycle({position(11, 2048), position(12, 2048)}));
        loop.stop();
        QVERIFY(!loop.takeLeaderCycle({position(11, 4095), position(12, 2048)}));
        QVERIFY(!loop.takeWriteFinished());
        QVERIFY(!loop.isWriting());
        QVERIFY(!loop.takeLeaderCycle({position(11, 4095), position(12, 2048)}));
        QCOMPARE(loop.recording().frames.size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestTeleopLoop)
#include "tst_teleoploop.moc"
