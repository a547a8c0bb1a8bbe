// Two simulated SO-101 arms for the teleoperation tests: the follower on the test's simulator
// ("bus", logged to bus.log) with a bus client scanned on it, the leader on a simulator of its
// own that the test's hand turns, and a LeRobot calibration file of each written from what the
// arms hold.
#pragma once

#include "busclient.h"
#include "feetechbus.h"
#include "lerobotcalibration.h"
#include "simoptions.h"

#include <QtTest>

#include <memory>

namespace testsupport {

class TeleopArmsTest : public FeetechBusTest
{
protected:
    static constexpr int kGoalAddress = 42;
    static constexpr int kTorqueAddress = 40;

    sim::SimulatorOptions armOptions(const QString &name, const QString &robot) const
    {
        sim::SimulatorOptions options =
            feetechBusOptions(m_dir, name, QVector<sim::FeetechServoSpec> {});
        options.robot = sim::simulatedRobot(robot, nullptr);
        options.servos = sim::robotServos(*options.robot);
        return options;
    }

    // The follower on "bus" (the test's simulator, logging to bus.log) and the leader on
    // "leader", with a calibration file of each, and no client on either: servoctl opens them.
    void startArmsForServoctl()
    {
        QString error;
        QVERIFY2(startSimulator(armOptions(QStringLiteral("bus"), QStringLiteral("so101")), &error),
                 qPrintable(error));
        m_leader = std::make_unique<sim::SimulatorThread>();
        QVERIFY2(m_leader->start(
                     armOptions(QStringLiteral("leader"), QStringLiteral("so101-leader")), &error),
                 qPrintable(error));
        QVERIFY(!writeCalibration(*m_simulator, followerFile()).isEmpty());
        QVERIFY(!writeCalibration(*m_leader, leaderFile()).isEmpty());
    }

    // The same, and a client on the follower that has found its six servos.
    void startArms()
    {
        startArmsForServoctl();
        if (QTest::currentTestFailed())
            return;
        m_client = std::make_unique<feetech::BusClient>(patientTiming());
        QVERIFY(connectAndScan(*m_client, m_simulator->linkPath(), 6));
        QCOMPARE(m_client->servos()->count(), 6);
    }

    void stopArms()
    {
        m_client.reset();
        m_leader.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    // What the arm on `simulator` holds, as LeRobot writes it, in `path`.
    QString writeCalibration(sim::SimulatorThread &simulator, const QString &path) const
    {
        const QStringList names = {QStringLiteral("shoulder_pan"), QStringLiteral("shoulder_lift"),
                                   QStringLiteral("elbow_flex"),   QStringLiteral("wrist_flex"),
                                   QStringLiteral("wrist_roll"),   QStringLiteral("gripper")};
        QVector<feetech::LeRobotMotor> motors;
        simulator.call([&](sim::Simulator &running) {
            for (int id = 1; id <= names.size(); ++id) {
                sim::VirtualFeetechServo *servo = running.feetechBus()->findServo(quint8(id));
                if (!servo)
                    return;
                motors.append({names.at(id - 1), id, 0, servo->value(u"position_offset"),
                               servo->value(u"min_angle_limit"), servo->value(u"max_angle_limit")});
            }
        });
        if (motors.size() != names.size())
            return {};
        return writeTestFile(QFileInfo(path).fileName(), feetech::leRobotCalibrationToJson(motors));
    }

    QString followerFile() const { return m_dir.filePath(QStringLiteral("follower.json")); }
    QString leaderFile() const { return m_dir.filePath(QStringLiteral("leader.json")); }

    bool turnLeader(quint8 id, int position)
    {
        bool turned = false;
        m_leader->call([&](sim::Simulator &simulator) {
            turned = simulator.feetechBus()->hand().turn(id, position);
        });
        return turned;
    }

    // The SYNC WRITEs the follower heard at `address`: each as its entries' values by ID.
    QVector<QMap<int, int>> syncWrites(int address, int size) const
    {
        QVector<QMap<int, int>> writes;
        for (const feetech::Packet &packet :
             feetechRequestsReceived(logPath(), feetech::Instruction::SyncWrite)) {
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

    std::unique_ptr<sim::SimulatorThread> m_leader;
    std::unique_ptr<feetech::BusClient> m_client;
};

} // namespace testsupport
