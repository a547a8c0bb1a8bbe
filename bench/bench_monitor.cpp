// Runs Feetech telemetry against 6 simulated STS3215 at 1 Mbps on a pty and prints JSON figures:
// samples per second as fast as the bus allows and at set rates, next to the wire limit.
#include "benchsupport.h"
#include "busoperations.h"
#include "eventloops.h"
#include "feetechsession.h"
#include "simulatorthread.h"
#include "telemetry.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cstdio>

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kServos = 6;
constexpr int kRunSeconds = 5;
constexpr int kSyncReadRequestSize = 8; // header, ID, length, instruction, address, size, checksum
constexpr int kStatusOverhead = 6; // header, ID, length, error, checksum
// The vendor tool: one servo, about 30 Hz, on its GUI thread (issue 6).
constexpr double kVendorSamplesPerSecond = 30.0;

QJsonObject describe(const bench::StreamRun &run, double wireLimitCyclesPerSecond)
{
    const double samplesPerSecond = double(run.samples) / run.seconds;
    QJsonObject figures {
        {QStringLiteral("rate_hz"),
         run.rateHz > 0 ? QJsonValue(run.rateHz) : QJsonValue(QStringLiteral("max"))},
        {QStringLiteral("seconds"), run.seconds},
        {QStringLiteral("samples_per_s"), samplesPerSecond},
        {QStringLiteral("cycles_per_s"), double(run.cycles) / run.seconds},
        {QStringLiteral("missed"), run.missed},
        {QStringLiteral("late"), run.late},
        {QStringLiteral("session_cpu_ms_per_s"), run.cpuMs / run.seconds},
    };
    if (run.rateHz <= 0)
        figures.insert(QStringLiteral("share_of_wire_limit"),
                       double(run.cycles) / run.seconds / wireLimitCyclesPerSecond);
    return figures;
}

} // namespace

int main(int argc, char **argv)
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    sim::SimulatorOptions options = bench::stsBusOptions(dir, kServos, k1M);
    sim::SimulatorThread simulator;
    QString error;
    if (!simulator.start(options, &error)) {
        std::fprintf(stderr, "bench_monitor: %s\n", qPrintable(error));
        return 1;
    }
    feetech::Session session;
    session.open(simulator.linkPath(), k1M, seriallink::EchoMode::Off);
    QVector<feetech::ServoInfo> servos;
    const auto found =
        QObject::connect(&session, &feetech::Session::servoFound,
                         [&servos](const feetech::ServoInfo &s) { servos.append(s); });
    bench::Waiter scanned;
    QObject::connect(&session, &feetech::Session::scanFinished, [&scanned] { scanned.finish(); });
    feetech::ScanOptions scan;
    scan.lastId = kServos;
    session.submit(feetech::operations::scan(scan));
    scanned.wait(30000);
    QObject::disconnect(found);
    if (servos.size() != kServos) {
        std::fprintf(stderr, "bench_monitor: found %d of %d servos\n", int(servos.size()), kServos);
        return 1;
    }

    // One cycle: the SYNC READ request (plus one ID byte per servo) and every servo's answer.
    const qint64 cycleBytes = kSyncReadRequestSize + kServos
        + qint64(kServos)
            * (kStatusOverhead
               + feetech::RegisterTable::forFamily(feetech::Family::Sts).feedbackBlock().size);
    const double cycleWireMs = bench::wireMs(cycleBytes, k1M);
    const double wireCyclesPerSecond = 1000.0 / cycleWireMs;

    QJsonArray runs;
    for (const double rate : {0.0, 100.0, 50.0})
        runs.append(describe(bench::streamTelemetry(session, servos, rate, kRunSeconds),
                             wireCyclesPerSecond));
    const QJsonObject report {
        {QStringLiteral("servos"), kServos},
        {QStringLiteral("baud"), k1M},
        {QStringLiteral("cycle_bytes"), cycleBytes},
        {QStringLiteral("cycle_wire_ms"), cycleWireMs},
        {QStringLiteral("wire_limit_samples_per_s"), wireCyclesPerSecond * kServos},
        {QStringLiteral("vendor_tool_samples_per_s"), kVendorSamplesPerSecond},
        {QStringLiteral("runs"), runs},
    };
    std::printf("%s", QJsonDocument(report).toJson(QJsonDocument::Indented).constData());
    return 0;
}
