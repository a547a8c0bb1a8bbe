// Tests of sharing the bus through the client (ShareService and the session's share) on a
// simulated bus, with another program on the share's pseudo-terminal.
#include "feetechbus.h"
#include "programport.h"

#include "busclient.h"
#include "busoperations.h"
#include "feetechpacket.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::BusClient;
using feetech::Refusal;
using feetech::ShareService;
using testsupport::ProgramPort;

namespace {

constexpr qint32 k1M = 1000000;

QByteArray feedbackSyncRead(const QVector<quint8> &ids)
{
    const feetech::Block block = testsupport::stsFeedbackBlock();
    return feetech::syncRead(quint8(block.address), quint8(block.size), ids);
}

QByteArray feedbackRead(quint8 id)
{
    const feetech::Block block = testsupport::stsFeedbackBlock();
    return feetech::read(id, quint8(block.address), quint8(block.size));
}

// The result an operation's reply finishes with; an empty one when it did not within 10 s.
feetech::OperationResult resultOf(feetech::OperationReply *reply)
{
    if (!reply)
        return {};
    QSignalSpy finished(reply, &feetech::OperationReply::finished);
    if (!finished.wait(10000))
        return {};
    return finished.first().at(0).value<feetech::OperationResult>();
}

} // namespace

class TestShareService : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<BusClient> m_client;
    QVector<seriallink::PacketLogEntry> m_log;

    QString sharePath() const { return m_dir.filePath(QStringLiteral("program")); }

    // Shares the bus at sharePath(): whether it shares within 10 s.
    bool startSharing()
    {
        share::ShareOptions options;
        options.linkPath = sharePath();
        Refusal refusal;
        if (!m_client->share()->start(options, &refusal)) {
            qWarning("refused: %s", qPrintable(refusal.describe()));
            return false;
        }
        return QTest::qWaitFor(
            [&] { return m_client->share()->state() == ShareService::State::Sharing; }, 10000);
    }

    // The packet log's lines of the other program's frames.
    int programLines() const
    {
        return int(std::count_if(m_log.begin(), m_log.end(), [](const auto &entry) {
            return entry.summary.startsWith(QLatin1String("Other program"));
        }));
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<BusClient>(testsupport::patientTiming());
        m_log.clear();
        connect(m_client->link(), &seriallink::LinkMirror::packetLogged, this,
                [this](const seriallink::PacketLogEntry &entry) { m_log.append(entry); });
        m_client->connectTo(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->link()->isConnected(), 10000);
    }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void theProgramIsAnsweredAndShownWithoutTrafficOfOurs()
    {
        QVERIFY(startSharing());
        QCOMPARE(m_client->share()->linkPath(), sharePath());
        QVERIFY(!m_client->share()->isWatching()); // the watch reads only when asked

        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QVERIFY(program.readModel(2));
        const QVector<QByteArray> single = program.ask(feedbackRead(1), 1);
        QCOMPARE(single.size(), 1);
        QCOMPARE(feetech::decodePacket(single.first())->id, quint8(1));
        QCOMPARE(program.ask(feedbackSyncRead({1, 2}), 2).size(), 2);

        // Its servos join the servo list, with their tables.
        QTRY_COMPARE_WITH_TIMEOUT(m_client->servos()->count(), 2, 5000);
        const int index = m_client->servos()->indexOf({1, k1M});
        QVERIFY(index >= 0);
        QVERIFY(m_client->servos()->at(index).info.hasTable());

        // A subscriber (the Monitor) is fed the program's reads, and asks nothing itself.
        QObject monitor;
        QSignalSpy samples(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived);
        QVERIFY(m_client->telemetry()->subscribe(&monitor, {index}, 50.0));
        QCOMPARE(program.ask(feedbackSyncRead({1, 2}), 2).size(), 2);
        QTRY_VERIFY_WITH_TIMEOUT(!samples.isEmpty(), 5000);
        const auto batch = samples.first().at(0).value<QVector<feetech::FeedbackSample>>();
        QCOMPARE(batch.size(), 1); // only the servo asked for
        QCOMPARE(batch.first().id, quint8(1));
        QCOMPARE(batch.first().value(feetech::Quantity::Position),
                 std::optional<double>(simulatorValue(1, u"present_position")));
        QVERIFY(batch.first().value(feetech::Quantity::Voltage).has_value());
        QVERIFY(batch.first().value(feetech::Quantity::Temperature).has_value());
        QVERIFY(m_client->telemetry()->latestSample(index).has_value());
        // What it read shows in the servo's parameters as well.
        QTRY_COMPARE_WITH_TIMEOUT(
            m_client->servos()->parameters(index)->deviceValue(QStringLiteral("present_position")),
            std::optional<qint32>(simulatorValue(1, u"present_position")), 5000);

        // The packet log has the program's frames: five requests, seven answers.
        QTRY_COMPARE_WITH_TIMEOUT(programLines(), 12, 5000);
        // The wire carried the program's requests and nothing of ours.
        QTRY_COMPARE_WITH_TIMEOUT(testsupport::feetechFramesReceived(logPath()), program.requests(),
                                  5000);
        QTRY_COMPARE_WITH_TIMEOUT(m_client->share()->counters().framesFromProgram, qint64(5), 5000);
        QCOMPARE(m_client->share()->counters().unanswered, qint64(0));
        program.close();
    }

    void startIsRefusedWithItsReason()
    {
        share::ShareOptions options;
        Refusal refusal;
        QVERIFY(!m_client->share()->start(options, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::NoSharePath);

        // A path the session cannot make: it says why, and nothing shares.
        QSignalSpy failed(m_client->share(), &ShareService::startFailed);
        options.linkPath = m_dir.filePath(QStringLiteral("no-such-folder/program"));
        QVERIFY(m_client->share()->start(options, &refusal));
        QVERIFY(failed.wait(5000));
        QVERIFY(!failed.first().at(0).toString().isEmpty());
        QCOMPARE(m_client->share()->state(), ShareService::State::Off);

        QVERIFY(startSharing());
        options.linkPath = sharePath();
        QVERIFY(!m_client->share()->start(options, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::AlreadyShared);

        BusClient unconnected;
        QVERIFY(!unconnected.share()->start(options, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::NotConnected);
    }

    void whatWouldChangeTheRateIsRefusedWhileShared()
    {
        QVERIFY(startSharing());
        Refusal refusal;
        QVERIFY(!m_client->scan({}, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::BusShared);
        QVERIFY(!m_client->isScanning());
        QVERIFY(!m_client->motorSetup()->find({}, &refusal));
        QCOMPARE(refusal.code(), Refusal::Code::BusShared);

        // Submitted all the same, the session ends it unsent.
        feetech::ServoInfo servo;
        servo.id = 1;
        servo.baud = k1M;
        const feetech::OperationResult result = resultOf(m_client->submit(
            feetech::operations::changeBaud(servo, 500000), 1, k1M, BusClient::Work::Foreground));
        QCOMPARE(result.failure, feetech::OperationFailure::BusShared);
        QVERIFY(!result.ok);
        // Heard on this thread: the session's own signal comes from the link thread.
        QSignalSpy scanned(m_client.get(), &BusClient::scanFinished);
        m_client->runInSession(
            [](feetech::Session &session) { session.submit(feetech::operations::scan({})); });
        QTRY_COMPARE_WITH_TIMEOUT(scanned.count(), 1, 5000);
        QCOMPARE(scanned.first().at(0).toBool(), false);
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }

    void ownOperationsGoBetweenTheProgramsTransactions()
    {
        QVERIFY(startSharing());
        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QVERIFY(program.readModel(2));
        QTRY_COMPARE_WITH_TIMEOUT(m_client->servos()->count(), 2, 5000);
        const int index = m_client->servos()->indexOf({1, k1M});

        // The program's SYNC READ is on its way when a read of ours is asked for: whichever
        // reaches the link first, the other waits for its end.
        program.send(feedbackSyncRead({1, 2}));
        feetech::OperationReply *read = m_client->readServo(index);
        QVERIFY(read);
        QSignalSpy readFinished(read, &feetech::OperationReply::finished);
        QCOMPARE(program.collect(2).size(), 2);
        QVERIFY(!readFinished.isEmpty() || readFinished.wait(10000));
        const auto result = readFinished.first().at(0).value<feetech::OperationResult>();
        QVERIFY2(result.ok, qPrintable(result.message));
        QVERIFY(program.readModel(1));

        // Nothing collided: every frame the servos heard is whole, and every answer reached the
        // one that asked.
        const QVector<QByteArray> heard = testsupport::feetechFramesReceived(logPath());
        QCOMPARE(testsupport::feetechPacketsReceived(logPath()).size(), heard.size());
        QCOMPARE(m_client->servos()->at(index).read, true);
        QTRY_COMPARE_WITH_TIMEOUT(m_client->share()->counters().unanswered, qint64(0), 5000);
        program.close();
    }

    void allTorqueOffGoesBetweenTheProgramsTransactions()
    {
        QVERIFY(startSharing());
        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QVERIFY(program.readModel(2));
        QTRY_COMPARE_WITH_TIMEOUT(m_client->servos()->count(), 2, 5000);
        QVERIFY(withServo(
            1, k1M, [](sim::VirtualFeetechServo &servo) { servo.setValue(u"torque_enable", 1); }));

        program.send(feedbackSyncRead({1, 2}));
        feetech::OperationReply *torqueOff = m_client->allTorqueOff();
        QVERIFY(torqueOff);
        QSignalSpy finished(torqueOff, &feetech::OperationReply::finished);
        QCOMPARE(program.collect(2).size(), 2);
        QVERIFY(!finished.isEmpty() || finished.wait(10000));
        const auto result = finished.first().at(0).value<feetech::OperationResult>();
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        // The program goes on as before.
        QVERIFY(program.readModel(1));

        const QVector<QByteArray> heard = testsupport::feetechFramesReceived(logPath());
        QCOMPARE(testsupport::feetechPacketsReceived(logPath()).size(), heard.size());
        QCOMPARE(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write,
                                                      feetech::kBroadcastId)
                     .size(),
                 1);
        program.close();
    }

    void theWatchReadsOnlyOnceAsked()
    {
        QVERIFY(startSharing());
        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QTRY_COMPARE_WITH_TIMEOUT(m_client->servos()->count(), 1, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(testsupport::feetechFramesReceived(logPath()).size(), 1, 5000);

        // In the program's idle gaps it reads the servo the program uses, one READ at a time.
        m_client->share()->setWatch(true);
        QVERIFY(m_client->share()->isWatching());
        QTRY_VERIFY_WITH_TIMEOUT(m_client->share()->watchReads() > 0, 5000);
        QVERIFY(!testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Read, 1)
                     .isEmpty());
        // The program is answered as before.
        QVERIFY(program.readModel(1));
        program.close();
    }

    void reconnectingEndsTheShare()
    {
        QVERIFY(startSharing());
        m_client->connectTo(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        QTRY_COMPARE_WITH_TIMEOUT(m_client->share()->state(), ShareService::State::Off, 10000);
        QVERIFY(!QFileInfo::exists(sharePath()));
    }

    void stopSharingGivesTheBusBack()
    {
        QVERIFY(startSharing());
        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QTRY_COMPARE_WITH_TIMEOUT(m_client->servos()->count(), 1, 5000);
        QObject monitor;
        QVERIFY(m_client->telemetry()->subscribe(&monitor, {0}, 50.0));
        program.close();

        QSignalSpy samples(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived);
        m_client->share()->stop();
        QTRY_COMPARE_WITH_TIMEOUT(m_client->share()->state(), ShareService::State::Off, 10000);
        QVERIFY(!QFileInfo::exists(sharePath()));

        // The stream waited while shared: now it reads the servo itself.
        QVERIFY(samples.wait(5000));
        QVERIFY(!testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncRead)
                     .isEmpty());
        m_client->telemetry()->unsubscribe(&monitor);
        const feetech::OperationResult pinged = resultOf(m_client->submit(
            feetech::operations::ping(1, k1M), 1, k1M, BusClient::Work::Foreground));
        QVERIFY2(pinged.ok, qPrintable(pinged.message));
        Refusal refusal;
        QVERIFY(m_client->scan({}, &refusal));
    }

    void disconnectingEndsTheShare()
    {
        QVERIFY(startSharing());
        m_client->disconnectFrom();
        QTRY_COMPARE_WITH_TIMEOUT(m_client->share()->state(), ShareService::State::Off, 10000);
        QVERIFY(!QFileInfo::exists(sharePath()));
    }
};

QTEST_MAIN(TestShareService)
#include "tst_shareservice.moc"
