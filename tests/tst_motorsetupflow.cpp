// Tests of the motor set-up flow against the simulated bus: joints set up one servo at a time,
// failures and stops, choosing a joint, and a check of the bus marking joints done.
#include "pluggedbus.h"

#include "busclient.h"
#include "motorsetupflow.h"

#include <QSettings>
#include <QSignalSpy>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;

const QString kArm = QStringLiteral("SO-101 follower arm");

using JointState = feetech::MotorSetupFlow::JointState;
using Work = feetech::MotorSetupFlow::Work;

} // namespace

class TestMotorSetupFlow : public testsupport::PluggedBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<feetech::MotorSetupFlow> m_flow;
    feetech::RobotTemplate m_robot = testsupport::builtInRobot(kArm);

    // Starts `start` (a find, set-up or check) and waits for the flow to be idle again.
    template<typename Start>
    void startAndWait(Start start)
    {
        feetech::Refusal refusal;
        QVERIFY2(start(&refusal), qPrintable(refusal.describe()));
        QVERIFY(m_flow->isWorking());
        QTRY_VERIFY_WITH_TIMEOUT(!m_flow->isWorking(), 30000);
    }
    void findAndWait()
    {
        startAndWait([this](feetech::Refusal *refusal) { return m_flow->find(refusal); });
    }
    void setUpAndWait()
    {
        startAndWait([this](feetech::Refusal *refusal) { return m_flow->setUp(refusal); });
    }
    void checkAndWait()
    {
        startAndWait([this](feetech::Refusal *refusal) { return m_flow->checkBus(refusal); });
    }

private slots:
    void init()
    {
        QSettings().clear();
        QString error;
        QVERIFY2(startEmptyBus(&error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>();
        m_client->connectTo(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->link()->isConnected(), 10000);
        m_flow = std::make_unique<feetech::MotorSetupFlow>(m_client.get());
        m_flow->setRobot(m_robot);
    }

    void cleanup()
    {
        m_flow.reset();
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aRobotStartsWithEveryJointToDoAndTheFirstCurrent()
    {
        QCOMPARE(m_flow->jointCount(), int(m_robot.joints.size()));
        QCOMPARE(m_flow->currentJoint(), 0);
        for (int joint = 0; joint < m_flow->jointCount(); ++joint)
            QCOMPARE(m_flow->jointState(joint), JointState::ToDo);
        QVERIFY(!m_flow->isWorking());
        QVERIFY(m_flow->isBusFree());
        feetech::Refusal refusal;
        QVERIFY(!m_flow->setUp(&refusal)); // nothing found yet
        QVERIFY(!refusal);
    }

    void aFactoryServoIsFoundThenSetUpAndTheNextJointBecomesCurrent()
    {
        QSignalSpy finished(m_flow.get(), &feetech::MotorSetupFlow::finished);
        QVERIFY(plug(1, QStringLiteral("STS3215"), 500000));
        findAndWait();
        QCOMPARE(finished.size(), 1);
        QCOMPARE(finished.at(0).at(0).value<Work>(), Work::Finding);
        QVERIFY(m_flow->found().has_value());
        QCOMPARE(m_flow->found()->baud, 500000);
        QCOMPARE(pluggedServos().first().id, quint8(1)); // a find writes nothing
        setUpAndWait();
        QCOMPARE(finished.size(), 2);
        QCOMPARE(finished.at(1).at(0).value<Work>(), Work::SettingUp);
        QCOMPARE(m_flow->jointState(0), JointState::Done);
        QVERIFY(m_flow->jointReason(0).isEmpty());
        QCOMPARE(m_flow->currentJoint(), 1);
        QVERIFY(!m_flow->found().has_value());
        verifySetUp(0, m_robot, m_robot.joints.at(0));
    }

    void noServoAnsweringFailsTheJointWithTheReason()
    {
        findAndWait();
        QCOMPARE(m_flow->jointState(0), JointState::Failed);
        QVERIFY2(m_flow->jointReason(0).contains(QLatin1String("No servo answers")),
                 qPrintable(m_flow->jointReason(0)));
        QVERIFY(!m_flow->found().has_value());
        QCOMPARE(m_flow->currentJoint(), 0);
    }

    void aStopBeforeAnythingIsWrittenLeavesTheJointToDo()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        findAndWait();
        const quint64 revision = pluggedServos().first().revision;
        QVERIFY(m_flow->setUp(nullptr));
        QVERIFY(m_flow->stop());
        QVERIFY(m_flow->isStopping());
        QVERIFY(!m_flow->stop()); // once is enough
        QTRY_VERIFY_WITH_TIMEOUT(!m_flow->isWorking(), 30000);
        QVERIFY(!m_flow->isStopping());
        QCOMPARE(m_flow->jointState(0), JointState::ToDo);
        QCOMPARE(pluggedServos().first().revision, revision);
    }

    void aJointChosenBecomesCurrentButNotWhileWorking()
    {
        QVERIFY(m_flow->chooseJoint(3));
        QCOMPARE(m_flow->currentJoint(), 3);
        QVERIFY(!m_flow->chooseJoint(3)); // already current
        QVERIFY(!m_flow->chooseJoint(m_flow->jointCount()));
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(m_flow->find(nullptr));
        QVERIFY(!m_flow->chooseJoint(0));
        QTRY_VERIFY_WITH_TIMEOUT(!m_flow->isWorking(), 30000);
        QCOMPARE(m_flow->currentJoint(), 3);
    }

    void aCheckMarksTheJointsSetUpAtTheirIdAsDone()
    {
        const feetech::RobotJoint &pan = m_robot.joints.at(0);
        QVERIFY(plug(quint8(pan.id), pan.model, m_robot.baud));
        QVERIFY(withServo(quint8(pan.id), m_robot.baud, [&](sim::VirtualFeetechServo &servo) {
            for (auto it = pan.settings.cbegin(); it != pan.settings.cend(); ++it)
                servo.setValue(it.key(), it.value());
        }));
        QVERIFY(plug(3, QStringLiteral("STS3215"), k1M)); // at elbow_flex's ID, not set up
        QSignalSpy checked(m_flow.get(), &feetech::MotorSetupFlow::checked);
        checkAndWait();
        QCOMPARE(checked.size(), 1);
        QCOMPARE(checked.at(0).at(0).toBool(), true);
        QCOMPARE(checked.at(0).at(2).toInt(), 1);
        QCOMPARE(m_flow->jointState(0), JointState::Done);
        QCOMPARE(m_flow->jointState(2), JointState::ToDo);
        QVERIFY(!m_flow->jointReason(2).isEmpty());
        QCOMPARE(m_flow->currentJoint(), 1); // the first joint not done
    }

    void aCheckCountsOnlyTheJointsAnsweringNowAsTheOperationDoes()
    {
        // Every joint set up, then the arm unplugged and a factory servo connected alone.
        for (const feetech::RobotJoint &joint : std::as_const(m_robot.joints)) {
            QVERIFY(plug(quint8(joint.id), joint.model, m_robot.baud));
            QVERIFY(withServo(quint8(joint.id), m_robot.baud, [&](sim::VirtualFeetechServo &servo) {
                for (auto it = joint.settings.cbegin(); it != joint.settings.cend(); ++it)
                    servo.setValue(it.key(), it.value());
            }));
        }
        checkAndWait();
        for (int joint = 0; joint < m_flow->jointCount(); ++joint)
            QCOMPARE(m_flow->jointState(joint), JointState::Done);
        unplugAll();
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QSignalSpy checked(m_flow.get(), &feetech::MotorSetupFlow::checked);
        QString operationMessage;
        connect(m_client.get(), &feetech::BusClient::submitted, this,
                [&operationMessage](feetech::OperationReply *reply) {
                    connect(reply, &feetech::OperationReply::finished, reply,
                            [&operationMessage](const feetech::OperationResult &result) {
                                operationMessage = result.message;
                            });
                });
        checkAndWait();
        QCOMPARE(checked.size(), 1);
        QCOMPARE(checked.at(0).at(2).toInt(), 0);
        QCOMPARE(operationMessage, QStringLiteral("0 of 6 joint(s) already set up."));
        for (int joint = 0; joint < m_flow->jointCount(); ++joint)
            QCOMPARE(m_flow->jointState(joint), JointState::ToDo);
        QVERIFY2(m_flow->jointReason(0).contains(QLatin1String("ID 1 answers")),
                 qPrintable(m_flow->jointReason(0)));
        QCOMPARE(m_flow->jointReason(1),
                 QStringLiteral("set up earlier, but ID 2 does not answer now"));
        QCOMPARE(m_flow->currentJoint(), 0);
        // And once nothing answers at ID 1 either, nothing is said of what answered there: every
        // joint is simply to do.
        unplugAll();
        checkAndWait();
        for (int joint = 0; joint < m_flow->jointCount(); ++joint) {
            QCOMPARE(m_flow->jointState(joint), JointState::ToDo);
            QVERIFY2(m_flow->jointReason(joint).isEmpty(), qPrintable(m_flow->jointReason(joint)));
        }
    }

    void aServoSetUpReplacesTheListsStaleEntryAtItsNewId()
    {
        // Scanned with a servo at ID 2 that is unplugged since: the factory servo set up as
        // shoulder_lift takes ID 2, and the list shows the bus, ID 2 once and ID 1 no more.
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(2, QStringLiteral("STS3215"), k1M));
        feetech::ScanOptions options;
        options.lastId = 10;
        QSignalSpy scanned(m_client.get(), &feetech::BusClient::scanFinished);
        QVERIFY(m_client->scan(options));
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 30000);
        QCOMPARE(m_client->servos()->idsInUse(), (QVector<int> {1, 2}));
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(1); });
        QVERIFY(m_flow->chooseJoint(1));
        findAndWait();
        setUpAndWait();
        QCOMPARE(m_flow->jointState(1), JointState::Done);
        QCOMPARE(m_client->servos()->idsInUse(), QVector<int> {2});
        QCOMPARE(m_client->servos()->rowCount(), 1);
    }

    void theServoListFollowsWhatTheCheckProved()
    {
        // Scanned with servos at IDs 2 and 5; since then 5 was unplugged and the arm's joints
        // 1-3 were set up: the list shows 1, 2 and 3 after the check, not 5.
        QVERIFY(plug(2, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(5, QStringLiteral("STS3215"), k1M));
        feetech::ScanOptions options;
        options.lastId = 10;
        QSignalSpy scanned(m_client.get(), &feetech::BusClient::scanFinished);
        QVERIFY(m_client->scan(options));
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 30000);
        QCOMPARE(m_client->servos()->idsInUse(), (QVector<int> {2, 5}));
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(1); });
        for (const quint8 id : {1, 3})
            QVERIFY(plug(id, QStringLiteral("STS3215"), k1M));
        checkAndWait();
        QCOMPARE(m_client->servos()->idsInUse(), (QVector<int> {1, 2, 3}));
    }

    void aNewRobotStartsOver()
    {
        QVERIFY(m_flow->chooseJoint(2));
        m_flow->setRobot(m_robot);
        QCOMPARE(m_flow->currentJoint(), 0);
        m_flow->setRobot({});
        QCOMPARE(m_flow->currentJoint(), -1);
        feetech::Refusal refusal;
        QVERIFY(!m_flow->checkBus(&refusal));
        QVERIFY(!m_flow->find(&refusal));
        QVERIFY(!refusal);
    }
};

QTEST_GUILESS_MAIN(TestMotorSetupFlow)
#include "tst_motorsetupflow.moc"
