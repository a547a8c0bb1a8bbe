// servoctl share: open the port, offer a pseudo-terminal, forward until Ctrl-C or --duration.
#include "sharecommand.h"

#include "busshare.h"
#include "exitcode.h"
#include "feetechdescription.h"
#include "feetechdevice.h"
#include "feetechpacket.h"
#include "linksession.h"

#include <QJsonDocument>

namespace cli {

namespace {

struct ShareCommandTr
{
    Q_DECLARE_TR_FUNCTIONS(ShareCommand)
};

void printLine(const Output &output, const QJsonObject &object)
{
    output.out << QJsonDocument(object).toJson(QJsonDocument::Compact) << '\n';
    output.out.flush();
}

} // namespace

int runShareCommand(const Arguments &args, const QStringList &rest, const Output &output)
{
    static const QStringList kAllowed {QStringLiteral("port"),   QStringLiteral("baud"),
                                       QStringLiteral("echo"),   QStringLiteral("link"),
                                       QStringLiteral("record"), QStringLiteral("duration")};
    for (const QString &name : args.valueNames()) {
        if (!kAllowed.contains(name))
            throw UsageError {ShareCommandTr::tr("share takes no --%1").arg(name)};
    }
    if (!rest.isEmpty())
        throw UsageError {ShareCommandTr::tr("share takes no arguments besides its options")};
    if (!args.has(QStringLiteral("port")))
        throw UsageError {ShareCommandTr::tr("share needs --port: the adapter the servos are on")};
    if (!args.has(QStringLiteral("link")) || args.value(QStringLiteral("link")).isEmpty())
        throw UsageError {
            ShareCommandTr::tr("share needs --link PATH: the path the other program opens")};
    const qint32 baud = args.has(QStringLiteral("baud"))
        ? qint32(integerOption(args, QStringLiteral("baud"), 1200, 4000000))
        : kDefaultBaud;
    const std::optional<double> duration = durationOption(args);
    const seriallink::EchoMode echo = echoModeOption(args);

    static const feetech::FrameFormat format;
    seriallink::LinkSession link(format, feetech::describeFrame);
    const QString port = args.value(QStringLiteral("port"));
    if (!link.open(port, baud, echo)) {
        output.err << "servoctl: " << link.status().message << '\n';
        output.err.flush();
        return ExitDeviceFailure;
    }
    share::BusShare share(link);
    share::ShareOptions options;
    options.linkPath = args.value(QStringLiteral("link"));
    options.recordPath = args.value(QStringLiteral("record"));
    options.watch = args.flag(QStringLiteral("watch"));
    const QString refused = share.start(options);
    if (!refused.isEmpty()) {
        output.err << "servoctl: " << refused << '\n';
        output.err.flush();
        return ExitDeviceFailure;
    }
    output.err << ShareCommandTr::tr(
                      "Sharing %1 at %2 baud: give the other program %3 (%4). Ctrl-C ends.")
                      .arg(port)
                      .arg(baud)
                      .arg(share.linkPath(), share.terminalPath())
               << '\n';
    output.err.flush();

    QObject::connect(&share, &share::BusShare::transactionEnded,
                     [&output](const share::SharedTransaction &transaction) {
                         if (output.json)
                             printLine(output, transaction.toJson());
                     });
    QObject::connect(&share, &share::BusShare::alertRaised,
                     [&output](const share::ShareAlert &alert) {
                         if (output.json)
                             printLine(output, alert.toJson());
                         output.err << ShareCommandTr::tr("alert %1 at ID %2: %3")
                                           .arg(alert.code)
                                           .arg(alert.id)
                                           .arg(alert.message)
                                    << '\n';
                         output.err.flush();
                     });
    QObject::connect(&share, &share::BusShare::noted, [&output](const QString &text) {
        output.err << text << '\n';
        output.err.flush();
    });

    QEventLoop loop;
    streamWithoutWaiting(output);
    runUntilInterrupted(loop, duration);
    QString summary = share.summary();
    share.stop();
    link.close();
    const QString dropped = droppedLinesNote(output);
    if (!dropped.isEmpty())
        summary += u' ' + ShareCommandTr::tr("Output: %1.").arg(dropped);
    output.err << summary << '\n';
    output.err.flush();
    return ExitOk;
}

} // namespace cli
