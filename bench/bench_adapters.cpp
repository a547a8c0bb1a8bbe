// Runs the timing-sensitive work under every USB adapter profile of the simulator and prints JSON:
// per profile, a scan of IDs 0-253, table reads, telemetry at 50 Hz and as fast as the bus
// allows (samples, misses, late answers), PTK polling and an Apply, and the link's timeouts.
//
//   bench_adapters [--seconds N] [--profile NAME]... [--demo-seconds N]
//
// --seconds: how long each stream and the PTK polling run (default 10). --profile: only these
// (default: ideal, ftdi, ftdi-1ms, ch340, ch343, cp2102). --demo-seconds N: instead, the demo's
// own Feetech bus (servobench --demo-feetech), scanned and streamed at 50 Hz for N seconds.
#include "benchsupport.h"
#include "busoperations.h"
#include "demoservos.h"
#include "eventloops.h"
#include "feetechsession.h"
#include "ptksession.h"
#include "simulatorthread.h"
#include "usbadapter.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kServos = 6;
constexpr int kTableReads = 9;
constexpr double kStreamRateHz = 50.0;

struct Options
{
    int seconds = 10;
    QStringList profiles = sim::adapterProfileNames();
    int demoSeconds = 0;
};

std::optional<Options> parse(const QStringList &arguments)
{
    Options options;
    QStringList profiles;
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &option = arguments.at(i);
        if (i + 1 >= arguments.size())
            return std::nullopt;
        const QString value = arguments.at(++i);
        bool ok = false;
        if (option == QLatin1String("--seconds")) {
            options.seconds = value.toInt(&ok);
        } else if (option == QLatin1String("--demo-seconds")) {
            options.demoSeconds = value.toInt(&ok);
        } else if (option == QLatin1String("--profile")) {
            ok = sim::adapterProfileNames().contains(value);
            profiles.append(value);
        }
        if (!ok || options.seconds < 1 || options.demoSeconds < 0)
            return std::nullopt;
    }
    if (!profiles.isEmpty())
        options.profiles = profiles;
    return options;
}

QJsonObject describe(const bench::StreamRun &run)
{
    return {
        {QStringLiteral("rate_hz"),
         run.rateHz > 0 ? QJsonValue(run.rateHz) : QJsonValue(QStringLiteral("max"))},
        {QStringLiteral("seconds"), run.seconds},
        {QStringLiteral("samples_per_s"), double(run.samples) / run.seconds},
        {QStringLiteral("missed"), run.missed},
        {QStringLiteral("late"), run.late},
    };
}

QJsonObject counters(const seriallink::LinkCounters &counters)
{
    return {
        {QStringLiteral("timeouts"), counters.timeouts},
        {QStringLiteral("failures"), counters.failures},
        {QStringLiteral("late_replies"), counters.lateReplies},
        {QStringLiteral("checksum_errors"), counters.checksumErrors},
    };
}

// Scans IDs 0-253 at 1 Mbps on a freshly opened port; the servos found, or none on a failure.
QVector<feetech::ServoInfo> scan(feetech::Session &session, QJsonObject *figures)
{
    QVector<feetech::ServoInfo> found;
    const auto gotServo =
        QObject::connect(&session, &feetech::Session::servoFound,
                         [&found](const feetech::ServoInfo &servo) { found.append(servo); });
    bench::Waiter waiter;
    bool completed = false;
    const auto finished =
        QObject::connect(&session, &feetech::Session::scanFinished, [&](bool ok, const QString &) {
            completed = ok;
            waiter.finish();
        });
    QElapsedTimer clock;
    clock.start();
    session.submit(feetech::operations::scan(feetech::ScanOptions {}));
    waiter.wait(120000);
    figures->insert(QStringLiteral("scan_ms"), double(clock.nsecsElapsed()) / 1e6);
    figures->insert(QStringLiteral("scan_completed"), completed);
    figures->insert(QStringLiteral("scan_found"), int(found.size()));
    QObject::disconnect(gotServo);
    QObject::disconnect(finished);
    return found;
}

// Reads the servo's whole table several times; the median time and how many failed.
void readTables(feetech::Session &session, const feetech::ServoInfo &servo, QJsonObject *figures)
{
    std::vector<double> times;
    int failed = 0;
    for (int i = 0; i < kTableReads; ++i) {
        bench::Waiter waiter;
        bool ok = false;
        const auto connection = QObject::connect(&session, &feetech::Session::operationFinished,
                                                 [&](const feetech::OperationResult &result) {
                                                     ok = result.ok;
                                                     waiter.finish();
                                                 });
        QElapsedTimer clock;
        clock.start();
        session.submit(feetech::operations::read(servo, {}, feetech::ReadSource::Read));
        waiter.wait(10000);
        QObject::disconnect(connection);
        if (ok)
            times.push_back(double(clock.nsecsElapsed()) / 1e6);
        else
            ++failed;
    }
    std::sort(times.begin(), times.end());
    figures->insert(QStringLiteral("table_read_median_ms"),
                    times.empty() ? -1.0 : times.at(times.size() / 2));
    figures->insert(QStringLiteral("table_reads_failed"), failed);
}

// Starts the simulator behind the adapter `profile`; false, with the error in `figures`, when
// it would not start.
bool startBehind(sim::SimulatorThread &simulator, sim::SimulatorOptions options,
                 const QString &profile, QJsonObject *figures)
{
    options.adapter = sim::adapterProfile(profile);
    QString error;
    if (simulator.start(options, &error))
        return true;
    figures->insert(QStringLiteral("error"), error);
    return false;
}

QJsonObject feetechRun(const QString &profile, int seconds)
{
    QJsonObject figures;
    QTemporaryDir dir;
    sim::SimulatorThread simulator;
    if (!startBehind(simulator, bench::stsBusOptions(dir, kServos, k1M), profile, &figures))
        return figures;
    feetech::Session session;
    session.open(simulator.linkPath(), k1M, seriallink::EchoMode::Auto);
    const QVector<feetech::ServoInfo> servos = scan(session, &figures);
    if (servos.isEmpty())
        return figures;
    readTables(session, servos.first(), &figures);
    QJsonArray streams;
    for (const double rate : {kStreamRateHz, 0.0})
        streams.append(describe(bench::streamTelemetry(session, servos, rate, seconds)));
    figures.insert(QStringLiteral("telemetry"), streams);
    // Scans wait for silence on purpose; their timeouts are not counted here.
    figures.insert(QStringLiteral("link"), counters(session.counters()));
    return figures;
}

QJsonObject ptkRun(const QString &profile, int seconds)
{
    QJsonObject figures;
    QTemporaryDir dir;
    sim::SimulatorOptions options;
    options.kind = sim::SimulatorOptions::Kind::Ptk;
    options.linkPath = dir.filePath(QStringLiteral("ptk"));
    options.echo = true; // PTK's programmer is a single-wire adapter
    sim::SimulatorThread simulator;
    if (!startBehind(simulator, options, profile, &figures))
        return figures;
    ptk::Session session;
    qint64 answers = 0;
    ptk::ParameterSet values; // each answer carries some parameters; together, all of them
    QObject::connect(&session, &ptk::Session::valuesRead,
                     [&](const ptk::ParameterSet &read, ptk::ReadSource) {
                         ++answers;
                         for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
                             if (const auto value = read.value(meta.parameter))
                                 values.set(meta.parameter, *value);
                         }
                     });
    session.open(simulator.linkPath(), 115200, seriallink::EchoMode::Auto);
    session.setPolling(true);
    bench::Waiter().wait(seconds * 1000);
    session.setPolling(false);
    figures.insert(QStringLiteral("polled_sets_per_s"), double(answers) / seconds);
    bool applied = false;
    if (values.isComplete()) {
        bench::Waiter waiter;
        QObject::connect(&session, &ptk::Session::applyFinished, [&](bool ok, const QString &) {
            applied = ok;
            waiter.finish();
        });
        session.apply(values);
        waiter.wait(20000);
    }
    figures.insert(QStringLiteral("apply_verified"), applied);
    figures.insert(QStringLiteral("link"), counters(session.counters()));
    return figures;
}

QJsonObject demoRun(int seconds)
{
    QJsonObject figures;
    sim::DemoServos demo;
    sim::SimRefusal why;
    const QString port = demo.feetechPort(&why);
    if (port.isEmpty()) {
        figures.insert(QStringLiteral("error"), why.describe());
        return figures;
    }
    feetech::Session session;
    session.open(port, k1M, seriallink::EchoMode::Auto);
    const QVector<feetech::ServoInfo> servos = scan(session, &figures);
    if (servos.isEmpty())
        return figures;
    figures.insert(QStringLiteral("telemetry"),
                   describe(bench::streamTelemetry(session, servos, kStreamRateHz, seconds)));
    figures.insert(QStringLiteral("link"), counters(session.counters()));
    return figures;
}

} // namespace

int main(int argc, char **argv)
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    const auto options = parse(QCoreApplication::arguments().mid(1));
    if (!options) {
        std::fprintf(stderr,
                     "usage: bench_adapters [--seconds N] [--profile NAME]... "
                     "[--demo-seconds N]\n");
        return 2;
    }
    QJsonObject report;
    if (options->demoSeconds > 0) {
        report.insert(QStringLiteral("demo_feetech"), demoRun(options->demoSeconds));
    } else {
        QJsonObject profiles;
        for (const QString &profile : options->profiles) {
            std::fprintf(stderr, "bench_adapters: %s\n", qPrintable(profile));
            profiles.insert(
                profile,
                QJsonObject {{QStringLiteral("feetech"), feetechRun(profile, options->seconds)},
                             {QStringLiteral("ptk"), ptkRun(profile, options->seconds)}});
        }
        report.insert(QStringLiteral("servos"), kServos);
        report.insert(QStringLiteral("baud"), k1M);
        report.insert(QStringLiteral("profiles"), profiles);
    }
    std::printf("%s", QJsonDocument(report).toJson(QJsonDocument::Indented).constData());
    return 0;
}
