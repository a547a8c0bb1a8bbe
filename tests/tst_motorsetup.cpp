// Tests of motor set-up through the session: finding the one servo at any rate, refusing every
// other bus, setting up ID, rate and settings, the joints check, all against the simulator.
#include "pluggedbus.h"

#include "busoperations.h"
#include "motorsetup.h"

#include <QtTest>

using feetech::JointCheck;
using feetech::MotorSearch;
using feetech::MotorSetupResult;
using feetech::MotorTarget;

namespace {

constexpr qint32 k1M = 1000000;

const QString kArm = QStringLiteral("SO-101 follower arm");

} // namespace

class TestMotorSetup : public testsupport::PluggedBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::Session> m_session;
    feetech::RobotTemplate m_robot = testsupport::builtInRobot(kArm);

    MotorTarget jointTarget(int id) const
    {
        for (const feetech::RobotJoint &joint : m_robot.joints) {
            if (joint.id == id)
                return feetech::motorTarget(m_robot, joint);
        }
        return {};
    }

    // Runs `start` and waits up to 30 s for the find or set-up it starts to end.
    MotorSetupResult run(const std::function<void()> &start)
    {
        QSignalSpy finished(m_session.get(), &feetech::Session::operationFinished);
        start();
        if (finished.isEmpty() && !finished.wait(30000))
            return {};
        const auto result = finished.first().at(0).value<feetech::OperationResult>();
        return result.detail.value<MotorSetupResult>();
    }

    MotorSetupResult setUp(const MotorTarget &target)
    {
        return run([&] { m_session->submit(feetech::operations::setUpMotor(target)); });
    }

    // A set-up that must write nothing to any servo on the bus; its result.
    MotorSetupResult refusedSetUp(MotorSearch::Verdict verdict)
    {
        const QVector<testsupport::PluggedServo> before = pluggedServos();
        const MotorSetupResult result = setUp(jointTarget(2));
        [&] {
            QVERIFY2(!result.ok, qPrintable(result.message));
            QCOMPARE(int(result.search.verdict), int(verdict));
            QCOMPARE(result.failure, result.search.failure());
            QVERIFY2(result.message.contains(QLatin1String("othing was written"))
                         || result.message.contains(QLatin1String("at a time"))
                         || result.message.contains(QLatin1String("no servo"), Qt::CaseInsensitive),
                     qPrintable(result.message));
            const QVector<testsupport::PluggedServo> after = pluggedServos();
            QCOMPARE(after.size(), before.size());
            for (int i = 0; i < before.size(); ++i) {
                QCOMPARE(after.at(i).revision, before.at(i).revision);
                QCOMPARE(after.at(i).eeprom, before.at(i).eeprom);
            }
            QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write)
                        .isEmpty());
        }();
        return result;
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startEmptyBus(&error), qPrintable(error));
        m_session = std::make_unique<feetech::Session>();
        m_session->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        QCOMPARE(m_session->status().state, seriallink::ConnectionState::Connected);
    }

    void cleanup()
    {
        m_session.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aFactoryServoAtAnyRateGetsTheJointsIdRateAndSettings_data()
    {
        QTest::addColumn<qint32>("factoryBaud");
        QTest::newRow("1 Mbps") << k1M;
        QTest::newRow("500 kbps") << 500000;
        QTest::newRow("115200 bps") << 115200;
    }

    void aFactoryServoAtAnyRateGetsTheJointsIdRateAndSettings()
    {
        QFETCH(qint32, factoryBaud);
        QVERIFY(plug(1, QStringLiteral("STS3215"), factoryBaud));
        const MotorTarget target = jointTarget(6); // the gripper has settings of its own
        QSignalSpy progress(m_session.get(), &feetech::Session::operationProgress);
        const MotorSetupResult result = setUp(target);
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.from.id, quint8(1));
        QCOMPARE(result.from.baud, factoryBaud);
        QCOMPARE(result.to.id, quint8(6));
        QCOMPARE(result.to.baud, k1M);
        QCOMPARE(result.verified.value(QStringLiteral("phase")) & 0x10, 0);
        QMap<QString, qint32> settings = result.verified;
        settings.remove(QStringLiteral("phase")); // a bit to clear, not a value
        QCOMPARE(settings, target.settings);
        QVERIFY(result.message.contains(QLatin1String("gripper is set up")));
        QCOMPARE(progress.size(), 5);
        QCOMPARE(progress.last().at(0).value<feetech::OperationProgress>().done, 5);
        verifySetUp(0, m_robot, *m_robot.joint(u"gripper"));
        powerCycle();
        verifySetUp(0, m_robot, *m_robot.joint(u"gripper"), Settings::EepromOnly);
    }

    void phaseBit4IsClearedAndThePhasesOtherBitsKept()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) {
            s.storeValue(u"phase", 0x80 | 0x10 | 0x01); // feedback reversed, multi-turn, driver
        }));
        const MotorTarget target = jointTarget(2);
        QCOMPARE(target.clearedBits.value(QStringLiteral("phase")), 0x10u);
        const MotorSetupResult result = setUp(target);
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.verified.value(QStringLiteral("phase")), 0x81);
        QCOMPARE(simulatorValue(2, u"phase"), 0x81);
        // One count of what was verified, in the headline as in the read-back step.
        const int settings = int(target.settings.size() + target.clearedBits.size());
        QVERIFY2(result.message.contains(QStringLiteral("%1 setting(s) verified").arg(settings)),
                 qPrintable(result.message));
        QVERIFY2(result.steps.join(u'|').contains(
                     QStringLiteral("%1 setting(s) hold their values").arg(settings)),
                 qPrintable(result.steps.join(u'|')));
    }

    void aServoAlreadySetUpIsOnlyVerified()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(setUp(jointTarget(1)).ok);
        const quint64 revision = pluggedServos().first().revision;
        const MotorSetupResult again = setUp(jointTarget(1));
        QVERIFY2(again.ok, qPrintable(again.message));
        QVERIFY(again.steps.contains(QStringLiteral("It already holds every setting.")));
        QCOMPARE(pluggedServos().first().revision, revision);
    }

    void findReportsTheOneServoWithoutWriting()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), 115200));
        const MotorSetupResult result =
            run([&] { m_session->submit(feetech::operations::findMotor(jointTarget(3))); });
        QVERIFY(result.ok);
        QVERIFY(!result.setUp);
        QCOMPARE(int(result.search.verdict), int(MotorSearch::Verdict::OneServo));
        QCOMPARE(result.search.servo.model.name, QStringLiteral("STS3215"));
        QCOMPARE(result.search.servo.baud, 115200);
        QVERIFY(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).isEmpty());
    }

    void noServoAnsweringWritesNothingAndSaysToCheckThePower()
    {
        const MotorSetupResult result = refusedSetUp(MotorSearch::Verdict::NoServo);
        QCOMPARE(result.failure, feetech::OperationFailure::NoAnswer);
        QCOMPARE(result.message,
                 QStringLiteral("No servo answers at any rate: check the power and the cable, and "
                                "connect the next servo."));
    }

    void twoServosAtDifferentIdsWriteNothing()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(2, QStringLiteral("STS3215"), k1M));
        const MotorSetupResult result = refusedSetUp(MotorSearch::Verdict::SeveralServos);
        QCOMPARE(result.failure, feetech::OperationFailure::SeveralServos);
        QVERIFY2(result.message.contains(QLatin1String("connect one servo at a time")),
                 qPrintable(result.message));
        QVERIFY(result.search.count >= 2);
    }

    void twoServosAtOneIdAreToldApartByTheirGarbledPositionReads()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        const MotorSetupResult result = refusedSetUp(MotorSearch::Verdict::SharedId);
        QCOMPARE(result.failure, feetech::OperationFailure::SharedId);
        QCOMPARE(result.message,
                 QStringLiteral("Two servos answer at ID 1; connect them one at a time."));
    }

    void aServoAtAnotherRateBesidesOneAt1MbpsWritesNothing()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(1, QStringLiteral("STS3215"), 115200));
        const MotorSetupResult result = refusedSetUp(MotorSearch::Verdict::SeveralServos);
        QCOMPARE(result.search.count, 2);
        QVERIFY2(result.message.startsWith(QLatin1String("2 servos answer (ID 1 at 1")),
                 qPrintable(result.message));
        QVERIFY(result.message.contains(QLatin1String("ID 1 at 115")));
    }

    void aServoOfAnotherModelWritesNothingAndNamesBothModels()
    {
        QVERIFY(plug(1, QStringLiteral("SCS15"), k1M));
        const MotorSetupResult result = refusedSetUp(MotorSearch::Verdict::WrongModel);
        QCOMPARE(result.failure, feetech::OperationFailure::WrongModel);
        QVERIFY2(result.message.startsWith(QLatin1String("Found servo 1 at 1 Mbps, model SCS15")),
                 qPrintable(result.message));
        QVERIFY(result.message.contains(QLatin1String("shoulder_lift needs model STS3215")));
    }

    void aStopBeforeTheNextStepWritesNothingMore()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        const quint64 revision = pluggedServos().first().revision;
        const MotorSetupResult result = run([&] {
            m_session->submit(feetech::operations::setUpMotor(jointTarget(2)));
            m_session->cancel(feetech::Operation::SetUpMotor);
        });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::Stopped);
        QCOMPARE(pluggedServos().first().revision, revision);
        QCOMPARE(pluggedServos().first().id, quint8(1));
    }

    void aStopWhileTheSetUpWaitsInTheQueueWritesNothing()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        const quint64 revision = pluggedServos().first().revision;
        feetech::ScanOptions options;
        options.lastId = 2;
        const MotorSetupResult result = run([&] {
            m_session->submit(
                feetech::operations::scan(options)); // the set-up waits behind the scan
            m_session->submit(feetech::operations::setUpMotor(jointTarget(2)));
            m_session->cancel(feetech::Operation::SetUpMotor);
        });
        QVERIFY2(!result.ok, qPrintable(result.message));
        QVERIFY(result.stopped);
        QCOMPARE(pluggedServos().first().revision, revision);
        QCOMPARE(pluggedServos().first().id, quint8(1));
    }

    void ramSettingsAreWrittenWithoutSayingTheEepromWasUnlocked()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        MotorTarget target = jointTarget(2);
        target.settings = {{QStringLiteral("acceleration"), 20}};
        const MotorSetupResult result = setUp(target);
        QVERIFY2(result.ok, qPrintable(result.message));
        QVERIFY2(result.steps.contains(QStringLiteral("Wrote acceleration.")),
                 qPrintable(result.steps.join(QLatin1Char('|'))));
    }

    void theCheckShowsJointsSetUpAtTheirIdAsDone()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(setUp(jointTarget(1)).ok);
        QVERIFY(plug(2, QStringLiteral("STS3215"), k1M)); // at its ID, but as it left the factory
        QVERIFY(plug(3, QStringLiteral("SCS15"), k1M));
        QVERIFY(plug(4, QStringLiteral("STS3215"), 115200)); // not at the template's rate
        powerCycle(); // RAM settings (acceleration) start afresh; the set-up holds
        const QVector<JointCheck> joints = feetech::jointChecks(m_robot);
        QSignalSpy checked(m_session.get(), &feetech::Session::operationFinished);
        m_session->submit(feetech::operations::checkJoints(k1M, joints));
        QVERIFY(checked.wait(20000));
        const auto result = checked.first()
                                .at(0)
                                .value<feetech::OperationResult>()
                                .detail.value<QVector<JointCheck>>();
        QCOMPARE(result.size(), 6);
        QVERIFY(result.at(0).done());
        QVERIFY(!result.at(1).done());
        QVERIFY(result.at(1).found);
        QVERIFY2(result.at(1).problem().startsWith(QLatin1String("ID 2 answers, but ")),
                 qPrintable(result.at(1).problem()));
        QVERIFY(result.at(1).problem().contains(QLatin1String("p_gain is 32, not 16")));
        QVERIFY(!result.at(2).done());
        QCOMPARE(result.at(2).problem(),
                 QStringLiteral("ID 3 answers as model SCS15, not STS3215."));
        for (int i = 3; i < 6; ++i) {
            QVERIFY(!result.at(i).found);
            QVERIFY(result.at(i).problem().isEmpty());
        }
    }
};

QTEST_GUILESS_MAIN(TestMotorSetup)
#include "tst_motorsetup.moc"
