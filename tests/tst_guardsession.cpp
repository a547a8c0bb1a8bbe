// End-to-end tests of the overload and thermal guard over the pty simulator: a blocked horn is
// held (or its torque switched off), a hot servo is held, and a tripped overload is recovered.
#include "busoperations.h"
#include "feetechbus.h"

#include "overloadguard.h"
#include "servoparameters.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::GuardCause;
using feetech::GuardEvent;
using feetech::GuardStage;
using feetech::OperationResult;

namespace {

constexpr qint32 k1M = 1000000;

QVector<GuardEvent> eventsOf(const QSignalSpy &spy)
{
    QVector<GuardEvent> events;
    for (const QList<QVariant> &arguments : spy)
        events.append(arguments.at(0).value<GuardEvent>());
    return events;
}

// The first event of `cause` at `stage`, its place in `events` in *at; nothing when none.
std::optional<GuardEvent> find(const QVector<GuardEvent> &events, GuardCause cause,
                               GuardStage stage, int *at = nullptr)
{
    for (int i = 0; i < events.size(); ++i) {
        if (events.at(i).cause == cause && events.at(i).stage == stage) {
            if (at)
                *at = i;
            return events.at(i);
        }
    }
    return std::nullopt;
}

} // namespace

class TestGuardSession : public testsupport::FeetechSessionTest
{
    Q_OBJECT

private:
    feetech::ServoInfo m_servo;

    // Torque on and a goal far from where the horn stands, through the session's write.
    OperationResult drive(qint32 goal)
    {
        QString error;
        const auto writes = feetech::encodeWrites(
            m_servo.table(),
            {{QStringLiteral("torque_enable"), 1}, {QStringLiteral("goal_position"), goal}},
            &error);
        if (!writes) {
            qWarning("%s", qPrintable(error));
            return {};
        }
        return run([&] { m_session->submit(feetech::operations::write(m_servo, *writes)); });
    }

    void setAction(feetech::GuardAction action)
    {
        feetech::GuardSettings settings;
        feetech::GuardLimits limits = feetech::defaultGuardLimits(m_servo.table());
        limits.action = action;
        settings.servos.insert({m_servo.id, m_servo.baud}, limits);
        m_session->setGuardSettings(settings);
    }

    // A guard set low enough to see even a torque-limited strain, and the horn held by a load.
    bool blockUnderAStrictGuard()
    {
        feetech::GuardSettings settings;
        feetech::GuardLimits limits = feetech::defaultGuardLimits(m_servo.table());
        limits.loadPercent = 5.0;
        limits.holdTime = std::chrono::milliseconds(400);
        settings.servos.insert({m_servo.id, m_servo.baud}, limits);
        m_session->setGuardSettings(settings);
        return withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); });
    }

    bool waitFor(QSignalSpy &spy, GuardCause cause, GuardStage stage)
    {
        return QTest::qWaitFor([&] { return find(eventsOf(spy), cause, stage).has_value(); },
                               15000);
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSession(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
        // The servo's own overload trip as late as it goes (2.54 s): a loaded machine delays
        // the guard's samples, and the tests are about the guard, not about that race.
        setSimulatorValue(1, u"protection_time", 254);
        feetech::ScanOptions options;
        options.bauds = {k1M};
        options.lastId = 1;
        QSignalSpy scanned(m_session.get(), &feetech::Session::scanFinished);
        m_session->submit(feetech::operations::scan(options));
        QVERIFY(scanned.wait(20000));
        QCOMPARE(m_found.size(), 1);
        m_servo = m_found.first();
    }

    void cleanup()
    {
        stopSession();
        m_found.clear();
    }

    void aBlockedHornIsWarnedAboutThenHeldWhereItStands()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); }));
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        QSignalSpy logged(m_session.get(), &feetech::Session::packetLogged);
        const qint32 start = simulatorValue(1, u"present_position");
        QVERIFY(drive(start > 2048 ? 500 : 3500).ok);
        QVERIFY(waitFor(events, GuardCause::Overload, GuardStage::Acted));
        int warnedAt = -1;
        int actedAt = -1;
        const auto warned =
            find(eventsOf(events), GuardCause::Overload, GuardStage::Warning, &warnedAt);
        const auto acted =
            find(eventsOf(events), GuardCause::Overload, GuardStage::Acted, &actedAt);
        QVERIFY(warned);
        QVERIFY(warnedAt < actedAt); // warns first
        QVERIFY(acted->ok);
        QCOMPARE(acted->action, feetech::GuardAction::Hold);
        QVERIFY(std::abs(acted->value) > acted->limit);
        QVERIFY(acted->steadyUs - warned->steadyUs > 0);
        QVERIFY2(acted->message.contains(QLatin1String("ID 1")), qPrintable(acted->message));
        // Held: the goal is where the horn stands (it never moved), the torque still on.
        QVERIFY(acted->heldAt);
        QCOMPARE(simulatorValue(1, u"goal_position"), *acted->heldAt);
        QCOMPARE(simulatorValue(1, u"present_position"), start);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        // The packet log says it too.
        bool inLog = false;
        for (const QList<QVariant> &arguments : std::as_const(logged))
            inLog = inLog
                || arguments.at(0).value<seriallink::PacketLogEntry>().error == acted->message;
        QVERIFY(inLog);
    }

    void theTorqueOffActionSwitchesTheBlockedServosTorqueOff()
    {
        setAction(feetech::GuardAction::TorqueOff);
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(-1000); }));
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        QVERIFY(drive(simulatorValue(1, u"present_position") > 2048 ? 500 : 3500).ok);
        QVERIFY(waitFor(events, GuardCause::Overload, GuardStage::Acted));
        const auto acted = find(eventsOf(events), GuardCause::Overload, GuardStage::Acted);
        QVERIFY(acted->ok);
        QCOMPARE(acted->action, feetech::GuardAction::TorqueOff);
        QVERIFY(acted->message.contains(QLatin1String("torque was switched off")));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void aServoMovedByASyncWriteIsGuardedToo()
    {
        // The Joints tab's Move all: torque on first, then the goals in one SYNC WRITE.
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); }));
        QString error;
        const auto torque =
            feetech::encodeWrites(m_servo.table(), {{QStringLiteral("torque_enable"), 1}}, &error);
        QVERIFY(torque);
        QVERIFY(run([&] { m_session->submit(feetech::operations::write(m_servo, *torque)); }).ok);
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        const qint32 start = simulatorValue(1, u"present_position");
        const auto goal = feetech::encodeWrites(
            m_servo.table(), {{QStringLiteral("goal_position"), start > 2048 ? 500 : 3500}},
            &error);
        QVERIFY(goal);
        QVERIFY(run([&] {
                    m_session->submit(feetech::operations::syncWrite(
                        k1M, goal->first().address, int(goal->first().bytes.size()),
                        {{1, goal->first().bytes}}));
                }).ok);
        QVERIFY(waitFor(events, GuardCause::Overload, GuardStage::Acted));
        QCOMPARE(simulatorValue(1, u"goal_position"), start);
    }

    void anIdentifyOfABlockedServoIsStoppedAndPutBack()
    {
        QVERIFY(blockUnderAStrictGuard());
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        QSignalSpy finished(m_session.get(), &feetech::Session::operationFinished);
        m_session->submit(feetech::operations::identifyJoint(m_servo));
        QVERIFY(waitFor(events, GuardCause::Overload, GuardStage::Acted));
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 15000);
        const auto result = finished.first().at(0).value<OperationResult>();
        QCOMPARE(result.operation, feetech::Operation::Identify);
        QVERIFY(!result.ok); // stopped, not finished
    }

    void aMoveTestOfABlockedServoIsStoppedByTheGuard()
    {
        QVERIFY(blockUnderAStrictGuard());
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        QSignalSpy finished(m_session.get(), &feetech::Session::operationFinished);
        m_session->submit(feetech::operations::moveTest(m_servo));
        QVERIFY(waitFor(events, GuardCause::Overload, GuardStage::Acted));
        QTRY_VERIFY_WITH_TIMEOUT(!finished.isEmpty(), 15000);
        const auto result = finished.first().at(0).value<OperationResult>();
        QCOMPARE(result.operation, feetech::Operation::MoveTest);
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::GuardStopped);
    }

    void aServoNearItsMaximumTemperatureHasItsTorqueSwitchedOff()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) {
            s.setAmbientTemperature(67.0);
            s.setTemperature(67.0); // max 70 °C: within the 5 °C margin
        }));
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        const qint32 start = simulatorValue(1, u"present_position");
        QVERIFY(drive(start > 2048 ? start - 300 : start + 300).ok);
        QVERIFY(waitFor(events, GuardCause::Heat, GuardStage::Acted));
        int warnedAt = -1;
        int actedAt = -1;
        QVERIFY(find(eventsOf(events), GuardCause::Heat, GuardStage::Warning, &warnedAt));
        const auto acted = find(eventsOf(events), GuardCause::Heat, GuardStage::Acted, &actedAt);
        QVERIFY(warnedAt < actedAt);
        // A held motor keeps warming: heat is met with torque off, whatever the action set.
        QVERIFY(acted->ok);
        QCOMPARE(acted->action, feetech::GuardAction::TorqueOff);
        QVERIFY(acted->value >= 65.0);
        QVERIFY2(acted->message.contains(QLatin1String("70")), qPrintable(acted->message));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void aServoOutsidePositionModeIsNotHeldButSwitchedOff()
    {
        // In step mode a goal is a relative move: the guard must not write one.
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); }));
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        const qint32 start = simulatorValue(1, u"present_position");
        QVERIFY(drive(start > 2048 ? start - 300 : start + 300).ok);
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setValue(u"mode", 3); }));
        const qint32 goalBefore = simulatorValue(1, u"goal_position");
        QVERIFY(waitFor(events, GuardCause::Overload, GuardStage::Acted));
        const auto acted = find(eventsOf(events), GuardCause::Overload, GuardStage::Acted);
        QVERIFY(acted->ok);
        QCOMPARE(acted->action, feetech::GuardAction::TorqueOff);
        QVERIFY(!acted->heldAt);
        QCOMPARE(simulatorValue(1, u"goal_position"), goalBefore);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void aHotServoThatNothingDrivesIsOnlyWarnedAbout()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) {
            s.setAmbientTemperature(68.0);
            s.setTemperature(68.0);
        }));
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        feetech::TelemetryOptions options;
        options.servos = {m_servo};
        options.rateHz = 20.0;
        m_session->startTelemetry(options); // the Monitor page: samples, nothing driven
        QVERIFY(waitFor(events, GuardCause::Heat, GuardStage::Warning));
        // An action would have gone ahead of this ping.
        QVERIFY(run([&] { m_session->submit(feetech::operations::ping(1, k1M)); }).ok);
        m_session->stopTelemetry();
        QVERIFY(!find(eventsOf(events), GuardCause::Heat, GuardStage::Acted));
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write, 1)
                    .isEmpty());
    }

    void aServoThatIsNotDrivenIsNotRead()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setTemperature(68.0); }));
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        // A read of the servo's RAM: nothing drives it, so the guard stays silent; the guard's
        // first read would have come with the write that drives it.
        QVERIFY(run([&] {
                    m_session->submit(feetech::operations::read(
                        m_servo, m_servo.table().ramBlocks(), feetech::ReadSource::Refresh));
                }).ok);
        QVERIFY(run([&] { m_session->submit(feetech::operations::ping(1, k1M)); }).ok);
        QVERIFY(events.isEmpty());
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncRead)
                    .isEmpty());
    }

    void aTrippedOverloadIsReportedAndRecoveredByTorqueOffAndOn()
    {
        feetech::GuardSettings off;
        off.enabled = false; // let the servo's own protection trip
        m_session->setGuardSettings(off);
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); }));
        QVERIFY(drive(simulatorValue(1, u"present_position") > 2048 ? 500 : 3500).ok);
        QTRY_VERIFY_WITH_TIMEOUT((simulatorValue(1, u"status") & 0x20) != 0, 15000);
        // The guard, on again, reports the trip from its reads.
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        m_session->setGuardSettings({});
        QVERIFY(waitFor(events, GuardCause::LatchedOverload, GuardStage::Warning));
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(0); }));
        const OperationResult recovered =
            run([&] { m_session->submit(feetech::operations::recoverOverload(m_servo, false)); });
        QVERIFY2(recovered.ok, qPrintable(recovered.message));
        QCOMPARE(recovered.failure, feetech::OperationFailure::None);
        QCOMPARE(recovered.operation, feetech::Operation::RecoverOverload);
        QCOMPARE(simulatorValue(1, u"status") & 0x20, 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        // Torque on never jumps: it holds where it stands.
        QCOMPARE(simulatorValue(1, u"goal_position"), simulatorValue(1, u"present_position"));
    }

    void aLatchedOverloadAsksForAPowerCycleAndIsClearAfterOne()
    {
        QSignalSpy events(m_session.get(), &feetech::Session::guardEvent);
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setOverloadLatched(true); }));
        QVERIFY(drive(simulatorValue(1, u"present_position")).ok); // torque on: driven, read
        QVERIFY(waitFor(events, GuardCause::LatchedOverload, GuardStage::Warning));
        const OperationResult stuck =
            run([&] { m_session->submit(feetech::operations::recoverOverload(m_servo, false)); });
        QVERIFY(!stuck.ok);
        QCOMPARE(stuck.failure, feetech::OperationFailure::StillLatched);
        QVERIFY2(stuck.message.contains(QLatin1String("power")), qPrintable(stuck.message));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0); // left as the servo really is
        // The user switches the power off and on, then asks for the check.
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->setPowered(0, false);
            simulator.feetechBus()->setPowered(0, true);
        });
        const OperationResult checked =
            run([&] { m_session->submit(feetech::operations::recoverOverload(m_servo, true)); });
        QVERIFY2(checked.ok, qPrintable(checked.message));
        QCOMPARE(checked.failure, feetech::OperationFailure::None);
        QCOMPARE(simulatorValue(1, u"status") & 0x20, 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0); // a check switches nothing on
    }
};

QTEST_GUILESS_MAIN(TestGuardSession)
#include "tst_guardsession.moc"
