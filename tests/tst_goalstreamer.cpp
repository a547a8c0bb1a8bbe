// Tests of GoalStreamer against a simulated servo: a burst of goals keeps one write on the wire
// and ends at the newest goal; a failing write drops the goal waiting behind it.
#include "feetechbus.h"

#include "busclient.h"
#include "goalstreamer.h"
#include "operationreply.h"

#include <QSignalSpy>
#include <QtTest>

#include <algorithm>

using feetech::BusClient;
using feetech::GoalStreamer;

namespace {

constexpr qint32 k1M = 1000000;
const QString kGoalPosition = QStringLiteral("goal_position");

} // namespace

class TestGoalStreamer : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<BusClient> m_client;
    std::unique_ptr<GoalStreamer> m_streamer;
    int m_mostInFlight = 0;

    // Sends `goal` to servo ID 1 as the Control page's slider does: at once, or queued behind
    // the write on the wire.
    void offer(qint32 goal)
    {
        if (!m_streamer->queueIfBusy(goal))
            send(goal);
    }

    void send(qint32 goal)
    {
        feetech::Refusal refusal;
        QVERIFY2(m_streamer->send(0, {{kGoalPosition, goal}}, &refusal),
                 qPrintable(refusal.describe()));
        m_mostInFlight = std::max(m_mostInFlight, m_streamer->writesInFlight());
    }

    // The goal position writes servo ID 1 received.
    int goalWritesReceived() const
    {
        const int address = m_client->servos()->at(0).info.table().find(kGoalPosition)->address;
        const auto writes =
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write, 1);
        return int(std::count_if(writes.cbegin(), writes.cend(), [address](const auto &write) {
            return quint8(write.parameters.at(0)) == address;
        }));
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
        m_client = std::make_unique<BusClient>(testsupport::patientTiming());
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 3));
        QCOMPARE(m_client->servos()->count(), 1);
        m_streamer = std::make_unique<GoalStreamer>(m_client.get());
        connect(m_streamer.get(), &GoalStreamer::queuedGoalDue, this,
                [this](qint32 goal) { send(goal); });
        m_mostInFlight = 0;
    }

    void cleanup()
    {
        m_streamer.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void aBurstOfGoalsKeepsOneWriteInFlightAndEndsAtTheNewest()
    {
        QSignalSpy submitted(m_client.get(), &BusClient::submitted);
        for (qint32 goal = 1000; goal <= 2000; goal += 100)
            offer(goal);
        QCOMPARE(m_streamer->writesInFlight(), 1);
        QCOMPARE(m_streamer->queuedGoal(), std::optional<qint32>(2000));

        QTRY_VERIFY_WITH_TIMEOUT(m_streamer->writesInFlight() == 0 && !m_streamer->queuedGoal(),
                                 10000);
        QCOMPARE(m_mostInFlight, 1);
        QCOMPARE(simulatorValue(1, kGoalPosition), 2000);
        // The first goal and the newest: the ones between were replaced while they waited.
        QCOMPARE(submitted.size(), 2);
        QCOMPARE(goalWritesReceived(), 2);
    }

    void aFailingWriteDropsTheQueuedGoal()
    {
        const qint32 before = simulatorValue(1, kGoalPosition);
        setSimulatorValue(1, u"id", 22); // servo 1 goes silent: its writes fail
        QSignalSpy due(m_streamer.get(), &GoalStreamer::queuedGoalDue);
        feetech::Refusal refusal;
        feetech::OperationReply *reply = m_streamer->send(0, {{kGoalPosition, 1000}}, &refusal);
        QVERIFY2(reply, qPrintable(refusal.describe()));
        QSignalSpy finished(reply, &feetech::OperationReply::finished);
        QVERIFY(m_streamer->queueIfBusy(2000));

        QVERIFY(finished.wait(10000));
        QVERIFY(!finished.first().at(0).value<feetech::OperationResult>().ok);
        QCOMPARE(m_streamer->writesInFlight(), 0);
        QVERIFY(!m_streamer->queuedGoal());
        QVERIFY(due.isEmpty());
        QCOMPARE(simulatorValue(22, kGoalPosition), before);
    }

    void aWriteUnansweredPastTheStaleTimeLetsTheNextGoalOut()
    {
        m_streamer->setStaleMs(0);
        offer(1500);
        QCOMPARE(m_streamer->writesInFlight(), 1);
        QVERIFY(!m_streamer->queueIfBusy(1600));
        QVERIFY(!m_streamer->queuedGoal());
        QTRY_COMPARE_WITH_TIMEOUT(m_streamer->writesInFlight(), 0, 10000);
    }
};

QTEST_GUILESS_MAIN(TestGoalStreamer)
#include "tst_goalstreamer.moc"
