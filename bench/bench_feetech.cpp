// Runs the Feetech session against the simulated bus on a pty and prints JSON figures: scan time
// at one and at every baud rate, and full table reads, each next to its wire-time lower bound.
#include "benchsupport.h"
#include "busoperations.h"
#include "eventloops.h"
#include "feetechpacket.h"
#include "feetechsession.h"
#include "modeltable.h"
#include "registertable.h"
#include "simulatorthread.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;
constexpr int kStsCount = 6; // STS3215, IDs 1-6 at 1 Mbps
constexpr quint8 kSmsId = 7; // one SMS at 115200
constexpr int kIdCount = feetech::kMaxServoId + 1; // IDs 0-253
constexpr int kScanRepeats = 5;
constexpr int kAllBaudRepeats = 3;
constexpr int kThoroughRepeats = 1; // about 7 s each: every ID at every rate
constexpr int kTableReads = 200;
constexpr int kWarmUpReads = 5;
// What the vendor's C++ SDK waits for a missing reply (spec §11, §12).
constexpr double kVendorTimeoutMs = 100.0;
constexpr int kPingSize = 6; // request and reply
constexpr int kReadRequestSize = 8;
constexpr int kIdentityReplySize = 6 + 9; // addresses 0-8

using bench::Waiter;
using bench::wireMs;

struct ScanRun
{
    double wallMs = 0;
    bool completed = false;
    int found = 0;
    int probes = 0;
    double probePhaseMs = 0; // until the first PING to one ID went out
    qint64 framesSent = 0;
    qint64 timeouts = 0;
    qint64 checksumErrors = 0;
    qint64 latencyUs = -1;
    qint64 allowanceUs = 0;
};

// Every scan starts on a freshly opened port, as a user's first scan does: nothing measured yet.
class Bench
{
public:
    explicit Bench(const QString &link)
        : m_link(link)
    {
        QObject::connect(&m_session, &feetech::Session::servoFound,
                         [this](const feetech::ServoInfo &servo) { m_found.append(servo); });
        QObject::connect(&m_session, &feetech::Session::packetLogged,
                         [this](const seriallink::PacketLogEntry &entry) {
                             if (entry.direction == seriallink::Direction::In)
                                 m_wireBytes += entry.bytes.size();
                             if (entry.direction != seriallink::Direction::Out)
                                 return;
                             ++m_framesOut;
                             m_wireBytes += entry.bytes.size();
                             if (entry.bytes.size() <= 2)
                                 return;
                             if (quint8(entry.bytes.at(2)) == feetech::kBroadcastId)
                                 ++m_broadcastsOut;
                             else if (m_firstUnicastNs < 0)
                                 m_firstUnicastNs = m_clock.nsecsElapsed();
                         });
    }

    bool reopen()
    {
        m_session.open(m_link, k1M, seriallink::EchoMode::Auto);
        return m_session.status().state == seriallink::ConnectionState::Connected;
    }

    ScanRun scan(const feetech::ScanOptions &options)
    {
        ScanRun run;
        if (!reopen())
            return run;
        m_found.clear();
        m_broadcastsOut = 0;
        m_firstUnicastNs = -1;
        Waiter waiter;
        const auto connection = QObject::connect(&m_session, &feetech::Session::scanFinished,
                                                 [&](bool completed, const QString &) {
                                                     run.completed = completed;
                                                     waiter.finish();
                                                 });
        m_clock.start();
        m_session.submit(feetech::operations::scan(options));
        waiter.wait(60000);
        run.wallMs = double(m_clock.nsecsElapsed()) / 1e6;
        run.probePhaseMs = double(m_firstUnicastNs) / 1e6;
        QObject::disconnect(connection);
        run.found = int(m_found.size());
        run.probes = m_broadcastsOut;
        run.framesSent = m_session.counters().framesSent;
        run.timeouts = m_session.counters().timeouts;
        run.checksumErrors = m_session.counters().checksumErrors;
        if (const auto latency = m_session.measuredLatency())
            run.latencyUs = latency->count();
        run.allowanceUs = m_session.scanAllowance().count();
        return run;
    }

    struct TableRead
    {
        double ms = -1; // negative: the read failed
        int reads = 0; // READs sent
        qint64 wireBytes = 0; // requests and replies as they crossed the wire
    };

    // One full table read: its wall time, the READs it sent and the bytes they moved.
    TableRead readTable(const feetech::ServoInfo &servo)
    {
        Waiter waiter;
        bool ok = false;
        const auto connection = QObject::connect(&m_session, &feetech::Session::operationFinished,
                                                 [&](const feetech::OperationResult &result) {
                                                     ok = result.ok;
                                                     waiter.finish();
                                                 });
        const qint64 framesBefore = m_framesOut;
        const qint64 bytesBefore = m_wireBytes;
        QElapsedTimer clock;
        clock.start();
        m_session.submit(feetech::operations::read(servo, {}, feetech::ReadSource::Read));
        waiter.wait(5000);
        const double ms = double(clock.nsecsElapsed()) / 1e6;
        QObject::disconnect(connection);
        return {ok ? ms : -1.0, int(m_framesOut - framesBefore), m_wireBytes - bytesBefore};
    }

    const QVector<feetech::ServoInfo> &found() const { return m_found; }

private:
    QString m_link;
    feetech::Session m_session;
    QVector<feetech::ServoInfo> m_found;
    qint64 m_framesOut = 0;
    qint64 m_wireBytes = 0; // frames sent and received (not echoes)
    int m_broadcastsOut = 0;
    QElapsedTimer m_clock;
    qint64 m_firstUnicastNs = -1;
};

double percentile(QVector<double> samples, int percent)
{
    std::sort(samples.begin(), samples.end());
    return samples.at((samples.size() - 1) * percent / 100);
}

// Bytes that must cross the wire at one rate: the probes and their (collided) answers, a PING
// per ID, each present servo's answer and its identity READ.
double scanWireMs(qint32 baud, int servos, int probes)
{
    if (probes > 0 && servos == 0)
        return wireMs(qint64(probes) * kPingSize, baud); // nothing answers: no sweep
    const qint64 bytes = qint64(probes) * 2 * kPingSize + qint64(kIdCount) * kPingSize
        + qint64(servos) * (kPingSize + kReadRequestSize + kIdentityReplySize);
    return wireMs(bytes, baud);
}

QJsonObject summarise(const QVector<ScanRun> &runs, double wireBoundMs, int missingIds)
{
    QVector<double> walls;
    QVector<double> probePhases;
    QJsonArray latencies;
    QJsonArray allowances;
    QJsonArray found;
    bool completed = true;
    for (const ScanRun &run : runs) {
        walls.append(run.wallMs);
        probePhases.append(run.probePhaseMs);
        latencies.append(run.latencyUs);
        allowances.append(run.allowanceUs);
        found.append(run.found);
        completed = completed && run.completed;
    }
    const double median = percentile(walls, 50);
    return {
        {QStringLiteral("repeats"), int(runs.size())},
        {QStringLiteral("completed"), completed},
        {QStringLiteral("found"), found},
        {QStringLiteral("median_ms"), median},
        {QStringLiteral("max_ms"), percentile(walls, 100)},
        {QStringLiteral("wire_lower_bound_ms"), wireBoundMs},
        {QStringLiteral("median_over_wire"), median / wireBoundMs},
        {QStringLiteral("vendor_reference_ms"), missingIds * kVendorTimeoutMs},
        {QStringLiteral("vendor_reference"),
         QStringLiteral("%1 missing IDs x 100 ms (Feetech C++ SDK timeout, spec §11/§12)")
             .arg(missingIds)},
        {QStringLiteral("broadcast_probes_sent"), runs.last().probes},
        {QStringLiteral("median_ms_before_first_unicast_ping"), percentile(probePhases, 50)},
        {QStringLiteral("frames_sent"), runs.last().framesSent},
        {QStringLiteral("timeouts"), runs.last().timeouts},
        {QStringLiteral("checksum_errors"), runs.last().checksumErrors},
        {QStringLiteral("measured_latency_us_after_scan"), latencies},
        {QStringLiteral("scan_allowance_us_after_scan"), allowances},
    };
}

} // namespace

// With no argument every group runs; naming groups (scan_1M, all_bauds, table_read) runs only
// those, e.g. to profile one of them (table_read alone still scans once to find its servo).
int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    const QStringList groups = QCoreApplication::arguments().mid(1);
    const auto wanted = [&groups](const QString &group) {
        return groups.isEmpty() || groups.contains(group);
    };
    QTemporaryDir dir;
    sim::SimulatorOptions options = bench::stsBusOptions(dir, kStsCount, k1M);
    options.servos.append({kSmsId, QStringLiteral("SMS"), k115k});
    sim::SimulatorThread simulator;
    QString error;
    if (!simulator.start(options, &error)) {
        std::fprintf(stderr, "bench_feetech: %s\n", qPrintable(error));
        return 1;
    }
    Bench bench(simulator.linkPath());
    const std::map<qint32, int> servosAt {{k1M, kStsCount}, {k115k, 1}};
    const int servoCount = kStsCount + 1;

    // 1. IDs 0-253 at 1 Mbps.
    feetech::ScanOptions oneRate;
    QVector<ScanRun> runs;
    const int scanRepeats = wanted(QStringLiteral("scan_1M")) ? kScanRepeats : 1;
    for (int i = 0; i < scanRepeats; ++i)
        runs.append(bench.scan(oneRate));
    std::optional<feetech::ServoInfo> sts;
    for (const feetech::ServoInfo &servo : bench.found()) {
        if (servo.id == 1)
            sts = servo;
    }
    QJsonObject scan1M =
        summarise(runs, scanWireMs(k1M, kStsCount, runs.last().probes), kIdCount - kStsCount);
    scan1M.insert(QStringLiteral("servos_present"), kStsCount);
    // What one PING costs once the probes are done: mostly the timeout of a missing ID.
    const double sweepMs = scan1M.value(QStringLiteral("median_ms")).toDouble()
        - scan1M.value(QStringLiteral("median_ms_before_first_unicast_ping")).toDouble();
    scan1M.insert(QStringLiteral("ping_sweep_ms_per_id"), sweepMs / kIdCount);

    // 2. Every ID at every rate, with and without the broadcast probe.
    QJsonObject allBauds;
    for (const bool skipSilentRates : {true, false}) {
        if (!wanted(QStringLiteral("all_bauds")))
            break;
        feetech::ScanOptions everyRate;
        everyRate.bauds = feetech::baudRates();
        everyRate.skipSilentRates = skipSilentRates;
        QVector<ScanRun> baudRuns;
        for (int i = 0; i < (skipSilentRates ? kAllBaudRepeats : kThoroughRepeats); ++i)
            baudRuns.append(bench.scan(everyRate));
        double bound = 0;
        for (const qint32 baud : everyRate.bauds) {
            const int servos = servosAt.count(baud) ? servosAt.at(baud) : 0;
            // The session probes twice where something answers, once where nothing does; a
            // thorough scan still probes (to measure the line) but asks every ID regardless.
            const int probes = servos > 0 ? 2 : 1;
            bound += skipSilentRates ? scanWireMs(baud, servos, probes)
                                     : scanWireMs(baud, servos, 0)
                    + wireMs(qint64(probes) * (servos > 0 ? 2 : 1) * kPingSize, baud);
        }
        const int missing = kIdCount * int(everyRate.bauds.size()) - servoCount;
        allBauds.insert(skipSilentRates ? QStringLiteral("probe_first")
                                        : QStringLiteral("thorough_every_id"),
                        summarise(baudRuns, bound, missing));
    }
    allBauds.insert(QStringLiteral("servos_present"),
                    QStringLiteral("%1 STS3215 at 1 Mbps, 1 SMS at 115200").arg(kStsCount));

    // 3. Full table reads of one STS3215.
    QJsonObject tableRead;
    if (!wanted(QStringLiteral("table_read"))) {
        tableRead.insert(QStringLiteral("skipped"), true);
    } else if (!sts || !bench.reopen()) {
        tableRead.insert(QStringLiteral("error"), QStringLiteral("STS3215 ID 1 not found"));
    } else {
        const QVector<feetech::Block> blocks = sts->table().blocks();
        qint64 bytes = 0;
        QJsonArray blockList;
        for (const feetech::Block &block : blocks) {
            bytes += kReadRequestSize + 6 + block.size;
            blockList.append(QStringLiteral("%1+%2").arg(block.address).arg(block.size));
        }
        for (int i = 0; i < kWarmUpReads; ++i)
            bench.readTable(*sts);
        QVector<double> samples;
        int transactions = 0;
        qint64 bytesMoved = 0;
        int failures = 0;
        for (int i = 0; i < kTableReads; ++i) {
            const Bench::TableRead read = bench.readTable(*sts);
            transactions = read.reads;
            bytesMoved = read.wireBytes;
            if (read.ms < 0)
                ++failures;
            else
                samples.append(read.ms);
        }
        tableRead = {
            {QStringLiteral("model"), sts->model.name},
            {QStringLiteral("reads"), kTableReads},
            {QStringLiteral("failures"), failures},
            {QStringLiteral("blocks"), blockList},
            {QStringLiteral("read_transactions_per_table_read"), transactions},
            {QStringLiteral("wire_bytes_per_table_read"), bytes},
            {QStringLiteral("wire_lower_bound_ms"), wireMs(bytes, k1M)},
            // What the READs sent really moved: less than the bound (one READ per block) when
            // the session reads several blocks in one.
            {QStringLiteral("wire_bytes_moved_per_table_read"), bytesMoved},
            {QStringLiteral("wire_ms_moved_per_table_read"), wireMs(bytesMoved, k1M)},
        };
        if (!samples.isEmpty()) {
            tableRead.insert(QStringLiteral("median_ms"), percentile(samples, 50));
            tableRead.insert(QStringLiteral("p99_ms"), percentile(samples, 99));
            tableRead.insert(QStringLiteral("max_ms"), percentile(samples, 100));
        }
    }

    const QJsonObject result {
        {QStringLiteral("link"), QStringLiteral("servosim on a pty, in process")},
        {QStringLiteral("echo_mode"), QStringLiteral("auto")},
        {QStringLiteral("scan_ids_0_253_at_1M"), scan1M},
        {QStringLiteral("scan_ids_0_253_all_8_bauds"), allBauds},
        {QStringLiteral("table_read_1M"), tableRead},
    };
    std::printf("%s", QJsonDocument(result).toJson(QJsonDocument::Indented).constData());
    return 0;
}
