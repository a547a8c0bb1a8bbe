// Tests of the Feetech bus scan, driven on its own over a link to a simulated bus.
#include "feetechbus.h"

#include "busscan.h"
#include "hex.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::BusScan;
using feetech::Instruction;
using feetech::ScanOptions;
using feetech::ServoInfo;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;
constexpr qint32 k500k = 500000;

} // namespace

class TestBusScan : public testsupport::FeetechLinkTest
{
    Q_OBJECT

private:
    std::unique_ptr<BusScan> m_scan;
    QVector<ServoInfo> m_found;

    void startBus(const sim::SimulatorOptions &options)
    {
        QString error;
        QVERIFY2(startLink(options, &error), qPrintable(error));
        m_scan = std::make_unique<BusScan>(*m_bus);
        connect(m_scan.get(), &BusScan::servoFound, this,
                [this](const ServoInfo &servo) { m_found.append(servo); });
    }

    // Starts a bus with `models` at IDs 1, 2... at 1 Mbps and every answer touched by `faults`
    // (seeded), then scans IDs 0 to lastId: whether the scan completed.
    bool scanFaultyBus(std::initializer_list<QStringView> models, const sim::FaultSettings &faults,
                       int lastId, quint32 seed = 11)
    {
        sim::SimulatorOptions options = busOptions(testsupport::servosAt(k1M, models));
        options.faults = faults;
        options.seed = seed;
        startBus(options);
        ScanOptions scanOptions;
        scanOptions.lastId = lastId;
        return scan(scanOptions);
    }

    // Scans and waits up to 20 s for the end: whether it completed.
    bool scan(const ScanOptions &options)
    {
        QSignalSpy finished(m_scan.get(), &BusScan::finished);
        m_scan->start(options);
        if (finished.isEmpty() && !finished.wait(20000))
            return false;
        return finished.first().at(0).toBool();
    }

    std::optional<ServoInfo> found(quint8 id, qint32 baud) const
    {
        for (const ServoInfo &servo : m_found) {
            if (servo.id == id && servo.baud == baud)
                return servo;
        }
        return std::nullopt;
    }

    // The PINGs the bus received addressed to one ID (the broadcast probe excluded).
    int pingsTo(quint8 id) const
    {
        return int(testsupport::feetechRequestsReceived(logPath(), Instruction::Ping, id).size());
    }

    // The IDs asked one by one after the last broadcast probe, in order.
    QVector<int> idsAskedAfterTheLastProbe() const
    {
        QVector<int> ids;
        for (const feetech::Packet &ping :
             testsupport::feetechRequestsReceived(logPath(), Instruction::Ping)) {
            if (ping.id == feetech::kBroadcastId)
                ids.clear();
            else
                ids.append(ping.id);
        }
        return ids;
    }

    // The servos (IDs 1-3) whose answer to a unicast PING the simulator garbled, from its log:
    // named by the answer's ID byte (the flipped bit is rarely there).
    QVector<int> garbledPingAnswers() const
    {
        QVector<int> ids;
        for (const QString &line :
             testsupport::logLinesStartingWith(logPath(), QStringLiteral("out "))) {
            const QString hex = line.mid(4).section(QStringLiteral("  #"), 0, 0).trimmed();
            const auto bytes = util::parseHex(hex);
            const bool pingAnswer = bytes && bytes->size() == feetech::kMinimumPacketSize;
            const int id = pingAnswer ? quint8(bytes->at(2)) : -1;
            if (line.contains(QStringLiteral("corrupt")) && id >= 1 && id <= 3 && !ids.contains(id))
                ids.append(id);
        }
        return ids;
    }

private slots:
    void init() { m_found.clear(); }

    void cleanup()
    {
        m_scan.reset();
        stopLink();
    }

    void findsEveryServoAtTwoRatesWithItsIdentity()
    {
        // ID 1 twice: at another rate it is another servo.
        auto servos = testsupport::servosAt(k1M, {u"STS3215", u"SCS15"});
        servos.append({1, QStringLiteral("SMS"), k115k});
        servos.append({4, QStringLiteral("STS3215"), k115k});
        startBus(busOptions(servos));
        ScanOptions options;
        options.lastId = 6;
        options.bauds = {k1M, k115k};
        QSignalSpy finished(m_scan.get(), &BusScan::finished);
        QVERIFY(scan(options));
        QVERIFY2(finished.first().at(1).toString().contains(u'4'),
                 qPrintable(finished.first().at(1).toString()));
        QCOMPARE(m_found.size(), 4);
        const struct
        {
            quint8 id;
            qint32 baud;
            feetech::Family family;
        } expected[] = {{1, k1M, feetech::Family::Sts},
                        {2, k1M, feetech::Family::Scs},
                        {1, k115k, feetech::Family::Sms},
                        {4, k115k, feetech::Family::Sts}};
        for (const auto &servo : expected) {
            const auto info = found(servo.id, servo.baud);
            QVERIFY2(info, qPrintable(QStringLiteral("ID %1 at %2").arg(servo.id).arg(servo.baud)));
            QVERIFY(info->hasTable());
            QCOMPARE(*info->model.family, servo.family);
            // What the servo says of itself, as the simulator holds it.
            const bool held = withServo(servo.id, servo.baud, [&](const auto &held) {
                QCOMPARE(int(info->firmwareMajor), held.value(u"firmware_major"));
                QCOMPARE(int(info->firmwareMinor), held.value(u"firmware_minor"));
                QCOMPARE(int(info->modelMajor), held.value(u"model_major"));
                QCOMPARE(int(info->modelMinor), held.value(u"model_minor"));
                QCOMPARE(int(info->baudCode), held.value(u"baud_rate"));
            });
            QVERIFY(held);
        }
    }

    void skipsASilentRateWithoutAskingEachId()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        ScanOptions options;
        options.lastId = 5;
        options.bauds = {k1M, k500k};
        QVERIFY(scan(options));
        QCOMPARE(m_found.size(), 1);
        QCOMPARE(m_found.first().baud, k1M);
        // Every ID was asked at 1 Mbps; none at the rate where the probe heard nothing.
        for (quint8 id = 0; id <= 5; ++id)
            QVERIFY(pingsTo(id) >= 1);
        QCOMPARE(idsAskedAfterTheLastProbe(), QVector<int> {});
    }

    void aRateThatSeemedSilentIsLookedAtAgainWhenNobodyWasFound()
    {
        // The servo answers 30 ms late, the opening probe waits 20: the rate seems silent.
        // Before the scan reports nobody, it asks that rate once more, twice as patiently.
        m_timing.probeAllowance = std::chrono::milliseconds(20);
        m_timing.initialScanAllowance = std::chrono::milliseconds(20);
        m_timing.engine.replyTimeout = std::chrono::milliseconds(150);
        sim::SimulatorOptions options = busOptions(testsupport::servosAt(k1M, {u"STS3215"}));
        options.replyDelayUs = 30000;
        startBus(options);
        ScanOptions scanOptions;
        scanOptions.lastId = 3;
        QVERIFY(scan(scanOptions));
        QVERIFY(found(1, k1M));
        QCOMPARE(m_found.size(), 1);
    }

    void anEmptyBusIsProbedTwiceAtEachRateBeforeNobodyIsReported()
    {
        // Its one servo is at a rate the scan does not cover.
        startBus(busOptions({{1, QStringLiteral("STS3215"), k115k}}));
        ScanOptions options;
        options.lastId = 5;
        options.bauds = {k1M, k500k};
        QSignalSpy progress(m_scan.get(), &BusScan::progress);
        QVERIFY(scan(options));
        QVERIFY(m_found.isEmpty());
        QCOMPARE(pingsTo(feetech::kBroadcastId), 4);
        for (quint8 id = 0; id <= 5; ++id)
            QCOMPARE(pingsTo(id), 0);
        // The second look is counted too: progress ends at its own, larger total.
        QCOMPARE(progress.last().at(0).toInt(), progress.last().at(1).toInt());
        QCOMPARE(progress.last().at(1).toInt(), 2 * 2 * 6);
    }

    void aThoroughScanAsksEveryIdEvenAtASilentRate()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        ScanOptions options;
        options.lastId = 5;
        options.bauds = {k1M, k500k};
        options.skipSilentRates = false;
        QVERIFY(scan(options));
        QCOMPARE(m_found.size(), 1);
        QCOMPARE(idsAskedAfterTheLastProbe(), (QVector<int> {0, 1, 2, 3, 4, 5}));
    }

    void cancelStopsWithTheServosFoundSoFar()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})));
        ScanOptions options; // every ID at 1 Mbps, then every ID at 500 kbps, asked regardless
        options.bauds = {k1M, k500k};
        options.skipSilentRates = false;
        QSignalSpy finished(m_scan.get(), &BusScan::finished);
        QSignalSpy progress(m_scan.get(), &BusScan::progress);
        m_scan->start(options);
        QTRY_COMPARE_WITH_TIMEOUT(m_found.size(), 2, 10000);
        m_scan->cancel();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY2(finished.first().at(1).toString().contains(u'2'),
                 qPrintable(finished.first().at(1).toString()));
        QVERIFY(!m_scan->isRunning());
        QCOMPARE(m_found.size(), 2);
        const int total = 2 * (feetech::kMaxServoId + 1);
        QVERIFY(progress.last().at(0).toInt() < total);
        // It stopped where it was: the second rate was never reached.
        QCOMPARE(pingsTo(feetech::kMaxServoId), 0);
    }

    void aServoThatAnswersLateIsFoundByTheRecheck()
    {
        // Every reply is 15 ms late, and the sweep waits at most 2 ms for one: each servo's
        // answer comes during a later ID's wait, names its sender, and that servo is asked
        // again with the engine's own, patient timeout.
        m_timing.minimumScanAllowance = std::chrono::milliseconds(1);
        m_timing.maximumScanAllowance = std::chrono::milliseconds(2);
        m_timing.engine.replyTimeout = std::chrono::milliseconds(150);
        sim::SimulatorOptions options = busOptions(testsupport::servosAt(k1M, {u"STS3215"}));
        options.servos.append({2, QStringLiteral("SCS15"), k1M});
        options.replyDelayUs = 15000;
        startBus(options);
        ScanOptions scanOptions;
        scanOptions.lastId = 40;
        QVERIFY(scan(scanOptions));
        QVERIFY(found(1, k1M));
        QVERIFY(found(2, k1M));
        QCOMPARE(found(2, k1M)->model.family, feetech::Family::Scs);
        // Asked in the sweep and again in the recheck.
        if (pingsTo(1) < 2) {
            for (const QString &l : testsupport::logLines(logPath()))
                qInfo() << l;
        }
        QVERIFY(pingsTo(1) >= 2);
        QVERIFY(pingsTo(2) >= 2);
    }

    void everyServoIsFoundWhenAnswersComeLateAtRandom()
    {
        // Each answer is late by 0-8 ms at random while the sweep waits at most 1 ms: most
        // answers come during a later ID's wait or between two PINGs, and each names its
        // servo, which is asked again with the engine's patient timeout.
        m_timing.minimumScanAllowance = std::chrono::microseconds(500);
        m_timing.maximumScanAllowance = std::chrono::milliseconds(1);
        sim::FaultSettings late;
        late.delayMs = 8;
        QVERIFY(scanFaultyBus(
            {u"STS3215", u"STS3215", u"SCS15", u"STS3215", u"STS3215", u"STS3215"}, late, 30));
        for (quint8 id = 1; id <= 6; ++id)
            QVERIFY2(found(id, k1M), qPrintable(QStringLiteral("servo %1 missed").arg(id)));
        QCOMPARE(m_found.size(), 6);
    }

    void aSlowerLinkGetsALongerWaitAndStillFindsEveryone()
    {
        // The wait for a missing ID follows the answers heard: 5 ms more on every answer
        // makes it longer, and nobody goes missing on either link.
        const auto scanAndMeasure = [this](qint64 replyDelayUs) {
            sim::SimulatorOptions options =
                busOptions(testsupport::servosAt(k1M, {u"STS3215", u"SCS15", u"STS3215"}));
            options.replyDelayUs = replyDelayUs;
            startBus(options);
            std::chrono::microseconds wait {0};
            connect(m_scan.get(), &BusScan::progress, this,
                    [this, &wait] { wait = m_scan->pingWait(k1M); });
            ScanOptions scanOptions;
            scanOptions.lastId = 12;
            const bool completed = scan(scanOptions);
            const bool everyone = found(1, k1M) && found(2, k1M) && found(3, k1M);
            m_scan.reset();
            stopLink();
            m_found.clear();
            return std::make_tuple(completed, everyone, wait);
        };
        const auto [slowCompleted, slowEveryone, slowWait] = scanAndMeasure(5000);
        QVERIFY(slowCompleted);
        QVERIFY(slowEveryone);
        // A busy moment slows the fast link too, and the wait rightly follows it: the fast
        // link gets up to three tries to show its own pace.
        std::chrono::microseconds fastWait = std::chrono::hours(1);
        for (int attempt = 0; attempt < 3 && fastWait >= slowWait; ++attempt) {
            const auto [completed, everyone, wait] = scanAndMeasure(0);
            QVERIFY(completed);
            QVERIFY(everyone);
            fastWait = std::min(fastWait, wait);
        }
        QVERIFY2(slowWait > fastWait,
                 qPrintable(QStringLiteral("%1 us on the slow link, %2 us on the fast one")
                                .arg(slowWait.count())
                                .arg(fastWait.count())));
        // Each answer took 5 ms beyond its wire time: the slow link waits at least that.
        QVERIFY(slowWait > std::chrono::milliseconds(5));
    }

    void aGarbledAnswerIsAskedAgain()
    {
        // A third of the answers have a bit flipped: a servo whose answer came garbled is
        // asked again rather than taken for an empty ID (its second answer may be garbled
        // too: whether it is found then is the dice's).
        QVector<int> garbled;
        for (quint32 seed = 5; seed < 8 && garbled.isEmpty(); ++seed) {
            cleanup();
            m_found.clear();
            sim::FaultSettings garbling;
            garbling.corrupt = 0.35;
            QVERIFY(scanFaultyBus({u"STS3215", u"STS3215", u"STS3215"}, garbling, 8, seed));
            garbled = garbledPingAnswers();
        }
        QVERIFY2(!garbled.isEmpty(), "no PING answer was garbled with any of the seeds");
        for (const int id : garbled)
            QVERIFY2(pingsTo(quint8(id)) >= 2, qPrintable(QStringLiteral("ID %1").arg(id)));
    }

    void progressReachesTheTotalRateByRate()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        ScanOptions options;
        options.firstId = 1;
        options.lastId = 10;
        options.bauds = {k1M, k500k};
        QSignalSpy progress(m_scan.get(), &BusScan::progress);
        QVERIFY(scan(options));
        const int total = 2 * 10;
        int last = -1;
        for (const QList<QVariant> &step : progress) {
            QCOMPARE(step.at(1).toInt(), total);
            QVERIFY(step.at(0).toInt() >= last);
            // The first half is counted at 1 Mbps, the rest at 500 kbps.
            if (step.at(0).toInt() > 10)
                QCOMPARE(step.at(2).toInt(), k500k);
            else if (step.at(0).toInt() > 0)
                QCOMPARE(step.at(2).toInt(), k1M);
            last = step.at(0).toInt();
        }
        QCOMPARE(last, total);
    }
};

QTEST_GUILESS_MAIN(TestBusScan)
#include "tst_busscan.moc"
