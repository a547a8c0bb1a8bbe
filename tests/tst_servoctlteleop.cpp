// servoctl feetech teleop against two simulated arms, a leader turned by the simulator's hand
// and a follower: the safe start, tracking in LeRobot's units, the stop that holds or releases,
// a bus lost, and what is refused before anything moves.
#include "motionrecording.h"
#include "robottemplate.h"
#include "servoctlrun.h"
#include "teleoparms.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using testsupport::runServoctl;

class TestServoctlTeleop : public testsupport::TeleopArmsTest
{
    Q_OBJECT

private:
    testsupport::ServoctlResult teleop(const QStringList &more = {}) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath(),
                                        QStringLiteral("--json"), QStringLiteral("feetech"),
                                        QStringLiteral("teleop"), QStringLiteral("--leader"),
                                        m_leader->linkPath(), QStringLiteral("--calibration"),
                                        followerFile(), QStringLiteral("--leader-calibration"),
                                        leaderFile()}
                           + more);
    }

private slots:
    void cleanup() { stopArms(); }

    void theFollowerHoldsFirstThenEasesToTheLeaderAndHoldsWhenStopped()
    {
        startArmsForServoctl();
        const qint32 standing = simulatorValue(2, u"present_position");
        QVERIFY(turnLeader(2, standing + 600));
        const auto result = teleop({QStringLiteral("--duration"), QStringLiteral("2.5"),
                                    QStringLiteral("--max-speed"), QStringLiteral("180")});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QJsonObject summary = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QVERIFY(summary[QStringLiteral("cycles")].toInt() > 20);
        QVERIFY(summary[QStringLiteral("held")].toBool());
        // Joints mapped as LeRobot's SO arms map them unless told, and said so.
        QCOMPARE(summary[QStringLiteral("norm_mode")].toString(), QStringLiteral("degrees"));
        QVERIFY2(result.err.contains(QStringLiteral("use_degrees")), qPrintable(result.err));

        const auto goals = syncWrites(kGoalAddress, 2);
        const auto torque = syncWrites(kTorqueAddress, 1);
        QVERIFY(goals.size() > 20);
        QCOMPARE(torque.size(), 1);
        // The first goal is where the follower stood, before torque went on.
        QCOMPARE(goals.first().value(2), standing);
        QCOMPARE(torque.first().value(2), 1);
        // Eased in: no step larger than the speed allows in one cycle at 50 Hz, with margin.
        int largestStep = 0;
        for (int i = 1; i < goals.size(); ++i)
            largestStep = qMax(largestStep, qAbs(goals.at(i).value(2) - goals.at(i - 1).value(2)));
        QVERIFY2(largestStep <= 180 * 4096 / 360 / 50 * 3,
                 qPrintable(QString::number(largestStep)));
        // Tracking: the follower's joint 2 reached the leader's pose (both arms calibrated over
        // the whole encoder, so the same position).
        const int reached = goals.at(goals.size() - 2).value(2);
        QVERIFY2(qAbs(reached - (standing + 600)) <= 20, qPrintable(QString::number(reached)));
        // The stop held it where it stands.
        QVERIFY(qAbs(goals.last().value(2) - simulatorValue(2, u"present_position")) <= 30);
        QCOMPARE(simulatorValue(2, u"torque_enable"), 1);
    }

    void releaseLeavesTheFollowerLimp()
    {
        startArmsForServoctl();
        const auto result = teleop(
            {QStringLiteral("--duration"), QStringLiteral("0.5"), QStringLiteral("--release")});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        // servoctl may be gone before the simulator has read its last frame from the
        // pseudo-terminal: the servo is limp once it has.
        QTRY_COMPARE(simulatorValue(1, u"torque_enable"), 0);
        const auto torque = syncWrites(kTorqueAddress, 1);
        QCOMPARE(torque.size(), 2);
        QCOMPARE(torque.last().value(1), 0);
    }

    void whatCannotWorkIsRefusedBeforeAnythingMoves()
    {
        startArmsForServoctl();
        // The same port twice.
        auto refused = runServoctl({QStringLiteral("--port"), m_simulator->linkPath(),
                                    QStringLiteral("feetech"), QStringLiteral("teleop"),
                                    QStringLiteral("--leader"), m_simulator->linkPath(),
                                    QStringLiteral("--calibration"), followerFile(),
                                    QStringLiteral("--leader-calibration"), leaderFile()});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("same port")), qPrintable(refused.err));
        // A file whose offsets the arm does not hold: the command that writes it is named.
        QFile file(followerFile());
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray json = file.readAll();
        file.close();
        const QByteArray shifted =
            QByteArray(json).replace("\"homing_offset\": 0", "\"homing_offset\": 12");
        QVERIFY(shifted != json);
        const QString moved = writeTestFile(QStringLiteral("moved.json"), shifted);
        refused = runServoctl({QStringLiteral("--port"), m_simulator->linkPath(),
                               QStringLiteral("feetech"), QStringLiteral("teleop"),
                               QStringLiteral("--leader"), m_leader->linkPath(),
                               QStringLiteral("--calibration"), moved,
                               QStringLiteral("--leader-calibration"), leaderFile()});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("feetech calibration load")),
                 qPrintable(refused.err));
        // A joint the leader's file lacks.
        const QString fewer = writeTestFile(
            QStringLiteral("fewer.json"),
            QByteArray(R"({"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": 0,
                           "range_min": 0, "range_max": 4095}})"));
        refused = runServoctl({QStringLiteral("--port"), m_simulator->linkPath(),
                               QStringLiteral("feetech"), QStringLiteral("teleop"),
                               QStringLiteral("--leader"), m_leader->linkPath(),
                               QStringLiteral("--calibration"), followerFile(),
                               QStringLiteral("--leader-calibration"), fewer});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("gripper")), qPrintable(refused.err));
        // Nothing was written to the follower by any of them.
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncWrite)
                    .isEmpty());
        QVERIFY(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).isEmpty());
    }

    void theLeaderLostStopsWithTheFollowerHolding()
    {
        startArmsForServoctl();
        QTimer::singleShot(800, this, [this] { m_leader.reset(); });
        const auto result = teleop({QStringLiteral("--duration"), QStringLiteral("10")});
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QStringLiteral("the leader was lost")),
                 qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("holds where it is")), qPrintable(result.err));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
    }
};

QTEST_GUILESS_MAIN(TestServoctlTeleop)
#include "tst_servoctlteleop.moc"
