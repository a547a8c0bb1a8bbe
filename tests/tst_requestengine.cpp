// Unit tests of the request engine over a scripted transport: ordering, timeouts, retries, echo.
#include "ptkframe.h"
#include "requestengine.h"
#include "serialtransport.h"

#include <QtTest>

using seriallink::EchoMode;
using seriallink::Failure;
using seriallink::RequestEngine;
using seriallink::Transaction;
using seriallink::TransactionResult;

namespace {

// Records what is written and answers each write with what the test queued for it.
class ScriptedTransport final : public seriallink::Transport
{
public:
    bool open = true;
    bool echo = false;
    qint32 baud = 115200;
    QVector<QByteArray> written;
    QVector<QByteArray> answers; // one per write, in order; empty: silence
    QByteArray pendingInput; // what discardInput() finds
    // The answer comes 2 ms after the write and before the port says the write has left (a
    // device that answers at once, behind a busy event loop).
    bool answerBeforeConfirming = false;

    bool isOpen() const override { return open; }
    qint32 baudRate() const override { return baud; }
    void write(const QByteArray &bytes) override
    {
        written.append(bytes);
        const QByteArray answer = answers.isEmpty() ? QByteArray() : answers.takeFirst();
        if (answerBeforeConfirming) {
            QTimer::singleShot(2, this, [this, bytes, answer] {
                emit received(answer);
                emit bytesWritten(bytes.size());
            });
            return;
        }
        QTimer::singleShot(0, this, [this, bytes, answer] {
            emit bytesWritten(bytes.size());
            if (echo)
                emit received(bytes);
            if (!answer.isEmpty())
                emit received(answer);
        });
    }
    QByteArray discardInput() override { return std::exchange(pendingInput, {}); }
    void deliver(const QByteArray &bytes) { emit received(bytes); }
};

// A result that reads as failed until a transaction writes over it.
TransactionResult unfinished()
{
    TransactionResult result;
    result.failure = Failure::Cancelled;
    return result;
}

QByteArray reply(quint16 word0)
{
    return ptk::encodeReply({word0, 0});
}

Transaction query(quint8 command, Transaction::Priority priority, QVector<QString> *order,
                  TransactionResult *result = nullptr)
{
    Transaction transaction;
    transaction.request = ptk::encodeQuery(command);
    transaction.priority = priority;
    transaction.expectedReplySize = ptk::kReplySize;
    transaction.acceptsReply = [](const QByteArray &frame) {
        return frame.size() == ptk::kReplySize;
    };
    transaction.done = [order, result, command](const TransactionResult &outcome) {
        if (order)
            order->append(QString::number(command));
        if (result)
            *result = outcome;
    };
    return transaction;
}

// A PTK write frame (nothing answers it) whose outcome lands in *result.
Transaction noReplyWrite(quint16 gain, TransactionResult *result)
{
    Transaction write;
    write.request = ptk::encodeRequest({1, gain, 0});
    write.done = [result](const TransactionResult &outcome) {
        *result = outcome;
    };
    return write;
}

// A scan's PING: 300 µs for the first byte of the answer, then all the time it needs.
Transaction firstByteQuery(QVector<QString> *order, TransactionResult *result)
{
    Transaction transaction = query(0x38, Transaction::Priority::Command, order, result);
    transaction.replyTimeout = std::chrono::microseconds(300);
    transaction.afterFirstByte = std::chrono::seconds(30);
    transaction.retryCount = 0;
    return transaction;
}

} // namespace

class TestRequestEngine : public QObject
{
    Q_OBJECT

private:
    ptk::FrameFormat m_format;

    std::unique_ptr<RequestEngine> engine(ScriptedTransport &transport)
    {
        auto result = std::make_unique<RequestEngine>(transport, m_format, nullptr);
        seriallink::EngineTiming timing;
        timing.replyTimeout = std::chrono::milliseconds(5);
        timing.retryCount = 2;
        result->setTiming(timing);
        return result;
    }

    // At 9600 bps a query and its reply take 19.8 ms on the wire: an answer the transport hands
    // over at once is unmistakably sooner than the wire allows, one 60 ms later is not, however
    // slow the machine (a sanitizer build) is.
    std::unique_ptr<RequestEngine> engineAt9600(ScriptedTransport &transport)
    {
        transport.baud = 9600;
        return engine(transport);
    }

private slots:
    void theSlowEndIsTheNinetyFifthPercentileInAnyOrder()
    {
        QCOMPARE(seriallink::slowEnd({}), std::nullopt);
        std::deque<std::chrono::microseconds> times;
        for (int i = 100; i >= 1; --i) // 100, 99, ... 1, interleaved front and back
            i % 2 ? times.push_back(std::chrono::microseconds(i))
                  : times.push_front(std::chrono::microseconds(i));
        QCOMPARE(seriallink::slowEnd(times), std::chrono::microseconds(95));
        QCOMPARE(seriallink::slowEnd({std::chrono::microseconds(7)}), std::chrono::microseconds(7));
    }

    void anAnswerBeforeTheWriteIsConfirmedCountsItsLatencyFromTheWrite()
    {
        ScriptedTransport transport;
        transport.answerBeforeConfirming = true;
        transport.answers = {reply(1), reply(2)};
        auto subject = engine(transport);
        for (quint8 command : {0x38, 0x39}) {
            // Long enough that a latency counted from the engine's start or from the request
            // before would show it.
            QTest::qWait(300);
            TransactionResult result = unfinished();
            subject->submit(query(command, Transaction::Priority::Command, nullptr, &result));
            QTRY_COMPARE(result.failure, Failure::None);
            // 2 ms after the write, less the wire time of an echo not yet ruled out (0.9 ms).
            QVERIFY2(result.latency >= std::chrono::microseconds(500)
                         && result.latency < std::chrono::milliseconds(250),
                     qPrintable(QString::number(result.latency.count())));
        }
    }

    void commandsGoBeforeQueuedPolls()
    {
        ScriptedTransport transport;
        transport.answers = {reply(1), reply(2), reply(3), reply(4)};
        auto requests = engine(transport);
        QVector<QString> order;
        requests->submit(query(0x38, Transaction::Priority::Poll, &order));
        requests->submit(query(0x3D, Transaction::Priority::Poll, &order));
        requests->submit(query(0x01, Transaction::Priority::Command, &order));
        requests->submit(query(0x05, Transaction::Priority::Command, &order));
        QTRY_COMPARE(order.size(), 4);
        QCOMPARE(order,
                 (QVector<QString> {QStringLiteral("1"), QStringLiteral("5"), QStringLiteral("56"),
                                    QStringLiteral("61")}));
    }

    void onlyOneTransactionIsInFlight()
    {
        ScriptedTransport transport; // silent: every query times out
        auto requests = engine(transport);
        QVector<QString> order;
        requests->submit(query(0x38, Transaction::Priority::Poll, &order));
        requests->submit(query(0x3D, Transaction::Priority::Poll, &order));
        QTRY_COMPARE(transport.written.size(), 1 + 0); // the first goes out alone
        QCOMPARE(order.size(), 0);
        QTRY_COMPARE(order.size(), 2);
        // Three tries each, never interleaved.
        QCOMPARE(transport.written.size(), 6);
        for (int i = 0; i < 3; ++i)
            QCOMPARE(transport.written.at(i), ptk::encodeQuery(0x38));
    }

    void aMissingReplyIsRetriedThenReportedAsATimeout()
    {
        ScriptedTransport transport;
        transport.answers = {QByteArray(), QByteArray(), QByteArray()};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        QVector<QString> order;
        requests->submit(query(0x38, Transaction::Priority::Command, &order, &result));
        QTRY_COMPARE(order.size(), 1);
        QCOMPARE(result.failure, Failure::Timeout);
        QCOMPARE(result.attempts, 3);
        QCOMPARE(requests->counters().timeouts, 3);
        QCOMPARE(requests->counters().retries, 2);
        QCOMPARE(requests->counters().failures, 1);
    }

    void eachCountedTimeoutIsAnErrorInThePacketLog()
    {
        ScriptedTransport transport; // silent
        auto requests = engine(transport);
        QSignalSpy logged(requests.get(), &RequestEngine::packetLogged);
        TransactionResult result = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Poll, nullptr, &result));
        QTRY_COMPARE(result.failure, Failure::Timeout);
        int errors = 0;
        for (const QVariantList &arguments : std::as_const(logged))
            errors += arguments.first().value<seriallink::PacketLogEntry>().error.isEmpty() ? 0 : 1;
        // The log's error count and the status bar's timeouts are one account.
        QCOMPARE(errors, 3);
        QCOMPARE(requests->counters().timeouts, 3);
    }

    void aSilenceAskedForCountsNoTimeoutNorRetryAndIsLoggedAsANote()
    {
        ScriptedTransport transport; // silent: the ID asked about is free
        auto requests = engine(transport);
        QSignalSpy logged(requests.get(), &RequestEngine::packetLogged);
        TransactionResult result = unfinished();
        Transaction ask = query(0x38, Transaction::Priority::Command, nullptr, &result);
        ask.silenceExpected = true;
        ask.retryCount = 1;
        requests->submit(std::move(ask));
        QTRY_COMPARE(result.failure, Failure::Timeout);
        QCOMPARE(transport.written.size(), 2); // retried all the same
        QCOMPARE(requests->counters().timeouts, 0);
        QCOMPARE(requests->counters().retries, 0);
        QCOMPARE(requests->counters().failures, 0);
        QCOMPARE(logged.size(), 4); // two requests, two notes
        int notes = 0;
        for (const QVariantList &arguments : std::as_const(logged)) {
            const auto entry = arguments.first().value<seriallink::PacketLogEntry>();
            QVERIFY2(entry.error.isEmpty(), qPrintable(entry.error));
            // The note says why a missing reply is no error here.
            notes += entry.summary.contains(QLatin1String("silence was expected")) ? 1 : 0;
        }
        QCOMPARE(notes, 2);
    }

    void whatABroadcastListensForIsNeitherDiscardedNorAnError()
    {
        // Several servos answer a broadcast at once: whole answers and garbled bytes both.
        ScriptedTransport transport;
        transport.answers = {reply(1) + QByteArray("\x01\x02\x03", 3)};
        auto requests = engine(transport);
        QSignalSpy logged(requests.get(), &RequestEngine::packetLogged);
        TransactionResult result = unfinished();
        Transaction listen = query(0x38, Transaction::Priority::Command, nullptr, &result);
        listen.acceptsReply = [](const QByteArray &) {
            return false;
        };
        listen.silenceExpected = true;
        listen.collisionsExpected = true;
        listen.retryCount = 0;
        requests->submit(std::move(listen));
        QTRY_COMPARE(result.failure, Failure::Timeout);
        QCOMPARE(requests->counters().discardedBytes, 0);
        QCOMPARE(requests->counters().timeouts, 0);
        QVERIFY(logged.size() >= 3); // the request, the answer, the garbled bytes
        for (const QVariantList &arguments : std::as_const(logged)) {
            const auto entry = arguments.first().value<seriallink::PacketLogEntry>();
            QVERIFY2(entry.error.isEmpty(), qPrintable(entry.error));
        }
    }

    void aReplyOnTheSecondTryIsAccepted()
    {
        ScriptedTransport transport;
        transport.answers = {QByteArray(), reply(42)};
        auto requests = engine(transport);
        // The second try's answer comes at once, which on a link not yet known to answer at
        // once passes for the first try's late answer: the wire rule is not what this tests.
        seriallink::EngineTiming timing = requests->timing();
        timing.discardImpossiblyEarlyAnswers = false;
        requests->setTiming(timing);
        TransactionResult result = unfinished();
        QVector<QString> order;
        requests->submit(query(0x38, Transaction::Priority::Command, &order, &result));
        QTRY_COMPARE(order.size(), 1);
        QVERIFY(result.ok());
        QCOMPARE(result.attempts, 2);
        QCOMPARE(ptk::decodeReply(result.reply)->word0, quint16(42));
    }

    void anAnswerSoonerThanTheWireAllowsIsTheLateOneAnEarlierQueryIsOwed()
    {
        // The first query is not answered in time; its late reply lands just after the next
        // query went out, whose real answer comes once query and answer have crossed the wire.
        ScriptedTransport transport;
        transport.answers = {QByteArray(), reply(7)};
        auto requests = engineAt9600(transport);
        seriallink::EngineTiming timing = requests->timing();
        timing.retryCount = 0;
        requests->setTiming(timing);
        TransactionResult first = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &first));
        QTRY_COMPARE(first.failure, Failure::Timeout);
        timing.replyTimeout = std::chrono::milliseconds(2000);
        requests->setTiming(timing);
        TransactionResult result = unfinished();
        requests->submit(query(0x3D, Transaction::Priority::Command, nullptr, &result));
        QTRY_COMPARE(transport.written.size(), 2);
        QTimer::singleShot(60, Qt::PreciseTimer, &transport,
                           [&transport] { transport.deliver(reply(8)); });
        QTRY_VERIFY(result.ok());
        QCOMPARE(ptk::decodeReply(result.reply)->word0, quint16(8));
        QCOMPARE(result.attempts, 1);
        QCOMPARE(requests->counters().lateReplies, 1);
        QCOMPARE(requests->counters().discardedBytes, ptk::kReplySize);
    }

    void anAnswerAtOnceIsTheAnswerWhenNothingIsOwed()
    {
        // A virtual port or an emulator answers the moment it has the query.
        ScriptedTransport transport;
        transport.answers = {reply(7)};
        auto requests = engineAt9600(transport);
        TransactionResult result = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &result));
        QTRY_VERIFY(result.ok());
        QCOMPARE(ptk::decodeReply(result.reply)->word0, quint16(7));
        QCOMPARE(result.attempts, 1);
        QCOMPARE(requests->counters().lateReplies, 0);
        QCOMPARE(requests->counters().discardedBytes, 0);
    }

    void aQueryThatFailedAfterTakingALateAnswerStillOwesItsOwn()
    {
        // Q1's first try goes unanswered; its late answer lands at once on the retry and is
        // taken for it; the retry's own answer comes late, just after Q2 went out. It must not
        // pass for Q2's (PTK replies name no query), nor mislead the engine into treating the
        // link as one that answers at once.
        ScriptedTransport transport;
        transport.answers = {QByteArray(), reply(1), reply(2)};
        auto requests = engineAt9600(transport);
        seriallink::EngineTiming timing = requests->timing();
        timing.retryCount = 1;
        requests->setTiming(timing);
        TransactionResult first = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &first));
        QTRY_COMPARE(first.failure, Failure::Timeout);
        timing.replyTimeout = std::chrono::milliseconds(2000); // for the real answer
        requests->setTiming(timing);
        TransactionResult second = unfinished();
        requests->submit(query(0x3D, Transaction::Priority::Command, nullptr, &second));
        QTRY_COMPARE(transport.written.size(), 3);
        QTimer::singleShot(60, Qt::PreciseTimer, &transport,
                           [&transport] { transport.deliver(reply(3)); });
        QTRY_COMPARE(second.failure, Failure::None);
        QCOMPARE(ptk::decodeReply(second.reply)->word0, quint16(3));
        // And so again later: a query that goes unanswered owes its late answer.
        timing.retryCount = 0;
        timing.replyTimeout = std::chrono::milliseconds(5);
        requests->setTiming(timing);
        transport.answers = {QByteArray(), reply(4)};
        TransactionResult third = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &third));
        QTRY_COMPARE(third.failure, Failure::Timeout);
        timing.replyTimeout = std::chrono::milliseconds(2000);
        requests->setTiming(timing);
        TransactionResult fourth = unfinished();
        requests->submit(query(0x3D, Transaction::Priority::Command, nullptr, &fourth));
        QTRY_COMPARE(transport.written.size(), 5);
        QTimer::singleShot(60, Qt::PreciseTimer, &transport,
                           [&transport] { transport.deliver(reply(5)); });
        QTRY_COMPARE(fourth.failure, Failure::None);
        QCOMPARE(ptk::decodeReply(fourth.reply)->word0, quint16(5));
    }

    void aLinkThatAnswersAtOnceIsHeardAgainAfterAMissedQuery()
    {
        // Once the link has answered at once, a query it missed is not answered late: the
        // retry's answer, at once too, is taken.
        ScriptedTransport transport;
        transport.answers = {reply(1), QByteArray(), reply(2)};
        auto requests = engineAt9600(transport);
        TransactionResult first = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &first));
        QTRY_VERIFY(first.ok());
        TransactionResult second = unfinished();
        requests->submit(query(0x3D, Transaction::Priority::Command, nullptr, &second));
        QTRY_COMPARE(second.failure, Failure::None);
        QCOMPARE(second.attempts, 2);
        QCOMPARE(ptk::decodeReply(second.reply)->word0, quint16(2));
    }

    void anEchoAloneStartsNoFirstByteDeadline()
    {
        // A scan's wait for the first byte of an answer: the adapter's echo, come on its own,
        // is no answer begun, and the answer that follows it in time is heard.
        ScriptedTransport transport;
        transport.echo = true;
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        Transaction transaction = query(0x38, Transaction::Priority::Command, nullptr, &result);
        transaction.replyTimeout = std::chrono::milliseconds(2000);
        transaction.afterFirstByte = std::chrono::microseconds(1);
        transaction.retryCount = 0;
        requests->submit(std::move(transaction));
        QTRY_VERIFY(!transport.written.isEmpty());
        QTimer::singleShot(20, Qt::PreciseTimer, &transport,
                           [&transport] { transport.deliver(reply(5)); });
        QTRY_COMPARE(result.failure, Failure::None);
        QCOMPARE(ptk::decodeReply(result.reply)->word0, quint16(5));
    }

    void aGarbledAnswerOwesNothing()
    {
        // The servo answered (garbled); the retry's answer at once is no late one.
        ScriptedTransport transport;
        transport.answers = {QByteArray::fromHex("aa55"), reply(3)};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &result));
        QTRY_COMPARE(result.failure, Failure::None);
        QCOMPARE(result.attempts, 2);
        QCOMPARE(ptk::decodeReply(result.reply)->word0, quint16(3));
    }

    void strayInputIsDiscardedBeforeEachRequest()
    {
        ScriptedTransport transport;
        transport.pendingInput = reply(7); // a late reply of an earlier exchange
        transport.answers = {reply(8)};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &result));
        QTRY_VERIFY(result.ok());
        QCOMPARE(ptk::decodeReply(result.reply)->word0, quint16(8));
        QCOMPARE(requests->counters().discardedBytes, ptk::kReplySize);
    }

    void bytesWhileIdleAreCountedAsStrayAndNeverAnswerTheNextRequest()
    {
        ScriptedTransport transport;
        auto requests = engine(transport);
        QSignalSpy log(requests.get(), &RequestEngine::packetLogged);
        transport.deliver(reply(9));
        QCOMPARE(requests->counters().discardedBytes, ptk::kReplySize);
        QCOMPARE(log.size(), 1);
        QCOMPARE(log.first().first().value<seriallink::PacketLogEntry>().direction,
                 seriallink::Direction::Stray);
    }

    void aCorruptedReplyIsCountedAndNotTakenAsTheAnswer()
    {
        ScriptedTransport transport;
        QByteArray corrupted = reply(5);
        corrupted[5] = char(corrupted[5] ^ 0x10);
        transport.answers = {corrupted, reply(5)};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &result));
        QTRY_VERIFY(result.ok());
        QCOMPARE(result.attempts, 2);
        QCOMPARE(requests->counters().checksumErrors, 1);
    }

    void autoEchoDetectionRemovesTheAdaptersEcho_data()
    {
        QTest::addColumn<EchoMode>("mode");
        QTest::addColumn<bool>("adapterEchoes");
        QTest::addColumn<bool>("echoRemoved");
        QTest::newRow("auto, echoing adapter") << EchoMode::Auto << true << true;
        QTest::newRow("auto, plain adapter") << EchoMode::Auto << false << false;
        QTest::newRow("on") << EchoMode::On << true << true;
        QTest::newRow("off, plain adapter") << EchoMode::Off << false << false;
    }

    void autoEchoDetectionRemovesTheAdaptersEcho()
    {
        QFETCH(EchoMode, mode);
        QFETCH(bool, adapterEchoes);
        QFETCH(bool, echoRemoved);
        ScriptedTransport transport;
        transport.echo = adapterEchoes;
        transport.answers = {reply(1), reply(2)};
        auto requests = engine(transport);
        requests->setEchoMode(mode);
        TransactionResult first = unfinished();
        TransactionResult second = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, nullptr, &first));
        requests->submit(query(0x3D, Transaction::Priority::Command, nullptr, &second));
        QTRY_VERIFY(second.ok());
        QVERIFY(first.ok());
        QCOMPARE(requests->echoDetected(), echoRemoved);
        QCOMPARE(requests->counters().echoBytes, echoRemoved ? 2 * ptk::kRequestSize : 0);
        QCOMPARE(requests->counters().timeouts, 0);
    }

    void anAnswerWithTheRequestsVeryBytesIsTakenOnceTheEchoIsAccountedFor_data()
    {
        QTest::addColumn<EchoMode>("mode");
        QTest::addColumn<bool>("adapterEchoes");
        QTest::newRow("off, plain adapter") << EchoMode::Off << false;
        QTest::newRow("on, echoing adapter") << EchoMode::On << true;
    }

    void anAnswerWithTheRequestsVeryBytesIsTakenOnceTheEchoIsAccountedFor()
    {
        // A Feetech servo with the voltage bit answers a PING with the PING itself.
        QFETCH(EchoMode, mode);
        QFETCH(bool, adapterEchoes);
        ScriptedTransport transport;
        transport.echo = adapterEchoes;
        const QByteArray request = ptk::encodeQuery(0x38);
        transport.answers = {request};
        auto requests = engine(transport);
        requests->setEchoMode(mode);
        TransactionResult result = unfinished();
        Transaction transaction = query(0x38, Transaction::Priority::Command, nullptr, &result);
        transaction.acceptsReply = [request](const QByteArray &frame) {
            return frame == request;
        };
        transaction.answerMayEqualRequest = true;
        requests->submit(std::move(transaction));
        QTRY_COMPARE(result.failure, Failure::None);
        QCOMPARE(result.reply, request);
        QCOMPARE(result.attempts, 1);
    }

    void whileTheEchoIsUndecidedALoneCopyOfTheRequestIsReportedAsSuch()
    {
        // Echo or answer: the engine cannot tell, says so, and decides nothing.
        ScriptedTransport transport;
        const QByteArray request = ptk::encodeQuery(0x38);
        transport.answers = {request};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        Transaction transaction = query(0x38, Transaction::Priority::Command, nullptr, &result);
        transaction.acceptsReply = [request](const QByteArray &frame) {
            return frame == request;
        };
        transaction.answerMayEqualRequest = true;
        transaction.retryCount = 0;
        requests->submit(std::move(transaction));
        QTRY_COMPARE(result.failure, Failure::Timeout);
        QVERIFY(result.onlyOwnFrame);
        QVERIFY(!requests->echoDecided());
        // A request whose answer cannot equal it decides: an answer and no echo.
        TransactionResult next = unfinished();
        // The first is taken for the late answer the timed-out request may still owe.
        transport.answers = {reply(4), reply(4)};
        requests->submit(query(0x3D, Transaction::Priority::Command, nullptr, &next));
        QTRY_VERIFY(next.ok());
        QVERIFY(requests->echoDecided());
        QVERIFY(!requests->echoDetected());
    }

    void aWriteThatExpectsNoReplyCompletesAfterItHasLeft()
    {
        ScriptedTransport transport;
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        Transaction write = noReplyWrite(20, &result);
        requests->submit(write);
        QTRY_VERIFY(result.ok());
        QCOMPARE(requests->counters().timeouts, 0);
    }

    void aLateAnswerIsCountedLateAndHandedToItsRequestNotReportedAsAnError()
    {
        ScriptedTransport transport; // silent: the answer comes after the wait
        auto requests = engine(transport);
        QSignalSpy log(requests.get(), &RequestEngine::packetLogged);
        Transaction asked = query(0x38, Transaction::Priority::Command, nullptr);
        asked.retryCount = 0;
        QByteArray lateFrame;
        std::chrono::microseconds lateAfter {-1};
        asked.lateAnswer = [&](const QByteArray &frame, std::chrono::microseconds after) {
            lateFrame = frame;
            lateAfter = after;
            return true;
        };
        TransactionResult result = unfinished();
        asked.done = [&](const TransactionResult &outcome) {
            result = outcome;
        };
        requests->submit(asked);
        QTRY_COMPARE(result.failure, Failure::Timeout);
        QTest::qWait(10);
        log.clear();
        transport.deliver(reply(7));
        QCOMPARE(lateFrame, reply(7));
        QVERIFY(lateAfter >= std::chrono::milliseconds(10));
        QCOMPARE(requests->counters().lateReplies, 1);
        QCOMPARE(requests->counters().discardedBytes, 0);
        QCOMPARE(log.size(), 1);
        const auto entry = log.first().first().value<seriallink::PacketLogEntry>();
        QCOMPARE(entry.direction, seriallink::Direction::In);
        QVERIFY2(entry.error.isEmpty(), qPrintable(entry.error));
    }

    void aLateEchoIsNeverTakenForALateAnswer()
    {
        ScriptedTransport transport; // no echo in time, then the echo after the wait
        auto requests = engine(transport);
        requests->setEchoMode(EchoMode::On);
        Transaction asked = query(0x38, Transaction::Priority::Command, nullptr);
        asked.retryCount = 0;
        int claimed = 0;
        asked.lateAnswer = [&](const QByteArray &, std::chrono::microseconds) {
            ++claimed;
            return true; // would take anything
        };
        TransactionResult result = unfinished();
        asked.done = [&](const TransactionResult &outcome) {
            result = outcome;
        };
        requests->submit(asked);
        QTRY_COMPARE(result.failure, Failure::Timeout);
        QSignalSpy log(requests.get(), &RequestEngine::packetLogged);
        transport.deliver(asked.request);
        QCOMPARE(claimed, 0);
        QCOMPARE(log.size(), 1);
        QCOMPARE(log.first().first().value<seriallink::PacketLogEntry>().direction,
                 seriallink::Direction::Echo);
        // Its answer then is the late one, taken once: a second copy is stray.
        transport.deliver(reply(4));
        QCOMPARE(claimed, 1);
        transport.deliver(reply(4));
        QCOMPARE(claimed, 1);
        QCOMPARE(requests->counters().lateReplies, 1);
    }

    void aFrameNoEndedRequestClaimsIsStillStray()
    {
        ScriptedTransport transport;
        auto requests = engine(transport);
        Transaction asked = query(0x38, Transaction::Priority::Command, nullptr);
        asked.retryCount = 0;
        asked.lateAnswer = [](const QByteArray &, std::chrono::microseconds) {
            return false;
        };
        TransactionResult result = unfinished();
        asked.done = [&](const TransactionResult &outcome) {
            result = outcome;
        };
        requests->submit(asked);
        QTRY_COMPARE(result.failure, Failure::Timeout);
        QSignalSpy log(requests.get(), &RequestEngine::packetLogged);
        transport.deliver(reply(7));
        QCOMPARE(requests->counters().lateReplies, 0);
        QCOMPARE(log.size(), 1);
        QCOMPARE(log.first().first().value<seriallink::PacketLogEntry>().direction,
                 seriallink::Direction::Stray);
    }

    void theDefaultWaitGrowsToTheSlowEndOfTheAnswers()
    {
        // Answers 40 ms after their request, eight times the set wait (an FTDI adapter's latency
        // timer): the first is late; from then on the wait (some 62 ms) covers them.
        ScriptedTransport transport;
        auto requests = engine(transport);
        const auto answerLater = [&] {
            QTimer::singleShot(40, Qt::PreciseTimer, &transport,
                               [&] { transport.deliver(reply(3)); });
        };
        Transaction first = query(0x38, Transaction::Priority::Command, nullptr);
        first.retryCount = 0;
        bool tookLate = false;
        first.lateAnswer = [&](const QByteArray &, std::chrono::microseconds) {
            tookLate = true;
            return true;
        };
        TransactionResult result = unfinished();
        first.done = [&](const TransactionResult &outcome) {
            result = outcome;
        };
        requests->submit(first);
        answerLater();
        QTRY_VERIFY(tookLate);
        QCOMPARE(result.failure, Failure::Timeout);
        for (int i = 0; i < 3; ++i) {
            Transaction next = query(0x3D, Transaction::Priority::Command, nullptr, &result);
            next.retryCount = 0;
            result = unfinished();
            requests->submit(next);
            answerLater();
            QTRY_VERIFY(result.failure != Failure::Cancelled);
            QVERIFY(result.ok());
        }
        QCOMPARE(requests->counters().timeouts, 1);
    }

    void aWriteEndsWhenItsEchoIsBackAndALateEchoIsNoStrayInput()
    {
        ScriptedTransport transport;
        auto requests = engine(transport);
        requests->setEchoMode(EchoMode::On);
        seriallink::EngineTiming patient = requests->timing();
        patient.replyTimeout = std::chrono::seconds(3);
        QSignalSpy log(requests.get(), &RequestEngine::packetLogged);
        TransactionResult result = unfinished();
        Transaction write = noReplyWrite(20, &result);
        // The adapter gives the echo back only after the write's wait: it is still the echo.
        requests->submit(write);
        QTRY_VERIFY(result.ok());
        transport.deliver(write.request);
        // The next write's echo comes in time and ends it, long before its 3 s wait would.
        requests->setTiming(patient);
        transport.echo = true;
        result = unfinished();
        write.request = ptk::encodeRequest({1, 21, 0});
        requests->submit(write);
        QTRY_VERIFY_WITH_TIMEOUT(result.ok(), 1000);
        QCOMPARE(requests->counters().discardedBytes, 0);
        QCOMPARE(requests->counters().echoBytes, 2 * write.request.size());
        for (const auto &entry : log)
            QVERIFY(entry.first().value<seriallink::PacketLogEntry>().direction
                    != seriallink::Direction::Stray);
    }

    void cancellingEndsQueuedAndCurrentTransactions()
    {
        ScriptedTransport transport;
        auto requests = engine(transport);
        QVector<QString> order;
        TransactionResult last = unfinished();
        requests->submit(query(0x38, Transaction::Priority::Command, &order));
        requests->submit(query(0x3D, Transaction::Priority::Poll, &order, &last));
        QTRY_COMPARE(transport.written.size(), 1);
        requests->cancelAll(Failure::LinkDown);
        QCOMPARE(order.size(), 2);
        QCOMPARE(last.failure, Failure::LinkDown);
        QVERIFY(requests->isIdle());
    }

    void aClosedPortFailsTheTransactionAtOnce()
    {
        ScriptedTransport transport;
        transport.open = false;
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        QVector<QString> order;
        requests->submit(query(0x38, Transaction::Priority::Command, &order, &result));
        QTRY_COMPARE(order.size(), 1);
        QCOMPARE(result.failure, Failure::LinkDown);
        QVERIFY(transport.written.isEmpty());
    }

    void anAnswerThatHasBegunWhenAFirstByteWaitEndsGetsItsTime()
    {
        // A scan waits a fraction of a millisecond for the first byte; this answer's first
        // bytes are in by then, the rest comes well after.
        ScriptedTransport transport;
        const QByteArray answer = reply(7);
        transport.answers = {answer.left(3)};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        QVector<QString> order;
        requests->submit(firstByteQuery(&order, &result));
        QTRY_COMPARE(transport.written.size(), 1);
        QTimer::singleShot(20, &transport, [&] { transport.deliver(answer.mid(3)); });
        QTRY_COMPARE(order.size(), 1);
        QCOMPARE(result.failure, Failure::None);
        QCOMPARE(result.reply, answer);
    }

    void aFirstByteWaitWithNothingHeardEndsInATimeout()
    {
        ScriptedTransport transport; // silent
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        QVector<QString> order;
        requests->submit(firstByteQuery(&order, &result));
        QTRY_COMPARE(order.size(), 1);
        QCOMPARE(result.failure, Failure::Timeout);
        QCOMPARE(result.bytesHeard, 0);
    }

    void aListenOnlyWaitEndsOnceTheAnswersHaveComeIn()
    {
        // The broadcast probe: it accepts nothing, and its long wait is for a silent rate only.
        ScriptedTransport transport;
        transport.answers = {reply(1)};
        auto requests = engine(transport);
        TransactionResult result = unfinished();
        QVector<QString> order;
        Transaction transaction = query(0x38, Transaction::Priority::Command, &order, &result);
        transaction.acceptsReply = [](const QByteArray &) {
            return false;
        };
        transaction.replyTimeout = std::chrono::seconds(600);
        transaction.afterFirstByte = std::chrono::milliseconds(1);
        transaction.retryCount = 0;
        requests->submit(std::move(transaction));
        QTRY_COMPARE_WITH_TIMEOUT(order.size(), 1, 60000);
        QCOMPARE(result.failure, Failure::Timeout);
        QCOMPARE(result.bytesHeard, int(ptk::kReplySize));
    }

    void thePermissionMessageExplainsTheDialoutGroup()
    {
        const QString message = seriallink::portErrorMessage(
            QSerialPort::PermissionError, QStringLiteral("/dev/ttyUSB0"), QString());
        QVERIFY(message.contains(QStringLiteral("/dev/ttyUSB0")));
#ifdef Q_OS_LINUX
        QVERIFY(message.contains(QStringLiteral("dialout")));
#endif
        QVERIFY(seriallink::isLostError(QSerialPort::ResourceError));
        QVERIFY(!seriallink::isLostError(QSerialPort::PermissionError));
    }
};

QTEST_GUILESS_MAIN(TestRequestEngine)
#include "tst_requestengine.moc"
