// Tests of the link session: opening, closing, a lost port and its reopening, on a simulated bus.
#include "feetechbus.h"

#include "linksession.h"
#include "porttransport.h"

#include <QSignalSpy>
#include <QtTest>

using seriallink::ConnectionState;
using seriallink::Failure;
using seriallink::LinkSession;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;

} // namespace

class TestLinkSession : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    struct LinkDown
    {
        QString message;
        Failure failure = Failure::None;
    };

    feetech::FrameFormat m_format; // the link's framer keeps a reference: declared first
    std::unique_ptr<LinkSession> m_link;
    QVector<LinkDown> m_linkDowns;

    void startBus()
    {
        QString error;
        auto servos = testsupport::servosAt(k1M, {u"STS3215"});
        servos.append({2, QStringLiteral("STS3215"), k115k});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
    }

    // Sends a PING to `id` and waits up to 10 s for the engine's verdict.
    seriallink::TransactionResult ping(quint8 id)
    {
        auto result = std::make_shared<std::optional<seriallink::TransactionResult>>();
        seriallink::Transaction transaction;
        transaction.request = feetech::ping(id);
        transaction.acceptsReply = [id](const QByteArray &frame) {
            const auto packet = feetech::decodePacket(frame);
            return packet && packet->id == id;
        };
        transaction.done = [result](const seriallink::TransactionResult &r) {
            *result = r;
        };
        m_link->engine().submit(std::move(transaction));
        if (QTest::qWaitFor([&] { return result->has_value(); }, 10000))
            return **result;
        qWarning("the engine gave no verdict within 10 s");
        seriallink::TransactionResult none;
        none.failure = Failure::Timeout;
        return none;
    }

private slots:
    void init()
    {
        m_linkDowns.clear();
        startBus();
        m_link = std::make_unique<LinkSession>(
            m_format, [](const QByteArray &, const QByteArray &) { return QString(); });
        m_link->setReconnectInterval(std::chrono::milliseconds(20));
        m_link->setLinkDownHook([this](const QString &message, Failure failure) {
            m_linkDowns.append({message, failure});
        });
    }

    void cleanup()
    {
        m_link.reset();
        m_simulator.reset();
    }

    void openGivesConnectingUntilTheOwnerSaysConnected()
    {
        QSignalSpy status(m_link.get(), &LinkSession::statusChanged);
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        QVERIFY(m_link->isOpen());
        QCOMPARE(testsupport::connectionStates(status),
                 QVector<ConnectionState> {ConnectionState::Connecting});
        QCOMPARE(m_link->status().portName, m_simulator->linkPath());
        QCOMPARE(m_link->status().baud, k1M);
        QVERIFY(ping(1).ok());
        // The link itself never decides the device answers: that is the owner's word.
        QCOMPARE(m_link->status().state, ConnectionState::Connecting);
        m_link->setState(ConnectionState::Connected);
        QCOMPARE(
            testsupport::connectionStates(status),
            (QVector<ConnectionState> {ConnectionState::Connecting, ConnectionState::Connected}));
    }

    void openingAMissingPortGivesDisconnectedNamingThePort()
    {
        const QString missing = m_dir.filePath(QStringLiteral("no-such-port"));
        QSignalSpy status(m_link.get(), &LinkSession::statusChanged);
        QVERIFY(!m_link->open(missing, k1M, seriallink::EchoMode::Off));
        QVERIFY(!m_link->isOpen());
        QCOMPARE(testsupport::connectionStates(status),
                 (QVector<ConnectionState> {ConnectionState::Connecting,
                                            ConnectionState::Disconnected}));
        QCOMPARE(m_link->status().state, ConnectionState::Disconnected);
        QVERIFY2(m_link->status().message.contains(missing), qPrintable(m_link->status().message));
    }

    void closeRunsTheLinkDownHookWithCancelledAndEndsDisconnected()
    {
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        m_link->setState(ConnectionState::Connected);
        m_linkDowns.clear(); // opening ends whatever ran before it
        // A request waiting in the engine when the link closes hears that it was cancelled.
        auto ended = std::make_shared<std::optional<Failure>>();
        seriallink::Transaction waiting;
        waiting.request = feetech::ping(9); // nobody answers
        waiting.acceptsReply = [](const QByteArray &) {
            return false;
        };
        waiting.replyTimeout = std::chrono::seconds(5);
        waiting.done = [ended](const seriallink::TransactionResult &r) {
            *ended = r.failure;
        };
        m_link->engine().submit(std::move(waiting));
        const quint64 generation = m_link->generation();

        QSignalSpy status(m_link.get(), &LinkSession::statusChanged);
        m_link->close();
        QCOMPARE(m_linkDowns.size(), 1);
        QCOMPARE(m_linkDowns.first().failure, Failure::Cancelled);
        QVERIFY(ended->has_value());
        QCOMPARE(**ended, Failure::Cancelled);
        QVERIFY(!m_link->isOpen());
        QVERIFY(m_link->generation() != generation);
        QCOMPARE(testsupport::connectionStates(status),
                 QVector<ConnectionState> {ConnectionState::Disconnected});
    }

    void aLostPortRunsTheHookWithLinkDownAndIsReopenedWhenItReturns()
    {
        int reconnects = 0;
        m_link->setReconnectedHook([&reconnects] { ++reconnects; });
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        m_link->setState(ConnectionState::Connected);
        QVERIFY(ping(1).ok());
        m_linkDowns.clear();

        const sim::SimulatorOptions options = busOptions(testsupport::servosAt(k1M, {u"SCS15"}));
        m_simulator.reset(); // the adapter is pulled
        QTRY_COMPARE_WITH_TIMEOUT(m_link->status().state, ConnectionState::Lost, 10000);
        QCOMPARE(m_linkDowns.size(), 1);
        QCOMPARE(m_linkDowns.first().failure, Failure::LinkDown);
        QVERIFY2(m_link->status().message.contains(QLatin1String("Reconnecting")),
                 qPrintable(m_link->status().message));
        QVERIFY(!m_link->isOpen());
        QCOMPARE(reconnects, 0);
        const quint64 whileLost = m_link->generation();

        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(reconnects, 1, 10000);
        QVERIFY(m_link->isOpen());
        QVERIFY(m_link->generation() != whileLost);
        // With a hook, what the link is now is the owner's to say.
        QCOMPARE(m_link->status().state, ConnectionState::Lost);
        // It is the same port at the same rate, and it works: the new device answers.
        QCOMPARE(m_link->status().baud, k1M);
        QVERIFY(ping(1).ok());
    }

    void withoutAReconnectedHookAReturningPortIsConnected()
    {
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        m_link->setState(ConnectionState::Connected);
        const sim::SimulatorOptions options = busOptions(testsupport::servosAt(k1M, {u"STS3215"}));
        m_simulator.reset();
        QTRY_COMPARE_WITH_TIMEOUT(m_link->status().state, ConnectionState::Lost, 10000);
        QSignalSpy status(m_link.get(), &LinkSession::statusChanged);
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(m_link->status().state, ConnectionState::Connected, 10000);
        QCOMPARE(testsupport::connectionStates(status),
                 QVector<ConnectionState> {ConnectionState::Connected});
        QVERIFY(m_link->isOpen());
    }

    void setBaudRateChangesTheRateThePortAndStatusRunAt()
    {
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        QCOMPARE(ping(2).failure, Failure::Timeout); // servo 2 listens at 115200 only
        QVERIFY(m_link->setBaudRate(k115k));
        QCOMPARE(m_link->status().baud, k115k);
        QCOMPARE(m_link->transport().baudRate(), k115k);
        QVERIFY(ping(2).ok());
        QCOMPARE(ping(1).failure, Failure::Timeout);
    }

    void countersStartAgainAtZeroOnOpen()
    {
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        QVERIFY(ping(1).ok());
        QCOMPARE(ping(7).failure, Failure::Timeout);
        QVERIFY(m_link->counters().framesSent >= 2);
        QCOMPARE(m_link->counters().repliesOk, 1);
        QVERIFY(m_link->counters().timeouts > 0);
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        QCOMPARE(m_link->counters(), seriallink::LinkCounters {});
        QVERIFY(ping(1).ok());
        QCOMPARE(m_link->counters().repliesOk, 1);
    }

    void reopeningPublishesTheCountersItStartsFrom()
    {
        QSignalSpy published(m_link.get(), &LinkSession::countersChanged);
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        QVERIFY(ping(1).ok());
        QTRY_VERIFY_WITH_TIMEOUT(
            !published.isEmpty()
                && published.last().at(0).value<seriallink::LinkCounters>().repliesOk == 1,
            10000);
        published.clear();
        QVERIFY(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off));
        QCOMPARE(m_link->counters(), seriallink::LinkCounters {});
        // Whoever mirrors the counters (the status bar) hears that they start again.
        QVERIFY(!published.isEmpty());
        QCOMPARE(published.last().at(0).value<seriallink::LinkCounters>(),
                 seriallink::LinkCounters {});
    }
};

QTEST_GUILESS_MAIN(TestLinkSession)
#include "tst_linksession.moc"
