// Tests of the Feetech telemetry cycle, driven on its own over a link to a simulated bus.
#include "feetechbus.h"

#include "telemetrycycle.h"

#include <QSignalSpy>
#include <QtTest>

using feetech::FeedbackSample;
using feetech::Instruction;
using feetech::Packet;
using feetech::TelemetryCycle;
using feetech::TelemetryStats;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;

// The IDs a SYNC READ asks, in order.
QVector<quint8> syncReadIds(const Packet &request)
{
    QVector<quint8> ids;
    for (int i = 2; i < request.parameters.size(); ++i)
        ids.append(quint8(request.parameters.at(i)));
    return ids;
}

// Frames of a simulator log in order, each decoded, with whether the bus received it ("in") or
// sent it ("out").
QVector<std::pair<bool, Packet>> loggedTraffic(const QString &logPath)
{
    QVector<std::pair<bool, Packet>> traffic;
    for (const QString &line : testsupport::logLines(logPath)) {
        const QString direction = line.section(u' ', 0, 0);
        const auto bytes =
            util::parseHex(line.section(u' ', 1).section(QStringLiteral("  #"), 0, 0));
        const auto packet = bytes ? feetech::decodePacket(*bytes) : std::nullopt;
        if (packet && (direction == u"in" || direction == u"out"))
            traffic.append({direction == u"in", *packet});
    }
    return traffic;
}

} // namespace

class TestTelemetryCycle : public testsupport::FeetechLinkTest
{
    Q_OBJECT

private:
    std::unique_ptr<TelemetryCycle> m_cycle;
    QVector<FeedbackSample> m_samples;
    TelemetryStats m_stats;
    int m_cyclesEnded = 0;

    // STS3215 as 1 and 2 and an SCS15 as 3 at 1 Mbps, an SMS as 4 at 115200.
    void startBus()
    {
        auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS15"});
        servos.append({4, QStringLiteral("SMS"), k115k});
        m_timing.telemetryStatsInterval = std::chrono::milliseconds(50);
        QString error;
        QVERIFY2(startLink(busOptions(servos), &error), qPrintable(error));
        m_cycle = std::make_unique<TelemetryCycle>(*m_bus);
        m_cycle->setBusBusy([] { return false; });
        m_cycle->setCycleEnded([this] { ++m_cyclesEnded; });
        connect(m_cycle.get(), &TelemetryCycle::telemetry, this,
                [this](const QVector<FeedbackSample> &samples) { m_samples += samples; });
        connect(m_cycle.get(), &TelemetryCycle::statsChanged, this,
                [this](const TelemetryStats &stats) { m_stats = stats; });
    }

    // The options for streaming servos (id, baud) at 100 samples a second.
    feetech::TelemetryOptions options(const QVector<std::pair<quint8, qint32>> &servos)
    {
        feetech::TelemetryOptions options;
        options.rateHz = 100;
        options.missesBeforeMissing = 2;
        options.missingProbeInterval = std::chrono::milliseconds(150);
        for (const auto &[id, baud] : servos) {
            const auto info = identify(id, baud);
            if (!info)
                qWarning("servo %d at %d does not answer", id, baud);
            options.servos.append(info.value_or(feetech::ServoInfo {}));
        }
        return options;
    }

    int samplesOf(quint8 id) const
    {
        return int(std::count_if(m_samples.begin(), m_samples.end(),
                                 [id](const FeedbackSample &sample) { return sample.id == id; }));
    }

    bool isMissing(quint8 id) const
    {
        for (const feetech::ServoTelemetry &servo : m_stats.servos) {
            if (servo.id == id)
                return servo.missing;
        }
        return false;
    }

    QVector<Packet> syncReads() const
    {
        return testsupport::feetechRequestsReceived(logPath(), Instruction::SyncRead);
    }

private slots:
    void init()
    {
        m_samples.clear();
        m_stats = {};
        m_cyclesEnded = 0;
        startBus();
    }

    void cleanup()
    {
        m_cycle.reset();
        stopLink();
    }

    void everyServoGetsSamples()
    {
        m_cycle->start(options({{1, k1M}, {2, k1M}, {3, k1M}, {4, k115k}}));
        QVERIFY(m_cycle->isStreaming());
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(1) >= 3 && samplesOf(2) >= 3 && samplesOf(3) >= 3
                                     && samplesOf(4) >= 3,
                                 10000);
        for (const FeedbackSample &sample : std::as_const(m_samples)) {
            QCOMPARE(sample.baud, sample.id == 4 ? k115k : k1M);
            QVERIFY(sample.value(feetech::Quantity::Position).has_value());
        }
        QVERIFY(m_stats.running);
    }

    void eachCycleIsOneSyncReadPerRateAndOneReadPerServoWithout()
    {
        m_cycle->start(options({{1, k1M}, {2, k1M}, {3, k1M}, {4, k115k}}));
        QTRY_VERIFY_WITH_TIMEOUT(m_cyclesEnded >= 5, 10000);
        m_cycle->stop();
        int at1M = 0;
        int at115k = 0;
        for (const Packet &request : syncReads()) {
            const QVector<quint8> ids = syncReadIds(request);
            if (ids == QVector<quint8> {1, 2})
                ++at1M;
            else if (ids == QVector<quint8> {4})
                ++at115k;
            else
                QFAIL(qPrintable(
                    QStringLiteral("unexpected SYNC READ of %1 servos").arg(ids.size())));
        }
        QVERIFY(at1M >= 5);
        QVERIFY(qAbs(at1M - at115k) <= 1);
        // The SCS has no SYNC READ: it is asked alone, once a cycle.
        const int scsReads =
            testsupport::feetechRequestsReceived(logPath(), Instruction::Read, 3).size();
        QVERIFY(qAbs(scsReads - at1M) <= 1);
    }

    void aServoGoneFromTheBusIsMissingAfterItsMissesAndIsProbedNowAndThen()
    {
        m_cycle->start(options({{1, k1M}, {2, k1M}}));
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(2) >= 3, 10000);
        setSimulatorValue(2, u"id", 20); // gone from ID 2
        QTRY_VERIFY_WITH_TIMEOUT(isMissing(2), 10000);
        QVERIFY(!isMissing(1));
        // Asked in exactly missesBeforeMissing cycles after its last answer, then left out.
        const auto traffic = loggedTraffic(logPath());
        int lastAnswer = -1;
        for (int i = 0; i < traffic.size(); ++i) {
            if (!traffic.at(i).first && traffic.at(i).second.id == 2)
                lastAnswer = i;
        }
        QVERIFY(lastAnswer >= 0);
        int unanswered = 0;
        for (int i = lastAnswer + 1; i < traffic.size(); ++i) {
            const Packet &packet = traffic.at(i).second;
            if (traffic.at(i).first && packet.code == quint8(Instruction::SyncRead)
                && syncReadIds(packet).contains(2))
                ++unanswered;
        }
        QCOMPARE(unanswered, 2);

        // Then asked alone, once per probe interval, while servo 1 goes on every cycle.
        const int readsBefore =
            testsupport::feetechRequestsReceived(logPath(), Instruction::Read, 2).size();
        QTRY_VERIFY_WITH_TIMEOUT(
            testsupport::feetechRequestsReceived(logPath(), Instruction::Read, 2).size()
                >= readsBefore + 2,
            10000);
        const int probes =
            testsupport::feetechRequestsReceived(logPath(), Instruction::Read, 2).size()
            - readsBefore;
        int withoutIt = 0;
        for (const Packet &request : syncReads()) {
            if (syncReadIds(request) == QVector<quint8> {1})
                ++withoutIt;
        }
        QVERIFY2(withoutIt > probes,
                 qPrintable(QStringLiteral("%1 cycles, %2 probes").arg(withoutIt).arg(probes)));

        // Back on the bus: a probe finds it and it rejoins the cycle.
        setSimulatorValue(20, u"id", 2);
        QTRY_VERIFY_WITH_TIMEOUT(!isMissing(2), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(syncReadIds(syncReads().last()) == (QVector<quint8> {1, 2}),
                                 10000);
    }

    void stopEndsTheStreamAndTheLastStatsSayItIsNotRunning()
    {
        m_cycle->start(options({{1, k1M}, {3, k1M}}));
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(1) >= 3 && samplesOf(3) >= 3, 10000);
        QSignalSpy stats(m_cycle.get(), &TelemetryCycle::statsChanged);
        const int endedBefore = m_cyclesEnded;
        m_cycle->stop();
        QVERIFY(!m_cycle->isStreaming());
        QVERIFY(!m_cycle->inCycle());
        QVERIFY(!m_cycle->startIfDue());
        QCOMPARE(stats.size(), 1);
        const auto last = stats.first().at(0).value<TelemetryStats>();
        QVERIFY(!last.running);
        // Every sample counted was delivered: the batch still waiting went out with the stop.
        QCOMPARE(qint64(m_samples.size()), last.samples);
        // Whoever waited for the bus hears the cycle is over, even mid-cycle.
        QTRY_COMPARE_WITH_TIMEOUT(m_cyclesEnded, endedBefore + 1, 10000);
        // Nothing is asked any more: after a PING that queues behind anything still on its way,
        // the log ends with that PING.
        QVERIFY(runSteps({m_bus->ping(1, true, 0)}));
        const QVector<QByteArray> frames = testsupport::feetechFramesReceived(logPath());
        QCOMPARE(frames.last(), feetech::ping(1));
        QCOMPARE(m_samples.size(), int(last.samples));
    }

    void aBusyBusHoldsCyclesBackAndEachCycleEndIsReported()
    {
        bool busy = true;
        int asked = 0;
        m_cycle->setBusBusy([&] {
            ++asked;
            return busy;
        });
        m_cycle->start(options({{1, k1M}, {2, k1M}}));
        QTRY_VERIFY_WITH_TIMEOUT(asked >= 5, 10000);
        QVERIFY(syncReads().isEmpty());
        QCOMPARE(m_cyclesEnded, 0);
        QVERIFY(m_samples.isEmpty());
        busy = false;
        QTRY_VERIFY_WITH_TIMEOUT(m_cyclesEnded >= 3, 10000);
        QVERIFY(!syncReads().isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(1) >= 3 && samplesOf(2) >= 3, 10000);
        m_cycle->stop();
        m_cycle->setBusBusy([] { return false; }); // `busy` and `asked` go out of scope
    }
};

QTEST_GUILESS_MAIN(TestTelemetryCycle)
#include "tst_telemetrycycle.moc"
