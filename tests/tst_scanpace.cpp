// Unit tests of the scan's wait per ID: it follows the answers heard, within its floor and cap.
#include "scanpace.h"

#include <QtTest>

using feetech::ScanPace;
using std::chrono::microseconds;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;
constexpr microseconds kCap {1500};

// A pace that heard `count` answers, each `extra` beyond the PING's wire time at `baud`.
ScanPace heard(microseconds extra, int count, qint32 baud = k1M)
{
    ScanPace pace;
    for (int i = 0; i < count; ++i)
        pace.noteAnswer(ScanPace::pingWireTime(baud, false) + extra, baud);
    return pace;
}

} // namespace

class TestScanPace : public QObject
{
    Q_OBJECT

private slots:
    void beforeAnyAnswerTheWaitIsTheCapsWithTheWireTime()
    {
        const ScanPace pace;
        QVERIFY(!pace.measured());
        QCOMPARE(pace.pingWait(k1M, false, kCap), ScanPace::pingWireTime(k1M, false) + kCap);
    }

    void aSlowerLinkGetsALongerWait()
    {
        const ScanPace fast = heard(microseconds(100), 4);
        const ScanPace slow = heard(microseconds(400), 4);
        QVERIFY(slow.pingWait(k1M, false, kCap) > fast.pingWait(k1M, false, kCap));
        // Three times the typical extra, plus the margin, on top of the wire time.
        QCOMPARE(slow.pingWait(k1M, false, kCap),
                 ScanPace::pingWireTime(k1M, false) + microseconds(3 * 400) + ScanPace::kMargin);
    }

    void answersHeldForAnAdaptersPacketGetHalfAgainTheSlowest()
    {
        // An FTDI adapter's 16 ms latency timer: every answer about as late as the others.
        constexpr microseconds kLargeCap {60000};
        ScanPace pace = heard(microseconds(16000), 4);
        pace.noteAnswer(ScanPace::pingWireTime(k1M, false) + microseconds(17000), k1M);
        QCOMPARE(pace.pingWait(k1M, false, kLargeCap),
                 ScanPace::pingWireTime(k1M, false) + microseconds(17000 * 3 / 2)
                     + ScanPace::kMargin);
        // Spread wide, the median rule is the shorter one and stays.
        ScanPace spread = heard(microseconds(2000), 4);
        spread.noteAnswer(ScanPace::pingWireTime(k1M, false) + microseconds(30000), k1M);
        QCOMPARE(spread.pingWait(k1M, false, kLargeCap),
                 ScanPace::pingWireTime(k1M, false) + microseconds(3 * 2000) + ScanPace::kMargin);
    }

    void theWaitNeverExceedsTheCap()
    {
        const ScanPace slow = heard(microseconds(5000), 3);
        QCOMPARE(slow.pingWait(k1M, false, kCap), ScanPace::pingWireTime(k1M, false) + kCap);
    }

    void theWaitNeverFallsBelowTheWireTimeAndTheMinimumExtra()
    {
        // Answers that came quicker than their own bytes could (a pty) count as no extra.
        ScanPace instant;
        instant.noteAnswer(microseconds(0), k1M);
        QCOMPARE(instant.typicalExtra(), microseconds(0));
        QCOMPARE(instant.pingWait(k1M, false, kCap),
                 ScanPace::pingWireTime(k1M, false) + ScanPace::kMinimumExtra);
    }

    void oneSlowAnswerDoesNotSetThePace()
    {
        // The first exchange on a fresh port, or a busy moment: far slower than the rest.
        ScanPace pace = heard(microseconds(100), 4);
        pace.noteAnswer(ScanPace::pingWireTime(k1M, false) + microseconds(20000), k1M);
        QCOMPARE(pace.typicalExtra(), microseconds(100));
    }

    void whatWasLearnedAtOneRateServesAnother()
    {
        // The extra is what the adapter, servo and OS add: the wire time is the rate's own.
        const ScanPace pace = heard(microseconds(150), 3, k1M);
        QCOMPARE(pace.pingWait(k115k, false, kCap) - pace.pingWait(k1M, false, kCap),
                 ScanPace::pingWireTime(k115k, false) - ScanPace::pingWireTime(k1M, false));
        QVERIFY(ScanPace::pingWireTime(k115k, false) > ScanPace::pingWireTime(k1M, false));
    }

    void aSingleWireAdapterWaitsForThePingsEchoToo()
    {
        QCOMPARE(ScanPace::pingWireTime(k1M, true) - ScanPace::pingWireTime(k1M, false),
                 ScanPace::wireTime(6, k1M));
        QCOMPARE(ScanPace::wireTime(6, k1M), microseconds(60));
    }

    void onlyTheRecentAnswersCount()
    {
        ScanPace pace = heard(microseconds(2000), int(ScanPace::kWindow));
        for (std::size_t i = 0; i < ScanPace::kWindow; ++i)
            pace.noteAnswer(ScanPace::pingWireTime(k1M, false) + microseconds(100), k1M);
        QCOMPARE(pace.typicalExtra(), microseconds(100));
        pace.clear();
        QVERIFY(!pace.measured());
    }
};

QTEST_GUILESS_MAIN(TestScanPace)
#include "tst_scanpace.moc"
