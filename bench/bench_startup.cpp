// Times the real servobench from process start to its first painted window (no port), and its
// resident memory then, by launching the built binary with SERVOBENCH_STARTUP_PROBE set.
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace {

constexpr int kWarmUpRuns = 1; // the first start also reads the binary and Qt from disk
constexpr int kRuns = 7;
constexpr int kTimeoutMs = 30000;

double monotonicNs()
{
    timespec now {};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return double(now.tv_sec) * 1e9 + double(now.tv_nsec);
}

struct Start
{
    double msToFirstFrame = -1;
    double residentMb = -1;
    double peakResidentMb = -1;
    QString platform;
    QString error;
};

Start launch(const QString &binary, const QProcessEnvironment &environment)
{
    Start start;
    QProcess process;
    process.setProcessEnvironment(environment);
    process.setProgram(binary);
    process.setProcessChannelMode(QProcess::SeparateChannels);
    const double launchedNs = monotonicNs();
    process.start();
    if (!process.waitForFinished(kTimeoutMs)) {
        process.kill();
        process.waitForFinished(3000);
        start.error = QStringLiteral("servobench did not quit within %1 s").arg(kTimeoutMs / 1000);
        return start;
    }
    // The probe's line is the last JSON line of standard output.
    QJsonObject line;
    for (const QByteArray &text : process.readAllStandardOutput().split('\n')) {
        const QJsonDocument document = QJsonDocument::fromJson(text);
        if (document.isObject()
            && document.object().contains(QStringLiteral("first_frame_monotonic_ns")))
            line = document.object();
    }
    if (line.isEmpty()) {
        start.error = QStringLiteral("servobench printed no probe line (exit %1): %2")
                          .arg(process.exitCode())
                          .arg(QString::fromLocal8Bit(process.readAllStandardError()).trimmed());
        return start;
    }
    start.msToFirstFrame =
        (line.value(QStringLiteral("first_frame_monotonic_ns")).toDouble() - launchedNs) / 1e6;
    start.residentMb = line.value(QStringLiteral("resident_mb")).toDouble(-1);
    start.peakResidentMb = line.value(QStringLiteral("peak_resident_mb")).toDouble(-1);
    start.platform = line.value(QStringLiteral("platform")).toString();
    return start;
}

double median(QVector<double> values)
{
    std::sort(values.begin(), values.end());
    return values.at(values.size() / 2);
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QString binary =
        QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("../app/servobench"));
    if (!QFileInfo(binary).isExecutable()) {
        std::fprintf(stderr, "bench_startup: servobench not found at %s\n", qPrintable(binary));
        return 1;
    }
    // A first start: no saved settings or templates (a fresh config and data folder), no port.
    QTemporaryDir home;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("SERVOBENCH_STARTUP_PROBE"), QStringLiteral("1"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
    environment.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
    if (!environment.contains(QStringLiteral("QT_QPA_PLATFORM"))
        && !environment.contains(QStringLiteral("DISPLAY")))
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));

    QVector<double> times;
    QVector<double> resident;
    QVector<double> peak;
    QString platform;
    for (int run = 0; run < kWarmUpRuns + kRuns; ++run) {
        const Start start = launch(binary, environment);
        if (!start.error.isEmpty()) {
            std::fprintf(stderr, "bench_startup: %s\n", qPrintable(start.error));
            return 1;
        }
        if (run < kWarmUpRuns)
            continue;
        times.append(start.msToFirstFrame);
        resident.append(start.residentMb);
        peak.append(start.peakResidentMb);
        platform = start.platform;
    }
    QJsonArray each;
    for (const double ms : times)
        each.append(ms);
    const QJsonObject report {
        {QStringLiteral("binary"), QFileInfo(binary).canonicalFilePath()},
        {QStringLiteral("platform"), platform},
        {QStringLiteral("runs"), kRuns},
        {QStringLiteral("ms_to_first_frame"), each},
        {QStringLiteral("median_ms_to_first_frame"), median(times)},
        {QStringLiteral("max_ms_to_first_frame"), *std::max_element(times.begin(), times.end())},
        {QStringLiteral("median_resident_mb_at_first_frame"), median(resident)},
        {QStringLiteral("median_peak_resident_mb_at_first_frame"), median(peak)},
    };
    std::printf("%s", QJsonDocument(report).toJson(QJsonDocument::Indented).constData());
    return 0;
}
