// Tests of the servo commands that are no register edits: what each sends, and what it refuses.
#include "feetechbus.h"

#include "busclient.h"
#include "feetechpacket.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::BusClient;
using feetech::Instruction;
using feetech::OperationResult;
using feetech::Refusal;
using feetech::ServoCommands;

namespace {

constexpr qint32 k1M = 1000000;

// The result `reply` finished with; an empty one when there is none or it took over 10 s.
OperationResult resultOf(feetech::OperationReply *reply)
{
    if (!reply)
        return {};
    QSignalSpy finished(reply, &feetech::OperationReply::finished);
    if (!finished.wait(10000))
        return {};
    return finished.first().at(0).value<OperationResult>();
}

} // namespace

class TestServoCommands : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<BusClient> m_client;

    ServoCommands *commands() const { return m_client->commands(); }

    // Adds what a scan lists for two servos answering at `id`; its index.
    int addSharedId(quint8 id)
    {
        feetech::ServoInfo shared = m_client->servos()->at(0).info;
        shared.id = id;
        shared.sharedId = true;
        m_client->servos()->add(shared);
        return m_client->servos()->indexOf({id, k1M});
    }

    // Adds what a scan lists for a servo of a model it does not know; its index.
    int addUnknownModel(quint8 id)
    {
        feetech::ServoInfo unknown;
        unknown.id = id;
        unknown.baud = k1M;
        m_client->servos()->add(unknown);
        return m_client->servos()->indexOf({id, k1M});
    }

    // Every instruction packet the bus received other than the scan's and reads' ones.
    int commandsReceived() const
    {
        int count = 0;
        for (const Instruction code : {Instruction::Write, Instruction::Reboot, Instruction::Reset,
                                       Instruction::Calibrate, Instruction::Recovery})
            count += int(testsupport::feetechRequestsReceived(logPath(), code).size());
        return count;
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<BusClient>(testsupport::patientTiming());
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 3));
        QCOMPARE(m_client->servos()->count(), 2);
    }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
    }

    void clearStatusSendsOneResetToThatServoOnly()
    {
        const int index = m_client->servos()->indexOf({2, k1M});
        Refusal refusal;
        const OperationResult result = resultOf(commands()->clearStatus(index, &refusal));
        QVERIFY2(refusal.describe().isEmpty(), qPrintable(refusal.describe()));
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.operation, feetech::Operation::ClearStatus);
        QTRY_COMPARE(
            int(testsupport::feetechRequestsReceived(logPath(), Instruction::Reset, 2).size()), 1);
        QCOMPARE(int(testsupport::feetechRequestsReceived(logPath(), Instruction::Reset).size()),
                 1);
    }

    void aSharedIdIsSentNoCommand()
    {
        const int shared = addSharedId(7);
        QCOMPARE(commands()->blocker(shared).code(), Refusal::Code::SharedId);
        Refusal refusal;
        QVERIFY(!commands()->reboot(shared, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::SharedId);
        QVERIFY2(refusal.describe().contains(QLatin1String("ID 7")),
                 qPrintable(refusal.describe()));
        refusal = {};
        QVERIFY(!commands()->clearStatus(shared, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::SharedId);
        refusal = {};
        QVERIFY(!commands()->calibrateMiddle(shared, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::SharedId);
        refusal = {};
        QVERIFY(!commands()->factoryReset(shared, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::SharedId);
        QCOMPARE(commandsReceived(), 0);
    }

    void anUnknownModelIsNeitherCalibratedNorReset()
    {
        const int unknown = addUnknownModel(8);
        QVERIFY(!commands()->blocker(unknown)); // a reboot or a clear needs no register table
        Refusal refusal;
        QVERIFY(!commands()->calibrateMiddle(unknown, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::UnknownModel);
        refusal = {};
        QVERIFY(!commands()->factoryReset(unknown, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::UnknownModel);
        QCOMPARE(commandsReceived(), 0);
    }

    void clearStatusWaitsForAnIdleBus()
    {
        QVERIFY(m_client->readServo(0));
        QVERIFY(m_client->isBusy());
        Refusal refusal;
        QVERIFY(!commands()->clearStatus(0, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::Busy);
        QVERIFY(!refusal.describe().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(!m_client->isBusy(), 10000);
        QVERIFY(resultOf(commands()->clearStatus(0)).ok);
    }
};

QTEST_GUILESS_MAIN(TestServoCommands)
#include "tst_servocommands.moc"
