// feetech::Teleoperation against two simulated arms over pseudo-terminals: the follower on a
// bus client, the leader on a session of its own that the simulator's hand turns. The checked
// start that holds first, tracking in LeRobot's units, Stop holding, a lost leader, refusals.
#include "teleoparms.h"
#include "teleoperation.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::Teleoperation;

class TestTeleoperation : public testsupport::TeleopArmsTest
{
    Q_OBJECT

private:
    feetech::TeleopSettings settings() const
    {
        feetech::TeleopSettings run;
        run.leaderPort = m_leader->linkPath();
        run.followerCalibration = followerFile();
        run.leaderCalibration = leaderFile();
        run.maxSpeed = 180;
        return run;
    }

private slots:
    void cleanup() { stopArms(); }

    void theFollowerHoldsFirstThenFollowsTheLeaderAndStopHolds()
    {
        startArms();
        const qint32 standing = simulatorValue(2, u"present_position");
        QVERIFY(turnLeader(2, standing + 600));
        Teleoperation teleop(m_client.get());
        QSignalSpy ended(&teleop, &Teleoperation::ended);
        QVERIFY2(teleop.start(settings()), qPrintable(teleop.message()));
        QCOMPARE(teleop.state(), Teleoperation::State::Starting);
        QVERIFY(!teleop.start(settings())); // one run at a time
        QCOMPARE(teleop.problem(), Teleoperation::Problem::None);
        QTRY_COMPARE_WITH_TIMEOUT(teleop.state(), Teleoperation::State::Running, 15000);
        QCOMPARE(teleop.mapping().joints().size(), 6);
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(simulatorValue(2, u"goal_position") - (standing + 600)) <= 20,
                                 15000);
        QVERIFY(teleop.loop()->cycles() > 0);
        // Both arms calibrated over the whole encoder: in LeRobot's units the same place.
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(teleop.loop()->leaderNormalised().at(1)
                                      - teleop.loop()->followerGoalsNormalised().at(1))
                                     < 1.0,
                                 5000);
        QTRY_VERIFY_WITH_TIMEOUT(teleop.rateHz() > 0.0, 5000);

        // The first goal is where the follower stood, before its torque went on.
        const auto goals = syncWrites(kGoalAddress, 2);
        const auto torque = syncWrites(kTorqueAddress, 1);
        QVERIFY(goals.size() > 2);
        QCOMPARE(torque.size(), 1);
        QCOMPARE(goals.first().value(2), standing);
        QCOMPARE(torque.first().value(2), 1);

        teleop.stop();
        QCOMPARE(teleop.state(), Teleoperation::State::Stopping);
        QVERIFY(ended.wait(10000));
        QVERIFY(ended.first().at(0).toBool());
        QCOMPARE(teleop.problem(), Teleoperation::Problem::None);
        QCOMPARE(teleop.state(), Teleoperation::State::Idle);
        // Held where it stood when stopped (a servo on its way needs a moment to brake), torque on.
        const qint32 held = simulatorValue(2, u"goal_position");
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(simulatorValue(2, u"present_position") - held) <= 30, 5000);
        QCOMPARE(simulatorValue(2, u"goal_position"), held);
        QCOMPARE(simulatorValue(2, u"torque_enable"), 1);
    }

    void whatCannotWorkIsRefusedBeforeAnythingMoves()
    {
        startArms();
        Teleoperation teleop(m_client.get());
        feetech::TeleopSettings run = settings();

        run.leaderPort = m_simulator->linkPath();
        QVERIFY(!teleop.start(run));
        QCOMPARE(teleop.problem(), Teleoperation::Problem::SamePort);

        run = settings();
        run.leaderCalibration = m_dir.filePath(QStringLiteral("missing.json"));
        QVERIFY(!teleop.start(run));
        QCOMPARE(teleop.problem(), Teleoperation::Problem::UnreadableFile);

        // No file chosen: which one to choose, not "No file name specified".
        run = settings();
        run.followerCalibration.clear();
        QVERIFY(!teleop.start(run));
        QCOMPARE(teleop.problem(), Teleoperation::Problem::UnreadableFile);
        QVERIFY2(teleop.message().contains(QStringLiteral("Choose the follower's")),
                 qPrintable(teleop.message()));

        run = settings();
        run.leaderCalibration = writeTestFile(
            QStringLiteral("fewer.json"),
            QByteArray(R"({"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": 0,
                           "range_min": 0, "range_max": 4095}})"));
        QVERIFY(!teleop.start(run));
        QCOMPARE(teleop.problem(), Teleoperation::Problem::DifferentJoints);
        QVERIFY2(teleop.message().contains(QStringLiteral("gripper")),
                 qPrintable(teleop.message()));
        QCOMPARE(teleop.state(), Teleoperation::State::Idle);

        // A file the leader does not hold: found once the leader is read, before any write.
        QFile file(leaderFile());
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray json = file.readAll();
        file.close();
        const QByteArray shifted =
            QByteArray(json).replace("\"homing_offset\": 0", "\"homing_offset\": 12");
        QVERIFY(shifted != json);
        run = settings();
        run.leaderCalibration = writeTestFile(QStringLiteral("moved.json"), shifted);
        QSignalSpy ended(&teleop, &Teleoperation::ended);
        QVERIFY(teleop.start(run));
        QVERIFY(ended.wait(10000));
        QVERIFY(!ended.first().at(0).toBool());
        QCOMPARE(teleop.problem(), Teleoperation::Problem::NotCalibrated);
        // Which arm, what differs in words, that nothing was written, and a menu that exists.
        for (const char *said : {"The leader's shoulder_pan", "the file says 12",
                                 "Nothing was written", "Load calibration"})
            QVERIFY2(teleop.message().contains(QLatin1String(said)), qPrintable(teleop.message()));
        QVERIFY2(!teleop.message().contains(QLatin1String("wrote")), qPrintable(teleop.message()));

        // A leader port nobody answers on.
        run = settings();
        run.leaderPort = m_dir.filePath(QStringLiteral("no-such-port"));
        ended.clear();
        QVERIFY(teleop.start(run));
        QVERIFY(ended.wait(10000));
        QCOMPARE(teleop.problem(), Teleoperation::Problem::LeaderUnreachable);

        // Nothing was written to the follower by any of them.
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncWrite)
                    .isEmpty());
        QVERIFY(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).isEmpty());
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void aLostLeaderStopsWithTheFollowerHolding()
    {
        startArms();
        Teleoperation teleop(m_client.get());
        QSignalSpy ended(&teleop, &Teleoperation::ended);
        QVERIFY2(teleop.start(settings()), qPrintable(teleop.message()));
        QTRY_COMPARE_WITH_TIMEOUT(teleop.state(), Teleoperation::State::Running, 15000);
        QTRY_VERIFY_WITH_TIMEOUT(teleop.loop()->cycles() > 5, 10000);
        m_leader.reset();
        QVERIFY(ended.wait(10000));
        QVERIFY(ended.first().at(0).toBool());
        QCOMPARE(teleop.problem(), Teleoperation::Problem::LinkLost);
        QVERIFY2(teleop.message().contains(QStringLiteral("leader was lost")),
                 qPrintable(teleop.message()));
        QVERIFY2(teleop.message().contains(QStringLiteral("holds where it is")),
                 qPrintable(teleop.message()));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
    }
};

QTEST_GUILESS_MAIN(TestTeleoperation)
#include "tst_teleoperation.moc"
