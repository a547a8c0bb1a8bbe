// Runs the PTK session against the simulated servo at 115200 baud and prints JSON figures: poll
// interval against PTK's 50 ms, fast-mode sweep time against the wire limit, CPU per second.
#include "benchsupport.h"
#include "eventloops.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "ptksession.h"
#include "simulatorthread.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace {

constexpr qint32 kBaud = 115200;
constexpr int kPolledSeconds = 6;
constexpr int kFastSeconds = 3;

using bench::threadCpuMs;

QJsonObject spread(QVector<double> samples, const QString &unit)
{
    if (samples.isEmpty())
        return {{QStringLiteral("error"), QStringLiteral("no samples")}};
    std::sort(samples.begin(), samples.end());
    return {{QStringLiteral("samples"), int(samples.size())},
            {QStringLiteral("median_") + unit, samples.at(samples.size() / 2)},
            {QStringLiteral("p99_") + unit, samples.at(samples.size() * 99 / 100)},
            {QStringLiteral("max_") + unit, samples.last()}};
}

// Times between consecutive frames sent with `command` (any query when 0), in ms.
QVector<double> intervals(const QVector<std::pair<quint8, qint64>> &sent, quint8 command)
{
    QVector<double> result;
    qint64 last = -1;
    for (const auto &[sentCommand, ns] : sent) {
        if (command != 0 && sentCommand != command)
            continue;
        if (last >= 0)
            result.append(double(ns - last) / 1e6);
        last = ns;
    }
    return result;
}

void runFor(int seconds)
{
    QEventLoop loop;
    QTimer::singleShot(seconds * 1000, &loop, &QEventLoop::quit);
    loop.exec();
}

} // namespace

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    sim::SimulatorOptions options;
    options.kind = sim::SimulatorOptions::Kind::Ptk;
    options.linkPath = dir.filePath(QStringLiteral("ptk"));
    options.echo = true; // PTK's programmer is a single-wire adapter: every byte comes back
    sim::SimulatorThread simulator;
    QString error;
    if (!simulator.start(options, &error)) {
        std::fprintf(stderr, "bench_ptk: %s\n", qPrintable(error));
        return 1;
    }

    ptk::Session session;
    QElapsedTimer clock;
    clock.start();
    QVector<std::pair<quint8, qint64>> sent;
    QObject::connect(&session, &ptk::Session::packetLogged,
                     [&](const seriallink::PacketLogEntry &entry) {
                         if (entry.direction == seriallink::Direction::Out
                             && entry.bytes.size() == ptk::kRequestSize)
                             sent.append({quint8(entry.bytes.at(4)), clock.nsecsElapsed()});
                     });
    session.open(simulator.linkPath(), kBaud, seriallink::EchoMode::Auto);

    // PTK's own cadence.
    runFor(1); // settle: the first answers, echo detection
    sent.clear();
    const double cpuBefore = threadCpuMs();
    const qint64 wallBefore = clock.nsecsElapsed();
    runFor(kPolledSeconds);
    const double cpuMs = threadCpuMs() - cpuBefore;
    const double wallS = double(clock.nsecsElapsed() - wallBefore) / 1e9;
    const auto polled = sent;
    const auto pollCounters = session.counters();

    // Back to back.
    session.setPollInterval(0, true);
    runFor(1);
    sent.clear();
    runFor(kFastSeconds);
    const auto fast = sent;
    const auto fastCounters = session.counters();
    session.close();

    const double wireLimitMs =
        double(ptk::queryLayouts().size()) * (ptk::kRequestSize + ptk::kReplySize) * 10e3 / kBaud;
    QJsonObject interval = spread(intervals(polled, 0), QStringLiteral("ms"));
    interval.insert(QStringLiteral("target_ms"), 50);
    QJsonObject sweep =
        spread(intervals(fast, ptk::queryLayouts().front().command), QStringLiteral("ms"));
    sweep.insert(QStringLiteral("wire_limit_ms"), wireLimitMs);
    const QJsonObject result {
        {QStringLiteral("baud"), kBaud},
        {QStringLiteral("adapter_echo"), true},
        {QStringLiteral("poll_interval"), interval},
        {QStringLiteral("fast_sweep"), sweep},
        {QStringLiteral("cpu_ms_per_s_polling"), cpuMs / wallS},
        {QStringLiteral("polling_timeouts"), pollCounters.timeouts},
        {QStringLiteral("fast_timeouts"), fastCounters.timeouts - pollCounters.timeouts},
        {QStringLiteral("replies_ok"), fastCounters.repliesOk},
    };
    std::printf("%s", QJsonDocument(result).toJson(QJsonDocument::Indented).constData());
    return 0;
}
