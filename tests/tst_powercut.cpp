// End-to-end tests of power lost in the middle of an EEPROM write (servosim's power-cut bench
// case): the EEPROM keeps the old or the new value, never a mix, the write is never reported
// done, and a servo left unlocked is noticed and locked on request (BusClient and servoctl).
#include "busclient.h"
#include "feetechbus.h"
#include "operationlog.h"
#include "servoctlrun.h"
#include "simcommands.h"

#include <QtTest>

using testsupport::FeetechBusTest;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 kOldLimit = 4095;
constexpr qint32 kNewLimit = 3000; // two bytes on the wire: a mix would be neither value

} // namespace

class TestPowerCut : public FeetechBusTest
{
    Q_OBJECT

private:
    // Arms the cut, writes max_angle_limit through BusClient, gives power back: the outcome.
    std::optional<feetech::OperationResult> writeThroughCut(const QString &when)
    {
        feetech::BusClient client(testsupport::patientTiming());
        const int index = testsupport::connectScanAndRead(client, m_simulator->linkPath(), 2, 1);
        if (index < 0)
            return std::nullopt;
        QString reply;
        m_simulator->call([&](sim::Simulator &simulator) {
            reply = sim::runSimulatorCommand(QStringLiteral("power-cut 1 ") + when, simulator);
        });
        if (!reply.startsWith(QStringLiteral("ok")))
            return std::nullopt;
        model::ParameterModel *model = client.servos()->parameters(index);
        if (!model->edit(QStringLiteral("max_angle_limit"), kNewLimit))
            return std::nullopt;
        OperationLog finishedLog(&client);
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        if (!client.apply(index) || !finished.wait(30000))
            return std::nullopt;
        m_simulator->call([&](sim::Simulator &simulator) {
            sim::runSimulatorCommand(QStringLiteral("power 1 on"), simulator);
        });
        return finished.last().first().value<feetech::OperationResult>();
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
    }
    void cleanup() { m_simulator.reset(); }

    void aCutBetweenUnlockAndWriteKeepsTheOldValue()
    {
        const auto result = writeThroughCut(QStringLiteral("after-unlock"));
        QVERIFY(result);
        QVERIFY(!result->ok);
        QCOMPARE(result->failure, feetech::OperationFailure::NoAnswer);
        QVERIFY2(result->message.contains(QStringLiteral("may be left open")),
                 qPrintable(result->message));
        QCOMPARE(simulatorValue(1, u"max_angle_limit"), kOldLimit);
        QCOMPARE(simulatorValue(1, u"lock"), 1); // the servo powers up locked
    }

    void aCutBetweenWriteAndLockKeepsTheNewValue()
    {
        const auto result = writeThroughCut(QStringLiteral("after-write"));
        QVERIFY(result);
        QVERIFY(!result->ok); // its read-back and the relock found no power: never "done"
        QCOMPARE(simulatorValue(1, u"max_angle_limit"), kNewLimit);
        QCOMPARE(simulatorValue(1, u"lock"), 1);
    }

    void aServoLeftUnlockedIsNoticedAndLockedOnRequest()
    {
        setSimulatorValue(1, u"lock", 0); // the host went away between write and lock
        feetech::BusClient client(testsupport::patientTiming());
        const int index = testsupport::connectScanAndRead(client, m_simulator->linkPath(), 2, 1);
        QVERIFY(index >= 0);
        QVERIFY(client.servos()->eepromUnlocked(index));
        QCOMPARE(simulatorValue(1, u"lock"), 0); // noticing writes nothing
        OperationLog finishedLog(&client);
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        feetech::Refusal refusal;
        QVERIFY2(client.commands()->lockEeprom(index, &refusal), qPrintable(refusal.describe()));
        QVERIFY(finished.wait(10000));
        const auto result = finished.last().first().value<feetech::OperationResult>();
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(simulatorValue(1, u"lock"), 1);
        QVERIFY(!client.servos()->eepromUnlocked(index)); // the read-back says so too
    }

    void servoctlLocksAServoLeftUnlocked()
    {
        setSimulatorValue(1, u"lock", 0);
        const auto result = testsupport::runServoctl(
            {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("feetech"),
             QStringLiteral("lock"), QStringLiteral("--id"), QStringLiteral("1")});
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(result.err.contains(QStringLiteral("servoctl feetech lock --id 1")),
                 qPrintable(result.err));
        QVERIFY2(result.out.contains(QStringLiteral("locked (read back)")), qPrintable(result.out));
        QCOMPARE(simulatorValue(1, u"lock"), 1);
    }

    void thePowerCutCommandNamesWhen()
    {
        QString reply;
        m_simulator->call([&](sim::Simulator &simulator) {
            reply = sim::runSimulatorCommand(QStringLiteral("power-cut 1 sideways"), simulator);
        });
        QVERIFY2(reply.startsWith(QStringLiteral("error power-cut takes")), qPrintable(reply));
        m_simulator->call([&](sim::Simulator &simulator) {
            reply = sim::runSimulatorCommand(QStringLiteral("power-cut 9 after-write"), simulator);
        });
        QVERIFY2(reply.startsWith(QStringLiteral("error")), qPrintable(reply));
    }
};

QTEST_MAIN(TestPowerCut)
#include "tst_powercut.moc"
