// Times the real servobench from process start to its first painted window (no port), and its
// resident memory then, by launching the built binary with SERVOBENCH_STARTUP_PROBE set; then
// what the window costs left alone on its welcome page (CPU over a quiet stretch).
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QThread>

#include <algorithm>
#include <cstdio>
#include <ctime>

#include <unistd.h>

namespace {

constexpr int kWarmUpRuns = 1; // the first start also reads the binary and Qt from disk
constexpr int kRuns = 7;
constexpr int kTimeoutMs = 30000;
// The idle window: left to settle (first listings, fonts, the first paints), then watched.
constexpr int kIdleSettleMs = 3000;
constexpr int kIdleWatchMs = 10000;

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

// The CPU time (user and system) of process `pid` so far, in seconds; -1 when unreadable.
double cpuSeconds(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return -1;
    // The fields after the command name, which is in parentheses and may hold spaces.
    const QByteArray text = stat.readAll();
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13) // through the system time
        return -1;
    // utime and stime, the 14th and 15th fields of stat(5), in clock ticks (the list starts
    // at the 3rd field, the state).
    constexpr int kUserTicks = 14 - 3;
    constexpr int kSystemTicks = 15 - 3;
    const double ticksPerSecond = double(sysconf(_SC_CLK_TCK));
    return (fields.at(kUserTicks).toDouble() + fields.at(kSystemTicks).toDouble()) / ticksPerSecond;
}

// servobench on its welcome page, nothing connected, nobody touching it: % of one core.
double idleCpuPercent(const QString &binary, const QProcessEnvironment &environment, QString *error)
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.setProgram(binary);
    process.start();
    if (!process.waitForStarted(kTimeoutMs)) {
        *error = QStringLiteral("servobench did not start: %1").arg(process.errorString());
        return -1;
    }
    QThread::msleep(kIdleSettleMs);
    const double before = cpuSeconds(process.processId());
    const double startedNs = monotonicNs();
    QThread::msleep(kIdleWatchMs);
    const double after = cpuSeconds(process.processId());
    const double seconds = (monotonicNs() - startedNs) / 1e9;
    process.terminate();
    if (!process.waitForFinished(kTimeoutMs))
        process.kill();
    if (before < 0 || after < 0) {
        *error = QStringLiteral("servobench's CPU time could not be read (it quit early?)");
        return -1;
    }
    return 100.0 * (after - before) / seconds;
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
    QString idleError;
    const double idlePercent = idleCpuPercent(
        binary,
        [environment] {
            QProcessEnvironment quiet = environment;
            quiet.remove(QStringLiteral("SERVOBENCH_STARTUP_PROBE"));
            return quiet;
        }(),
        &idleError);
    if (idlePercent < 0) {
        std::fprintf(stderr, "bench_startup: %s\n", qPrintable(idleError));
        return 1;
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
        {QStringLiteral("idle_seconds_watched"), kIdleWatchMs / 1000},
        {QStringLiteral("idle_cpu_percent_of_one_core"), idlePercent},
    };
    std::printf("%s", QJsonDocument(report).toJson(QJsonDocument::Indented).constData());
    return 0;
}
