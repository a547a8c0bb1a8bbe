// Measures the GUI process while its Monitor page plots six servos (50 Hz unless --rate): CPU of
// the whole process and of the GUI thread, the plot's frames (how many, how long each took), and
// resident memory early and late in the run.
// The simulated servos run in a separate servosim process, so their work is not counted.
#include "benchsupport.h"
#include "busclient.h"
#include "eventloops.h"
#include "monitorpage.h"
#include "processmemory.h"
#include "telemetryplot.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QScopeGuard>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

constexpr int kServos = 6;
constexpr double kDefaultRateHz = 50.0; // --rate HZ changes it
constexpr int kWarmUpSeconds = 3;
constexpr int kMeasureSeconds = 10;
constexpr int kSecondHalfSeconds = 20; // how long the run goes on before memory is read again

double residentMegabytes()
{
    const auto memory = util::processMemory();
    return memory ? memory->residentMb : -1;
}

int fail(const QString &message)
{
    std::fprintf(stderr, "bench_gui_monitor: %s\n", qPrintable(message));
    return 1;
}

struct Window
{
    double seconds = 0;
    double processCpuMs = 0;
    double guiThreadCpuMs = 0;
};

Window measure(int seconds)
{
    Window window;
    const double process = bench::processCpuMs();
    const double gui = bench::threadCpuMs();
    QElapsedTimer clock;
    clock.start();
    bench::Waiter().wait(seconds * 1000);
    window.seconds = double(clock.nsecsElapsed()) / 1e9;
    window.processCpuMs = bench::processCpuMs() - process;
    window.guiThreadCpuMs = bench::threadCpuMs() - gui;
    return window;
}

// The plot's frames during the measured window: how many a second and how long they took.
struct Frames
{
    std::vector<qint64> nanoseconds;
    bool recording = false;

    double percentileMs(double fraction) const
    {
        if (nanoseconds.empty())
            return 0.0;
        std::vector<qint64> sorted = nanoseconds;
        std::sort(sorted.begin(), sorted.end());
        const auto at = std::size_t(fraction * double(sorted.size() - 1) + 0.5);
        return double(sorted.at(std::min(at, sorted.size() - 1))) / 1e6;
    }
};

} // namespace

int main(int argc, char **argv)
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QApplication app(argc, argv);
    // Options: --rate HZ (default 50) and --all-quantities (all six instead of the page's
    // default three), e.g. --rate 100 --all-quantities for the heavier case.
    const QStringList options = QCoreApplication::arguments().mid(1);
    double rateHz = kDefaultRateHz;
    const qsizetype rateAt = options.indexOf(QStringLiteral("--rate"));
    if (rateAt >= 0) {
        bool ok = false;
        rateHz = options.value(rateAt + 1).toDouble(&ok);
        if (!ok || rateHz <= 0)
            return fail(QStringLiteral("--rate needs a positive number of Hz"));
    }
    const bool allQuantities = options.contains(QStringLiteral("--all-quantities"));
    const QString servosim =
        QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("../app/servosim"));
    if (!QFileInfo(servosim).isExecutable())
        return fail(QStringLiteral("servosim not found at %1").arg(servosim));
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("bus"));
    QStringList arguments {QStringLiteral("feetech"), QStringLiteral("--link"), link};
    for (int id = 1; id <= kServos; ++id)
        arguments << QStringLiteral("--servo") << QStringLiteral("%1:STS3215").arg(id);
    QProcess simulator;
    simulator.start(servosim, arguments);
    if (!simulator.waitForStarted())
        return fail(QStringLiteral("servosim did not start"));
    const auto stopSimulator = qScopeGuard([&simulator] {
        simulator.terminate();
        simulator.waitForFinished(3000);
    });
    bench::Waiter linkReady;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&] {
        if (QFileInfo::exists(link))
            linkReady.finish();
    });
    poll.start(20);
    if (!linkReady.wait(10000))
        return fail(QStringLiteral("servosim made no link"));
    poll.stop();

    feetech::BusClient client;
    MonitorPage page(&client);
    // Tall enough for every quantity's pane (six with --all-quantities): the figure is of
    // every line drawn, not of the one pane a short window shows at a time.
    page.resize(1180, allQuantities ? 1250 : 820);
    page.show();
    bench::Waiter connected;
    QObject::connect(&client, &feetech::BusClient::statusChanged, [&](const auto &status) {
        if (status.state == seriallink::ConnectionState::Connected)
            connected.finish();
    });
    client.connectTo(link, 1000000, seriallink::EchoMode::Off);
    if (!connected.wait(5000))
        return fail(QStringLiteral("could not open %1").arg(link));
    bench::Waiter scanned;
    QObject::connect(&client, &feetech::BusClient::scanFinished, [&scanned] { scanned.finish(); });
    feetech::ScanOptions scan;
    scan.lastId = kServos;
    client.scan(scan);
    if (!scanned.wait(30000) || client.servos()->count() != kServos)
        return fail(
            QStringLiteral("found %1 of %2 servos").arg(client.servos()->count()).arg(kServos));

    QVector<int> all;
    for (int i = 0; i < kServos; ++i)
        all.append(i);
    page.setSelectedServos(all);
    if (allQuantities)
        page.setQuantities(QVector<feetech::Quantity>(std::begin(feetech::kAllQuantities),
                                                      std::end(feetech::kAllQuantities)));
    page.setRate(rateHz);
    QCoreApplication::processEvents(); // the panes are fitted to the page's height
    if (page.plot()->quantities().size() != page.quantities().size())
        return fail(QStringLiteral("the plot shows %1 of %2 quantities: the page is too short")
                        .arg(page.plot()->quantities().size())
                        .arg(page.quantities().size()));
    QString error;
    if (!page.start(&error))
        return fail(error);
    Frames frames;
    QObject::connect(page.plot(), &TelemetryPlot::framePainted, [&frames](qint64 nanoseconds) {
        if (frames.recording)
            frames.nanoseconds.push_back(nanoseconds);
    });
    measure(kWarmUpSeconds);
    const double memoryEarly = residentMegabytes();
    frames.recording = true;
    const Window window = measure(kMeasureSeconds);
    frames.recording = false;
    measure(kSecondHalfSeconds);
    const double memoryLate = residentMegabytes();
    const feetech::TelemetryStats stats = client.telemetry()->stats();
    page.stop();

    QJsonArray quantities;
    for (const feetech::Quantity quantity : page.quantities())
        quantities.append(feetech::quantityKey(quantity));
    const QJsonObject report {
        {QStringLiteral("platform"), QGuiApplication::platformName()},
        {QStringLiteral("servos"), kServos},
        {QStringLiteral("rate_hz"), rateHz},
        {QStringLiteral("quantities"), quantities},
        {QStringLiteral("plotted_series"), page.plot()->seriesCount()},
        {QStringLiteral("samples_per_s"), stats.samplesPerSecond},
        {QStringLiteral("telemetry_cycles"), stats.cycles},
        {QStringLiteral("missed_samples"), stats.missed}, // answers that never came
        {QStringLiteral("seconds_measured"), window.seconds},
        {QStringLiteral("process_cpu_percent_of_one_core"),
         window.processCpuMs / window.seconds / 10.0},
        {QStringLiteral("gui_thread_cpu_percent_of_one_core"),
         window.guiThreadCpuMs / window.seconds / 10.0},
        {QStringLiteral("resident_mb_after_3_s"), memoryEarly},
        {QStringLiteral("resident_mb_after_33_s"), memoryLate},
        {QStringLiteral("buffered_points"), page.plot()->bufferedPoints()},
        // A frame: bringing the plot's view up to date and painting it.
        {QStringLiteral("plot_frames_per_s"), double(frames.nanoseconds.size()) / window.seconds},
        {QStringLiteral("plot_frame_ms_median"), frames.percentileMs(0.5)},
        {QStringLiteral("plot_frame_ms_p99"), frames.percentileMs(0.99)},
        {QStringLiteral("plot_frame_ms_max"), frames.percentileMs(1.0)},
    };
    std::printf("%s", QJsonDocument(report).toJson(QJsonDocument::Indented).constData());
    return 0;
}
