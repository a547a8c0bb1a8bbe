// A program's SYNC READ loop (blocking, like the vendors' SDKs) on 6 simulated STS3215 at 1 Mbps,
// straight on the simulator's port and then through a share, in one run: the rate the share
// keeps and the round trip it adds. Prints JSON.
#include "benchsupport.h"
#include "blockingclient.h"
#include "busshare.h"
#include "eventloops.h"
#include "feetechdescription.h"
#include "feetechpacket.h"
#include "linksession.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <future>

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kServos = 6;
constexpr double kRunSeconds = 4.0;

struct LoopRun
{
    int cycles = 0;
    int incomplete = 0;
    double seconds = 0;
    double medianRoundTripUs = 0;
    double slowRoundTripUs = 0; // the 95th percentile: the loop's rate feels its slow end too
};

// SYNC READs of the feedback block of every servo, back to back, for kRunSeconds.
LoopRun syncReadLoop(const QString &path)
{
    LoopRun run;
    bench::BlockingClient program;
    if (!program.open(path, k1M)) {
        std::fprintf(stderr, "bench_share: %s: %s\n", qPrintable(path),
                     qPrintable(program.error()));
        return run;
    }
    QVector<quint8> ids;
    for (int id = 1; id <= kServos; ++id)
        ids.append(quint8(id));
    const QByteArray request = feetech::syncRead(56, 15, ids);
    std::vector<double> roundTrips;
    QElapsedTimer clock;
    clock.start();
    while (clock.nsecsElapsed() < qint64(kRunSeconds * 1e9)) {
        const qint64 before = clock.nsecsElapsed();
        const QVector<QByteArray> answers = program.exchange(request, kServos);
        roundTrips.push_back(double(clock.nsecsElapsed() - before) / 1e3);
        if (answers.size() == kServos)
            ++run.cycles;
        else
            ++run.incomplete;
    }
    run.seconds = double(clock.nsecsElapsed()) / 1e9;
    std::sort(roundTrips.begin(), roundTrips.end());
    if (!roundTrips.empty()) {
        run.medianRoundTripUs = roundTrips[roundTrips.size() / 2];
        run.slowRoundTripUs = roundTrips[roundTrips.size() * 95 / 100];
    }
    return run;
}

// Runs the loop in a thread of its own while this thread's event loop (the share's) goes on.
LoopRun runBeside(const QString &path)
{
    auto done = std::async(std::launch::async, [path] { return syncReadLoop(path); });
    while (done.wait_for(std::chrono::milliseconds(0)) != std::future_status::ready)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 20);
    return done.get();
}

QJsonObject describe(const LoopRun &run)
{
    return {{QStringLiteral("cycles_per_s"), run.cycles / run.seconds},
            {QStringLiteral("samples_per_s"), run.cycles * kServos / run.seconds},
            {QStringLiteral("incomplete"), run.incomplete},
            {QStringLiteral("median_round_trip_us"), run.medianRoundTripUs},
            {QStringLiteral("p95_round_trip_us"), run.slowRoundTripUs}};
}

} // namespace

int main(int argc, char **argv)
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    sim::SimulatorThread simulator;
    QString error;
    if (!simulator.start(bench::stsBusOptions(dir, kServos, k1M), &error)) {
        std::fprintf(stderr, "bench_share: %s\n", qPrintable(error));
        return 1;
    }
    const LoopRun direct = runBeside(simulator.linkPath());

    static const feetech::FrameFormat format;
    seriallink::LinkSession link(format, feetech::describeFrame);
    if (!link.open(simulator.linkPath(), k1M, seriallink::EchoMode::Off)) {
        std::fprintf(stderr, "bench_share: %s\n", qPrintable(link.status().message));
        return 1;
    }
    share::BusShare shared(link);
    share::ShareOptions options;
    options.linkPath = dir.filePath(QStringLiteral("program"));
    const QString refused = shared.start(options);
    if (!refused.isEmpty()) {
        std::fprintf(stderr, "bench_share: %s\n", qPrintable(refused));
        return 1;
    }
    const LoopRun through = runBeside(options.linkPath);
    shared.stop();

    const double ratio = direct.cycles > 0
        ? (through.cycles / through.seconds) / (direct.cycles / direct.seconds)
        : 0.0;
    const QJsonObject figures {
        {QStringLiteral("servos"), kServos},
        {QStringLiteral("baud"), k1M},
        {QStringLiteral("direct"), describe(direct)},
        {QStringLiteral("shared"), describe(through)},
        {QStringLiteral("shared_rate_ratio"), ratio},
        {QStringLiteral("added_round_trip_us"),
         through.medianRoundTripUs - direct.medianRoundTripUs},
    };
    std::printf("%s\n", QJsonDocument(figures).toJson(QJsonDocument::Compact).constData());
    return 0;
}
