// The output streams and link options every servoctl command shares: --echo, --trace, Ctrl-C.
#include "commandoutput.h"

#include "arguments.h"
#include "hex.h"
#include "lineoutlet.h"
#include "servoctltr.h"
#include "unixsignals.h"

#include <QCoreApplication>
#include <QTimer>

#include <csignal>
#include <limits>

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

namespace {

QVector<util::LineOutlet *> outlets(const Output &output)
{
    QVector<util::LineOutlet *> found;
    for (QTextStream *stream : {&output.out, &output.err}) {
        if (auto *outlet = qobject_cast<util::LineOutlet *>(stream->device()))
            found.append(outlet);
    }
    return found;
}

QString droppedLinesText(qint64 count)
{
    return ServoctlTr::tr("dropped %Ln line(s) nobody read", nullptr,
                          int(qMin<qint64>(count, std::numeric_limits<int>::max())));
}

} // namespace

QString droppedLinesNote(const Output &output)
{
    qint64 dropped = 0;
    for (const util::LineOutlet *outlet : outlets(output))
        dropped += outlet->droppedLines();
    return dropped > 0 ? droppedLinesText(dropped) : QString();
}

void sayDroppedLines(const Output &output)
{
    const QString dropped = droppedLinesNote(output);
    if (dropped.isEmpty())
        return;
    output.err << "servoctl: " << dropped << '\n';
    output.err.flush();
}

void streamWithoutWaiting(const Output &output)
{
    output.out.flush();
    output.err.flush();
    for (util::LineOutlet *outlet : outlets(output)) {
        const bool json = output.json && outlet == output.out.device();
        outlet->setDroppedLine([json](qint64 count) -> QByteArray {
            if (json)
                return QByteArrayLiteral("{\"dropped\":") + QByteArray::number(count) + "}\n";
            return "servoctl: " + droppedLinesText(count).toUtf8() + '\n';
        });
        outlet->setWhenFull(util::LineOutlet::WhenFull::Drop);
    }
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
