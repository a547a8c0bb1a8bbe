// LateAnswers: which ended request a late frame answers, for how long, and the answers owed.
#include "lateanswers.h"

#include <QtTest>

using seriallink::LateAnswers;
using std::chrono::microseconds;

namespace {

// A request written at `writtenUs`, ended at `endedUs`, whose late answer is `answer`.
LateAnswers::EndedRequest endedRequest(const QByteArray &request, const QByteArray &answer,
                                       qint64 writtenUs, qint64 endedUs, bool several = false)
{
    LateAnswers::EndedRequest ended;
    ended.request = request;
    ended.writtenAtUs = writtenUs;
    ended.endedAtUs = endedUs;
    ended.wireTime = microseconds(100);
    ended.several = several;
    ended.lateAnswer = [answer](const QByteArray &frame, microseconds) {
        return frame == answer;
    };
    return ended;
}

} // namespace

class TestLateAnswers : public QObject
{
    Q_OBJECT

private slots:
    void aLateFrameAnswersTheRequestThatAskedForItAndSaysHowLate()
    {
        LateAnswers late;
        late.remember(endedRequest("A?", "A!", 1000, 21000));
        late.remember(endedRequest("B?", "B!", 22000, 42000));
        const auto after = late.take("A!", 50000, true);
        QVERIFY(after.has_value());
        // From the request's writing, less the wire time it needed anyway.
        QCOMPARE(*after, microseconds(50000 - 1000 - 100));
        QVERIFY(!late.take("A!", 50001, true)); // answered once
        QVERIFY(late.take("B!", 50002, true));
        QVERIFY(!late.take("C!", 50003, true)); // nobody asked for it
    }

    void aRequestSeveralServosAnswerTakesEachOfThem()
    {
        LateAnswers late;
        late.remember(endedRequest("SYNC?", "sample", 0, 20000, true));
        QVERIFY(late.take("sample", 30000, true));
        QVERIFY(late.take("sample", 31000, true));
    }

    void theNewestRequestIsOfferedAFrameFirst()
    {
        LateAnswers late;
        late.remember(endedRequest("old?", "same!", 0, 20000));
        late.remember(endedRequest("new?", "same!", 30000, 50000));
        const auto after = late.take("same!", 60000, true);
        QVERIFY(after.has_value());
        QCOMPARE(*after, microseconds(60000 - 30000 - 100));
        // The older one is still waiting for its own.
        QCOMPARE(*late.take("same!", 60001, true), microseconds(60001 - 0 - 100));
    }

    void aRequestsOwnEchoIsNoAnswerWhereEchoesComeBack()
    {
        LateAnswers late;
        late.remember(endedRequest("PING", "PING", 0, 20000));
        QVERIFY(!late.take("PING", 30000, true));
        // Without an echo, the same bytes may be its answer (a PING answered with its own bytes).
        QVERIFY(late.take("PING", 30001, false));
    }

    void requestsAreOfferedFramesForASecondAndOnlyTheLastEight()
    {
        LateAnswers late;
        late.remember(endedRequest("A?", "A!", 0, 10000));
        QVERIFY(!late.take("A!", 10000 + 1'000'001, true)); // kept for a second only
        for (int i = 0; i < 9; ++i) {
            const QByteArray n = QByteArray::number(i);
            late.remember(endedRequest(n + '?', n + '!', i * 100, i * 100 + 50));
        }
        QVERIFY(!late.take("0!", 2000, true)); // the ninth pushed the first out
        QVERIFY(late.take("1!", 2001, true));
        QVERIFY(late.take("8!", 2002, true));
        late.forgetRequests();
        QVERIFY(!late.take("5!", 2003, true));
    }

    void anOwedAnswerLapsesAfterASecondOrWhenPaid()
    {
        LateAnswers late;
        QVERIFY(!late.answerOwed(0));
        late.oweAnswer(1000);
        late.oweAnswer(2000);
        QVERIFY(late.answerOwed(500'000));
        late.answerPaid();
        QVERIFY(late.answerOwed(500'001)); // one of two paid
        late.answerPaid();
        QVERIFY(!late.answerOwed(500'002));
        late.answerPaid(); // nothing owed: no debt below zero
        late.oweAnswer(3000);
        QVERIFY(late.answerOwed(3000 + 999'999));
        QVERIFY(!late.answerOwed(3000 + 1'000'000)); // lapsed
    }

    void aLinkThatAnswersAtOnceOwesNothingUntilItAnswersLate()
    {
        LateAnswers late;
        late.oweAnswer(0);
        late.answeredAtOnce();
        QVERIFY(late.answersAtOnce());
        QVERIFY(!late.answerOwed(10)); // such a device sends no late answers
        late.answeredLate();
        QVERIFY(!late.answersAtOnce());
        QVERIFY(late.answerOwed(11));
        // A new port forgets what the last one taught, and what it owed.
        late.answeredAtOnce();
        late.forgetLink();
        QVERIFY(!late.answersAtOnce());
        QVERIFY(!late.answerOwed(12));
    }
};

QTEST_GUILESS_MAIN(TestLateAnswers)
#include "tst_lateanswers.moc"
