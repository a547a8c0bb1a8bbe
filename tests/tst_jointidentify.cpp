// Tests identifying a joint end to end on a simulated bus (STS3215 ×2, SCS0009 at 1 Mbps): the
// horn moves only around where it stood and comes back, torque, torque limit, goal and speed are
// restored whether torque was on or off, a servo held by a motion test is refused, and a servo
// that stops answering is reported.
#include "feetechbus.h"
#include "jointidentify.h"
#include "motiontest.h"
#include "operationlog.h"
#include "servoctlrun.h"

#include <QTimer>
#include <QtTest>

#include <algorithm>
#include <csignal>
#include <memory>

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 kAmplitude = feetech::JointIdentify::kAmplitude;
constexpr qint32 kTolerance = feetech::JointIdentify::kReachTolerance;

} // namespace

class TestJointIdentify : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;

    int readServo(quint8 id)
    {
        return testsupport::connectScanAndRead(*m_client, m_simulator->linkPath(), 4, id);
    }

    struct Watched
    {
        qint32 lowest = 0;
        qint32 highest = 0;
        qint32 lowestTorqueLimit = 0;
        std::optional<feetech::OperationResult> result;
    };

    // Starts identifying servo `index` (ID `id`) and watches the simulated horn until the
    // result comes (20 s at most).
    Watched identifyWatching(int index, quint8 id)
    {
        Watched watched;
        watched.lowest = watched.highest = simulatorValue(id, u"present_position");
        watched.lowestTorqueLimit = simulatorValue(id, u"torque_limit");
        QTimer sampler;
        connect(&sampler, &QTimer::timeout, this, [&] {
            const qint32 position = simulatorValue(id, u"present_position");
            watched.lowest = std::min(watched.lowest, position);
            watched.highest = std::max(watched.highest, position);
            watched.lowestTorqueLimit =
                std::min(watched.lowestTorqueLimit, simulatorValue(id, u"torque_limit"));
        });
        sampler.start(2);
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        feetech::Refusal refusal;
        if (!m_client->identify()->start(index, &refusal)) {
            qWarning("identify refused: %s", qPrintable(refusal.describe()));
            return watched;
        }
        const bool ended = QTest::qWaitFor(
            [&] {
                for (const QList<QVariant> &signal : std::as_const(finished)) {
                    const auto result = signal.at(0).value<feetech::OperationResult>();
                    if (result.operation == feetech::Operation::Identify) {
                        watched.result = result;
                        return true;
                    }
                }
                return false;
            },
            20000);
        if (!ended)
            qWarning("identify did not end within 20 s");
        return watched;
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS0009"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
    }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void withTorqueOffTheHornWigglesAroundItsStartAndEverythingIsRestored()
    {
        setSimulatorValue(1, u"goal_speed", 777);
        const int index = readServo(1);
        QVERIFY(index >= 0);
        const qint32 start = simulatorValue(1, u"present_position");
        const qint32 limit = simulatorValue(1, u"torque_limit");
        const qint32 goal = simulatorValue(1, u"goal_position");
        const qint32 acceleration = simulatorValue(1, u"acceleration");
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);

        const Watched watched = identifyWatching(index, 1);
        QVERIFY(watched.result);
        QVERIFY2(watched.result->ok, qPrintable(watched.result->message));
        QVERIFY(watched.result->message.contains(QStringLiteral("off")));
        // It moved both ways, never further than the amplitude, and came back.
        QVERIFY2(watched.highest >= start + kAmplitude / 2,
                 qPrintable(QString::number(watched.highest)));
        QVERIFY2(watched.lowest <= start - kAmplitude / 2,
                 qPrintable(QString::number(watched.lowest)));
        QVERIFY(watched.highest <= start + kAmplitude + kTolerance);
        QVERIFY(watched.lowest >= start - kAmplitude - kTolerance);
        QVERIFY(std::abs(simulatorValue(1, u"present_position") - start) <= kTolerance);
        // It moved with little torque.
        QVERIFY(watched.lowestTorqueLimit <= 300);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(1, u"torque_limit"), limit);
        QCOMPARE(simulatorValue(1, u"goal_position"), goal);
        QCOMPARE(simulatorValue(1, u"goal_speed"), 777);
        QCOMPARE(simulatorValue(1, u"acceleration"), acceleration);
        QVERIFY(!m_client->identify()->isRunning(index));
        QVERIFY(!m_client->isBusy());
    }

    void withTorqueOnTheTorqueStaysOnAndTheHornComesBack()
    {
        const qint32 start = simulatorValue(2, u"present_position");
        setSimulatorValue(2, u"goal_position", start);
        setSimulatorValue(2, u"torque_enable", 1);
        setSimulatorValue(2, u"torque_limit", 800);
        const int index = readServo(2);
        QVERIFY(index >= 0);

        const Watched watched = identifyWatching(index, 2);
        QVERIFY(watched.result);
        QVERIFY2(watched.result->ok, qPrintable(watched.result->message));
        QVERIFY(watched.highest >= start + kAmplitude / 2);
        QVERIFY(watched.lowest <= start - kAmplitude / 2);
        QVERIFY(watched.highest <= start + kAmplitude + kTolerance);
        QVERIFY(watched.lowest >= start - kAmplitude - kTolerance);
        QCOMPARE(simulatorValue(2, u"torque_enable"), 1);
        QCOMPARE(simulatorValue(2, u"torque_limit"), 800);
        QCOMPARE(simulatorValue(2, u"goal_position"), start);
        QTRY_VERIFY_WITH_TIMEOUT(
            std::abs(simulatorValue(2, u"present_position") - start) <= kTolerance, 5000);
    }

    void anScsServoWithoutATorqueLimitIsIdentifiedToo()
    {
        const int index = readServo(3);
        QVERIFY(index >= 0);
        const qint32 start = simulatorValue(3, u"present_position");
        const Watched watched = identifyWatching(index, 3);
        QVERIFY(watched.result);
        QVERIFY2(watched.result->ok, qPrintable(watched.result->message));
        QVERIFY(watched.highest > start);
        QVERIFY(watched.lowest < start);
        QCOMPARE(simulatorValue(3, u"torque_enable"), 0);
    }

    void aServoInAMotionTestIsRefusedWithTheReasonAndNothingIsSent()
    {
        const int index = readServo(1);
        QVERIFY(index >= 0);
        feetech::MotionTest test(m_client.get(), testsupport::quickMotionTiming());
        feetech::MotionTestRefusal why;
        QVERIFY2(test.startSweep(testsupport::longSweep(index), &why), qPrintable(why.describe()));
        QCOMPARE(m_client->identify()->blocker(index).code(), feetech::Refusal::Code::ServoHeld);
        // The holder's reason is what the user reads.
        QVERIFY(m_client->identify()->blocker(index).describe().contains(
            QStringLiteral("motion test")));
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        feetech::Refusal refusal;
        QVERIFY(!m_client->identify()->start(index, &refusal));
        QCOMPARE(refusal.code(), feetech::Refusal::Code::ServoHeld);
        QVERIFY(!m_client->identify()->isRunning(index));
        // The other servo is free.
        QVERIFY2(
            !m_client->identify()->blocker(m_client->servos()->indexOf({2, k1M})),
            qPrintable(
                m_client->identify()->blocker(m_client->servos()->indexOf({2, k1M})).describe()));
        test.cancel();
        QVERIFY(!m_client->identify()->blocker(index));
    }

    void aMotionTestIsRefusedWhileItsServoIsIdentified()
    {
        const int index = readServo(1);
        QVERIFY(index >= 0);
        QVERIFY(m_client->identify()->start(index));
        feetech::MotionTest test(m_client.get(), testsupport::quickMotionTiming());
        feetech::MotionPlan plan;
        plan.index = index;
        plan.from = 1800;
        plan.to = 2300;
        feetech::MotionTestRefusal refusal;
        QVERIFY(!test.startStep(plan, &refusal));
        QCOMPARE(refusal.code(), feetech::MotionTestRefusal::Code::BeingIdentified);
        QCOMPARE(refusal.servoId(), quint8(1));
        QVERIFY(refusal.describe().contains(QStringLiteral("identified")));
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->identify()->isRunning(index), 20000);
    }

    void aServoThatStopsAnsweringIsReportedAndTheIdentifyEnds()
    {
        const int index = readServo(2);
        QVERIFY(index >= 0);
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QVERIFY(m_client->identify()->start(index));
        // Unplugged once it has started moving.
        QTRY_VERIFY_WITH_TIMEOUT(simulatorValue(2, u"torque_enable") == 1, 10000);
        m_simulator->call([](sim::Simulator &simulator) {
            sim::VirtualFeetechBus &bus = *simulator.feetechBus();
            for (int i = 0; i < bus.servoCount(); ++i) {
                if (bus.servo(i).id() == 2) {
                    bus.unplug(i);
                    return;
                }
            }
        });
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->identify()->isRunning(index), 20000);
        std::optional<feetech::OperationResult> result;
        for (const QList<QVariant> &signal : std::as_const(finished)) {
            const auto each = signal.at(0).value<feetech::OperationResult>();
            if (each.operation == feetech::Operation::Identify)
                result = each;
        }
        QVERIFY(result);
        QVERIFY(!result->ok);
        QCOMPARE(result->failure, feetech::OperationFailure::NoAnswer);
    }

    void allTorqueOffStopsItAndTheTorqueStaysOff()
    {
        const int index = readServo(1);
        QVERIFY(index >= 0);
        const qint32 limit = simulatorValue(1, u"torque_limit");
        OperationLog finishedLog(m_client.get());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QVERIFY(m_client->identify()->start(index));
        QTRY_VERIFY_WITH_TIMEOUT(simulatorValue(1, u"torque_enable") == 1, 10000);
        m_client->allTorqueOff();
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->identify()->isRunning(index), 20000);
        bool stopped = false;
        for (const QList<QVariant> &signal : std::as_const(finished)) {
            const auto each = signal.at(0).value<feetech::OperationResult>();
            if (each.operation == feetech::Operation::Identify)
                stopped = !each.ok && each.failure == feetech::OperationFailure::AfterTorqueOff;
        }
        QVERIFY(stopped);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(1, u"torque_limit"), limit);
    }

    void aServoAtAnotherRateIsIdentifiedWhileTheMonitorStreamsBothRates()
    {
        // Between moves the monitor's reads leave the link at 1 Mbps: every move and the
        // restore go out at servo 1's 500 kbps all the same.
        constexpr qint32 k500k = 500000;
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k500k},
                                            {2, QStringLiteral("STS3215"), k1M}}),
                                &error),
                 qPrintable(error));
        m_client->connectTo(m_simulator->linkPath(), k1M, seriallink::EchoMode::Auto);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->link()->isConnected(), 10000);
        feetech::ScanOptions options;
        options.lastId = 4;
        options.bauds = {k500k, k1M};
        QSignalSpy scanned(m_client.get(), &feetech::BusClient::scanFinished);
        m_client->scan(options);
        QTRY_VERIFY_WITH_TIMEOUT(!scanned.isEmpty(), 20000);
        const int slow = m_client->servos()->indexOf({1, k500k});
        const int fast = m_client->servos()->indexOf({2, k1M});
        QVERIFY(slow >= 0 && fast >= 0);
        m_client->readServo(slow);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->servos()->at(slow).read, 10000);
        feetech::Refusal refusal;
        QVERIFY2(m_client->telemetry()->subscribe(this, {slow, fast}, 0, &refusal),
                 qPrintable(refusal.describe()));
        const qint32 start = simulatorValue(1, u"present_position");
        const qint32 limit = simulatorValue(1, u"torque_limit");

        const Watched watched = identifyWatching(slow, 1);
        m_client->telemetry()->unsubscribe(this);
        QVERIFY(watched.result);
        QVERIFY2(watched.result->ok, qPrintable(watched.result->message));
        QVERIFY(watched.highest >= start + kAmplitude / 2);
        QVERIFY(watched.lowest <= start - kAmplitude / 2);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(1, u"torque_limit"), limit);
    }

    void servoctlIdentifyExitsZeroWithTorqueRestoredAndTwoForUsage()
    {
        const QString link = m_simulator->linkPath();
        const auto done = testsupport::runServoctl(
            {QStringLiteral("--port"), link, QStringLiteral("feetech"), QStringLiteral("identify"),
             QStringLiteral("--id"), QStringLiteral("1")});
        QVERIFY2(done.exitCode == 0, qPrintable(done.err));
        QVERIFY(done.out.contains(QStringLiteral("wiggled")));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        const auto missing = testsupport::runServoctl(
            {QStringLiteral("--port"), link, QStringLiteral("feetech"), QStringLiteral("identify"),
             QStringLiteral("--id"), QStringLiteral("9")});
        QCOMPARE(missing.exitCode, 1);
        const auto usage =
            testsupport::runServoctl({QStringLiteral("--port"), link, QStringLiteral("feetech"),
                                      QStringLiteral("identify")});
        QCOMPARE(usage.exitCode, 2);
    }

    void servoctlIdentifyStoppedByCtrlCRestoresTheServoAndExitsOne()
    {
        const qint32 limit = simulatorValue(1, u"torque_limit");
        const qint32 goal = simulatorValue(1, u"goal_position");
        // Ctrl-C once the horn is held: only the identify itself can have switched torque on,
        // so servoctl is inside it and watching for the signal.
        QTimer interrupter;
        connect(&interrupter, &QTimer::timeout, this, [&] {
            if (simulatorValue(1, u"torque_enable") == 1) {
                interrupter.stop();
                std::raise(SIGINT);
            }
        });
        interrupter.start(5);
        const auto done = testsupport::runServoctl(
            {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("feetech"),
             QStringLiteral("identify"), QStringLiteral("--id"), QStringLiteral("1")});
        QVERIFY(!interrupter.isActive());
        QCOMPARE(done.exitCode, 1);
        QVERIFY2(done.err.contains(QStringLiteral("interrupted")), qPrintable(done.err));
        QVERIFY2(done.err.contains(QStringLiteral("stopped")), qPrintable(done.err));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(1, u"torque_limit"), limit);
        QCOMPARE(simulatorValue(1, u"goal_position"), goal);
    }

    void servoctlIdentifyOfAServoNotInPositionModeExitsOneWithoutWriting()
    {
        setSimulatorValue(1, u"mode", 1);
        const auto refused = testsupport::runServoctl(
            {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("feetech"),
             QStringLiteral("identify"), QStringLiteral("--id"), QStringLiteral("1")});
        QCOMPARE(refused.exitCode, 1);
        QVERIFY2(refused.err.contains(QStringLiteral("position mode")), qPrintable(refused.err));
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write, 1)
                    .isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestJointIdentify)
#include "tst_jointidentify.moc"
