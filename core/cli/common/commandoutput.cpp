// The output streams and link options every servoctl command shares: --echo, --trace, Ctrl-C.
#include "commandoutput.h"

#include "arguments.h"
#include "hex.h"
#include "servoctltr.h"
#include "unixsignals.h"

#include <QCoreApplication>
#include <QTimer>

#include <csignal>

namespace cli {

seriallink::EchoMode echoModeOption(const Arguments &args)
{
    const QString echo = args.value(QStringLiteral("echo"));
    if (echo.isEmpty() || echo == QLatin1String("auto"))
        return seriallink::EchoMode::Auto;
    if (echo == QLatin1String("on"))
        return seriallink::EchoMode::On;
    if (echo == QLatin1String("off"))
        return seriallink::EchoMode::Off;
    throw UsageError {ServoctlTr::tr("--echo must be auto, on or off")};
}

void runUntilInterrupted(QEventLoop &loop, std::optional<double> seconds,
                         const std::function<void()> &onSignal)
{
    util::UnixSignalWatcher signalWatcher;
    signalWatcher.watch(SIGINT);
    signalWatcher.watch(SIGTERM);
    QObject::connect(&signalWatcher, &util::UnixSignalWatcher::received, &loop, [&loop, &onSignal] {
        if (onSignal)
            onSignal();
        else
            loop.quit();
    });
    if (seconds)
        QTimer::singleShot(qint64(*seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
}

void printTrace(const Output &output, const seriallink::PacketLogEntry &entry)
{
    static const char *const kDirections[] = {"->", "<-", "echo", "stray"};
    output.err << kDirections[int(entry.direction)] << ' ' << util::toHex(entry.bytes);
    if (!entry.summary.isEmpty())
        output.err << "  " << entry.summary;
    if (!entry.error.isEmpty())
        output.err << "  [" << entry.error << ']';
    output.err << '\n';
    output.err.flush();
}

} // namespace cli
