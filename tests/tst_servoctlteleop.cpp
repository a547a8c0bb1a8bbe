// servoctl feetech teleop against two simulated arms, a leader turned by the simulator's hand
// and a follower: the safe start, tracking in LeRobot's units, the stop that holds or releases,
// a bus lost, and what is refused before anything moves.
#include "feetechbus.h"
#include "motionrecording.h"
#include "robottemplate.h"
#include "servoctlrun.h"
#include "simoptions.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using testsupport::runServoctl;

namespace {

constexpr int kGoalAddress = 42;
constexpr int kTorqueAddress = 40;

// The SYNC WRITEs the follower heard at `address`: each as its entries' values by ID.
QVector<QMap<int, int>> syncWrites(const QString &logPath, int address, int size)
{
    QVector<QMap<int, int>> writes;
    for (const feetech::Packet &packet :
         testsupport::feetechRequestsReceived(logPath, feetech::Instruction::SyncWrite)) {
        if (packet.parameters.size() < 2 || quint8(packet.parameters.at(0)) != address)
            continue;
        QMap<int, int> values;
        for (int at = 2; at + size < packet.parameters.size() + 1; at += 1 + size) {
            int value = quint8(packet.parameters.at(at + 1));
            if (size == 2)
                value |= quint8(packet.parameters.at(at + 2)) << 8;
            values.insert(quint8(packet.parameters.at(at)), value);
        }
        writes.append(values);
    }
    return writes;
}

} // namespace

class TestServoctlTeleop : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    sim::SimulatorOptions armOptions(const QString &name, const QString &robot) const
    {
        sim::SimulatorOptions options =
            testsupport::feetechBusOptions(m_dir, name, QVector<sim::FeetechServoSpec> {});
        options.robot = sim::simulatedRobot(robot, nullptr);
        options.servos = sim::robotServos(*options.robot);
        return options;
    }

    // The follower on "bus" (the test's simulator, logging to bus.log) and the leader on
    // "leader", with a calibration file saved from each (which reads only: every write the
    // follower's log holds is the teleoperation's).
    void startArms()
    {
        QString error;
        QVERIFY2(startSimulator(armOptions(QStringLiteral("bus"), QStringLiteral("so101")), &error),
                 qPrintable(error));
        m_leader = std::make_unique<sim::SimulatorThread>();
        QVERIFY2(m_leader->start(
                     armOptions(QStringLiteral("leader"), QStringLiteral("so101-leader")), &error),
                 qPrintable(error));
        const QString names =
            QStringLiteral("shoulder_pan,shoulder_lift,elbow_flex,wrist_flex,wrist_roll,gripper");
        for (const auto &[port, file] : {std::pair {m_simulator->linkPath(), followerFile()},
                                         std::pair {m_leader->linkPath(), leaderFile()}}) {
            const auto saved = runServoctl(
                {QStringLiteral("--port"), port, QStringLiteral("feetech"),
                 QStringLiteral("calibration"), QStringLiteral("save"), QStringLiteral("--ids"),
                 QStringLiteral("1-6"), QStringLiteral("--names"), names, file});
            QVERIFY2(saved.exitCode == 0, qPrintable(saved.err));
        }
    }

    QString followerFile() const { return m_dir.filePath(QStringLiteral("follower.json")); }
    QString leaderFile() const { return m_dir.filePath(QStringLiteral("leader.json")); }

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

    bool turnLeader(quint8 id, int position)
    {
        bool turned = false;
        m_leader->call([&](sim::Simulator &simulator) {
            turned = simulator.feetechBus()->hand().turn(id, position);
        });
        return turned;
    }

    std::unique_ptr<sim::SimulatorThread> m_leader;

private slots:
    void cleanup()
    {
        m_leader.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void theFollowerHoldsFirstThenEasesToTheLeaderAndHoldsWhenStopped()
    {
        startArms();
        const qint32 standing = simulatorValue(2, u"present_position");
        QVERIFY(turnLeader(2, standing + 600));
        const auto result = teleop({QStringLiteral("--duration"), QStringLiteral("2.5"),
                                    QStringLiteral("--max-speed"), QStringLiteral("180")});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QJsonObject summary = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QVERIFY(summary[QStringLiteral("cycles")].toInt() > 20);
        QVERIFY(summary[QStringLiteral("held")].toBool());

        const auto goals = syncWrites(logPath(), kGoalAddress, 2);
        const auto torque = syncWrites(logPath(), kTorqueAddress, 1);
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
        startArms();
        const auto result = teleop(
            {QStringLiteral("--duration"), QStringLiteral("0.5"), QStringLiteral("--release")});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const auto torque = syncWrites(logPath(), kTorqueAddress, 1);
        QCOMPARE(torque.size(), 2);
        QCOMPARE(torque.last().value(1), 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void whatCannotWorkIsRefusedBeforeAnythingMoves()
    {
        startArms();
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
        startArms();
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
