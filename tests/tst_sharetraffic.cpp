// The share's reading of traffic without a bus: pairing with echo and time-outs, what servos
// show, and each alert's condition.
#include "busgate.h"
#include "feetechpacket.h"
#include "observedservos.h"
#include "sharealerts.h"
#include "transactiontracker.h"

#include <QtTest>

using share::ObservedServos;
using share::ShareAlerts;
using share::SharedTransaction;
using share::TransactionTracker;

namespace {

constexpr qint32 k1M = 1000000;

// A port that keeps what is written to it and answers only when told.
class QuietPort final : public seriallink::Transport
{
public:
    QVector<QByteArray> written;

    bool isOpen() const override { return true; }
    qint32 baudRate() const override { return k1M; }
    void write(const QByteArray &bytes) override { written.append(bytes); }
    QByteArray discardInput() override { return {}; }
    void answer(const QByteArray &bytes) { emit received(bytes); }
};

seriallink::StreamItem frame(const QByteArray &bytes)
{
    return {seriallink::StreamItem::Kind::Frame, bytes, 0};
}

seriallink::StreamItem garbage(const QByteArray &bytes)
{
    return {seriallink::StreamItem::Kind::Garbage, bytes, 0};
}

// A STS3215's identity bytes 0-18 as a READ of them answers: firmware 3.10, model 9.3, limits
// 0-4095, maximum 70 °C, supply 4.0-8.0 V.
QByteArray identityAnswer(quint8 id)
{
    return feetech::status(id, 0,
                           QByteArray::fromHex("030a0009030100000100"
                                               "00ff0f465028e8030c"));
}

SharedTransaction transaction(const QByteArray &request, const QVector<QByteArray> &replies,
                              qint64 timeUs = 0)
{
    SharedTransaction made;
    made.request = request;
    made.replies = replies;
    made.timeUs = timeUs;
    made.expectedReplies =
        request.size() > 4 && quint8(request.at(4)) == 0x82 ? int(made.askedIds().size()) : 1;
    return made;
}

} // namespace

class TestShareTraffic : public QObject
{
    Q_OBJECT

private:
    // Learns each transaction and gathers the alerts they raise.
    QStringList feed(ObservedServos &servos, ShareAlerts &alerts,
                     QVector<SharedTransaction> transactions)
    {
        QStringList codes;
        for (SharedTransaction &each : transactions) {
            servos.learn(each, k1M);
            for (const share::ShareAlert &alert : alerts.inspect(each, servos))
                codes.append(QStringLiteral("%1/%2").arg(alert.code).arg(alert.id));
        }
        return codes;
    }

private slots:
    void aReadIsAnsweredAndItsRoundTripMeasured()
    {
        QVector<SharedTransaction> done;
        TransactionTracker tracker([&done](SharedTransaction &&t) { done.append(t); });
        tracker.request(feetech::read(1, 56, 2), 100);
        QVERIFY(tracker.isOutstanding());
        tracker.heard(frame(feetech::status(1, 0, QByteArray::fromHex("0008"))), 450);
        QVERIFY(!tracker.isOutstanding());
        QCOMPARE(done.size(), 1);
        QCOMPARE(done.first().replies.size(), 1);
        QCOMPARE(*done.first().roundTripUs, qint64(350));
        QCOMPARE(tracker.echoes(), std::optional<bool>(false));
    }

    void anEchoIsToldFromTheAnswerAndAWriteNobodyAnswersEndsWithIt()
    {
        QVector<SharedTransaction> done;
        TransactionTracker tracker([&done](SharedTransaction &&t) { done.append(t); });
        const QByteArray request = feetech::read(2, 56, 2);
        tracker.request(request, 0);
        tracker.heard(frame(request), 100); // the adapter's echo
        QVERIFY(tracker.isOutstanding());
        tracker.heard(frame(feetech::status(2, 0, QByteArray::fromHex("0008"))), 400);
        QCOMPARE(done.size(), 1);
        QCOMPARE(done.first().echoBytes, int(request.size()));
        QCOMPARE(tracker.echoes(), std::optional<bool>(true));
        // A SYNC WRITE: nothing answers; it ends with its echo.
        const QByteArray write = *feetech::syncWrite(42, 2, {{1, QByteArray(2, '\0')}});
        tracker.request(write, 1000);
        QVERIFY(tracker.isOutstanding());
        tracker.heard(frame(write), 1200);
        QVERIFY(!tracker.isOutstanding());
        QCOMPARE(done.size(), 2);
    }

    void aSyncReadWaitsForEveryServoOrItsTime()
    {
        QVector<SharedTransaction> done;
        TransactionTracker tracker([&done](SharedTransaction &&t) { done.append(t); });
        tracker.setEchoes(false);
        tracker.request(feetech::syncRead(56, 2, {1, 2, 3}), 0);
        tracker.heard(frame(feetech::status(1, 0, QByteArray(2, '\0'))), 200);
        tracker.heard(garbage(QByteArray::fromHex("12fe")), 250);
        tracker.heard(frame(feetech::status(3, 0, QByteArray(2, '\0'))), 300);
        QVERIFY(tracker.isOutstanding());
        QVERIFY(!tracker.expire(1000));
        QVERIFY(tracker.expire(*tracker.deadlineUs()));
        QVERIFY(!tracker.isOutstanding()); // the bus is free for another request
        // The missing answer after its time, before the program's next request: the program
        // (whose own wait is longer) got it after all. Any other frame answers nothing.
        QCOMPARE(done.size(), 0);
        tracker.heard(frame(feetech::status(2, 0, QByteArray(2, '\0'))), 90000);
        QCOMPARE(done.size(), 1);
        QVERIFY(!done.first().unanswered());
        QCOMPARE(done.first().replies.size(), 3);
        QCOMPARE(done.first().garbledBytes, 2);
        QCOMPARE(done.first().roundTripUs, std::optional<qint64>(90000));
        QCOMPARE(tracker.strayFrames(), qint64(0));
        tracker.heard(frame(feetech::status(2, 0, QByteArray(2, '\0'))), 90100);
        QCOMPARE(tracker.strayFrames(), qint64(1));
        // Once the program asked again, an answer to the request before is no answer of it.
        tracker.request(feetech::syncRead(56, 2, {1, 2, 3}), 100000);
        QVERIFY(tracker.expire(*tracker.deadlineUs()));
        tracker.request(feetech::ping(1), 200000);
        QCOMPARE(done.size(), 2);
        QVERIFY(done.last().unanswered());
        tracker.heard(frame(feetech::status(3, 0, QByteArray(2, '\0'))), 200100);
        QCOMPARE(tracker.strayFrames(), qint64(2));
        // One the program never follows ends unanswered once no answer can be its any more.
        QVERIFY(tracker.expire(*tracker.deadlineUs()));
        QCOMPARE(done.size(), 2); // the PING's time ran out: it may still be answered late
        QVERIFY(tracker.expire(*tracker.deadlineUs()));
        QCOMPARE(done.size(), 3);
        QVERIFY(done.last().unanswered());
    }

    void theNextRequestEndsOneStillWaiting()
    {
        QVector<SharedTransaction> done;
        TransactionTracker tracker([&done](SharedTransaction &&t) { done.append(t); });
        tracker.request(feetech::ping(9), 0);
        tracker.request(feetech::ping(1), 5000);
        QCOMPARE(done.size(), 1);
        QVERIFY(done.first().unanswered());
        QCOMPARE(done.first().id(), quint8(9));
    }

    void theModelGivesTheBytesTheirMeaning()
    {
        ObservedServos servos;
        SharedTransaction position = transaction(
            feetech::read(1, 56, 2), {feetech::status(1, 0, QByteArray::fromHex("0008"))});
        servos.learn(position, k1M);
        QVERIFY(position.registers.isEmpty()); // the model is not known yet
        QVERIFY(servos.answered(1));
        SharedTransaction identity = transaction(feetech::read(1, 0, 19), {identityAnswer(1)});
        servos.learn(identity, k1M);
        QVERIFY(servos.table(1));
        QCOMPARE(servos.info(1)->model.name, QStringLiteral("STS3215"));
        QCOMPARE(servos.value(1, u"present_position"), std::optional<qint32>(2048));
        QCOMPARE(servos.scaled(1, u"max_voltage"), std::optional<double>(8.0));
        SharedTransaction again = transaction(feetech::read(1, 56, 2),
                                              {feetech::status(1, 0, QByteArray::fromHex("0004"))});
        servos.learn(again, k1M);
        QCOMPARE(again.registers.size(), 1);
        QCOMPARE(again.registers.first().key, QStringLiteral("present_position"));
        QCOMPARE(again.registers.first().value, 1024);
        // A SYNC WRITE's goals go to each servo it names.
        SharedTransaction goals = transaction(
            *feetech::syncWrite(
                42, 2, {{1, QByteArray::fromHex("e803")}, {2, QByteArray::fromHex("0008")}}),
            {});
        servos.learn(goals, k1M);
        QCOMPARE(servos.value(1, u"goal_position"), std::optional<qint32>(1000));
        QVERIFY(!servos.answered(2)); // written to, never heard from
    }

    void heatSupplyAndErrorBitsRaiseOnceUntilTheyClear()
    {
        ObservedServos servos;
        ShareAlerts alerts;
        feed(servos, alerts, {transaction(feetech::read(1, 0, 19), {identityAnswer(1)})});
        // Present voltage 12.0 V (above 8.0), temperature 66 °C (within 5 of 70).
        const QByteArray hot = feetech::status(1, 0, QByteArray::fromHex("7842"));
        QStringList codes = feed(servos, alerts, {transaction(feetech::read(1, 62, 2), {hot})});
        QCOMPARE(codes,
                 (QStringList {QStringLiteral("temperature-high/1"),
                               QStringLiteral("voltage-out-of-range/1")}));
        QVERIFY(feed(servos, alerts, {transaction(feetech::read(1, 62, 2), {hot})}).isEmpty());
        const QByteArray cool = feetech::status(1, 0, QByteArray::fromHex("4a19"));
        QVERIFY(feed(servos, alerts, {transaction(feetech::read(1, 62, 2), {cool})}).isEmpty());
        QCOMPARE(feed(servos, alerts, {transaction(feetech::read(1, 62, 2), {hot})}).size(), 2);
        // Error bits in a reply: overload on its own, the others together.
        codes = feed(servos, alerts, {transaction(feetech::ping(1), {feetech::status(1, 0x25)})});
        QCOMPARE(codes,
                 (QStringList {QStringLiteral("overload/1"), QStringLiteral("reply-error/1")}));
    }

    void garbledAnswersAtOneIdAgainAndAgainMeanASharedId()
    {
        ObservedServos servos;
        ShareAlerts alerts;
        QStringList codes;
        for (int i = 0; i < ShareAlerts::kGarbledAnswers; ++i) {
            SharedTransaction garbled = transaction(feetech::ping(4), {});
            garbled.garbledBytes = 7;
            codes += feed(servos, alerts, {garbled});
        }
        QCOMPARE(codes, QStringList {QStringLiteral("shared-id/4")});
    }

    void riskyWritesRaiseEachTimeAndAnUnlockedEepromWhenItsTimeIsUp()
    {
        ObservedServos servos;
        ShareAlerts alerts;
        feed(servos, alerts,
             {transaction(feetech::read(1, 0, 19), {identityAnswer(1)}),
              transaction(
                  feetech::read(1, 40, 31),
                  {feetech::status(1, 0,
                                   QByteArray(2, '\0') + QByteArray::fromHex("0008")
                                       + QByteArray(11, '\0') + QByteArray::fromHex("01") // locked
                                       + QByteArray::fromHex("0008") + QByteArray(13, '\0'))})});
        QCOMPARE(servos.value(1, u"present_position"), std::optional<qint32>(2048));
        const QByteArray ack = feetech::status(1, 0);
        QStringList codes =
            feed(servos, alerts,
                 {transaction(feetech::write(1, 55, QByteArray(1, '\0')), {ack}, 1000),
                  transaction(feetech::write(1, 18, QByteArray(1, char(0x10))), {ack}, 2000),
                  transaction(feetech::write(1, 42, QByteArray::fromHex("b80b")), {ack}, 3000),
                  transaction(feetech::write(1, 40, QByteArray(1, char(1))), {ack}, 4000)});
        QCOMPARE(codes,
                 (QStringList {QStringLiteral("multi-turn/1"), QStringLiteral("torque-jump/1")}));
        QVERIFY(alerts.tick(1000 + ShareAlerts::kUnlockedUs - 1).isEmpty());
        QCOMPARE(alerts.tick(1000 + ShareAlerts::kUnlockedUs).size(), 1);
        QVERIFY(alerts.tick(1000 + 2 * ShareAlerts::kUnlockedUs).isEmpty()); // said once
        // Locked again: nothing more to say.
        feed(servos, alerts,
             {transaction(feetech::write(1, 55, QByteArray(1, char(1))), {ack}, 9000)});
        QVERIFY(alerts.tick(100000000).isEmpty());
    }

    void requestsTheProgramGaveUpOnWhileAnOwnRequestWasAnsweredAreNotSent()
    {
        QuietPort port;
        share::BusGate gate(port);
        const QByteArray own = feetech::read(1, 56, 2);
        gate.write(own);
        QCOMPARE(port.written, QVector<QByteArray> {own});
        // Meanwhile the program asks, gives up waiting, and asks again: only the last one is
        // still waited for, and the answer to the first would reach it as the answer to that.
        const QByteArray gaveUp = feetech::read(2, 3, 2);
        const QByteArray unlocked = feetech::syncWrite(55, 1, {{3, QByteArray(1, '\0')}}).value();
        const QByteArray waited = feetech::read(3, 3, 2);
        gate.fromProgram(gaveUp + unlocked);
        gate.fromProgram(waited.left(3));
        gate.fromProgram(waited.mid(3));
        QCOMPARE(port.written.size(), 1);
        port.answer(QByteArray::fromHex("ffff0104000008f2"));
        QCOMPARE(port.written, (QVector<QByteArray> {own, unlocked + waited}));
        QCOMPARE(gate.counters().givenUp, 1);
    }
};

QTEST_GUILESS_MAIN(TestShareTraffic)
#include "tst_sharetraffic.moc"
