// servoctl feetech monitor: streams servos' feedback as text, JSON lines or CSV.
#include "feetechmonitorcommand.h"
#include "servoctltr.h"
#include "telemetryrecorder.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>

namespace cli {

namespace {

constexpr double kDefaultMonitorRate = 50.0;

} // namespace

// Streams the feedback of --ids until --duration has passed or Ctrl-C; one line per sample.
int FeetechMonitorCommand::monitor(const QString &what, const QStringList &operands)
{
    allowOptions(what,
                 {QStringLiteral("ids"), QStringLiteral("rate"), QStringLiteral("duration"),
                  QStringLiteral("csv")});
    expectOperands(what, operands, 0, {});
    if (!m_args.has(QStringLiteral("ids")))
        throw UsageError {ServoctlTr::tr("%1 needs --ids LIST (such as 1,2,5-7)").arg(what)};
    QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
    for (int i = 0; i < ids.size(); ++i) {
        if (ids.indexOf(ids.at(i)) != i)
            throw UsageError {ServoctlTr::tr("--ids names servo %1 twice").arg(ids.at(i))};
    }
    const std::optional<double> duration = durationOption(m_args);
    const double rate = monitorRate();
    const bool csv = m_args.flag(QStringLiteral("csv"));
    if (csv && m_output.json)
        throw UsageError {ServoctlTr::tr("choose --csv or --json, not both")};
    const qint32 baud = busBaud();

    FeetechDevice device(m_args, m_output);
    if (!device.open(baud))
        return fail(device.error());
    feetech::TelemetryOptions options;
    options.rateHz = rate;
    options.logEveryFrame = m_args.flag(QStringLiteral("trace"));
    for (const quint8 id : std::as_const(ids)) {
        const auto servo = device.identify(id, baud);
        if (!servo)
            return fail(device.error());
        if (!servo->hasTable())
            return fail(ServoctlTr::tr("servo %1 is of an unknown model (%2): its feedback cannot "
                                       "be decoded")
                            .arg(id)
                            .arg(servo->modelNumber()));
        options.servos.append(*servo);
    }

    feetech::Session &session = device.session();
    QEventLoop loop;
    const qint64 startUs = feetech::steadyMicroseconds();
    qint64 printed = 0;
    // CSV goes through the recorder the Monitor page records with: the same rows either way.
    feetech::TelemetryRecorder recorder;
    recorder.setFlushInterval(0);
    if (csv && !recorder.start(m_output.out))
        return fail(recorder.errorString());
    recorder.setStartUs(startUs);
    QObject::connect(&session, &feetech::Session::telemetry, &loop,
                     [&](const QVector<feetech::FeedbackSample> &samples) {
                         if (csv) {
                             recorder.write(samples);
                             recorder.flush();
                         } else {
                             for (const feetech::FeedbackSample &sample : samples)
                                 printSample(sample, startUs, options.servos);
                         }
                         printed += samples.size();
                         m_output.out.flush();
                     });
    // A servo that stops answering (or comes back) is said on stderr as it happens.
    QHash<quint8, bool> missing;
    feetech::TelemetryStats last;
    QObject::connect(&session, &feetech::Session::telemetryStats, &loop,
                     [&](const feetech::TelemetryStats &stats) {
                         last = stats;
                         for (const feetech::ServoTelemetry &servo : stats.servos) {
                             if (missing.value(servo.id) == servo.missing)
                                 continue;
                             missing.insert(servo.id, servo.missing);
                             m_output.err
                                 << (servo.missing
                                         ? ServoctlTr::tr("servoctl: servo %1 stopped answering")
                                         : ServoctlTr::tr("servoctl: servo %1 answers again"))
                                        .arg(servo.id)
                                 << '\n';
                             m_output.err.flush();
                         }
                     });
    QObject::connect(&session, &feetech::Session::statusChanged, &loop,
                     [&](const seriallink::ConnectionStatus &status) {
                         if (status.state != seriallink::ConnectionState::Connected)
                             loop.quit(); // unplugged: nothing more will come
                     });
    QTimer::singleShot(0, &loop, [&session, options] { session.startTelemetry(options); });
    streamWithoutWaiting(m_output);
    runUntilInterrupted(loop, duration);
    const bool linkLost = session.status().state != seriallink::ConnectionState::Connected;
    session.stopTelemetry(); // flushes the last samples through the connection above
    m_output.err << ServoctlTr::tr(
                        "servoctl: %1 samples in %2 s (%3 per second); %4 missed, %5 late")
                        .arg(printed)
                        .arg(last.elapsedSeconds, 0, 'f', 2)
                        .arg(last.elapsedSeconds > 0 ? double(printed) / last.elapsedSeconds : 0.0,
                             0, 'f', 1)
                        .arg(last.missed)
                        .arg(last.late)
                 << '\n';
    m_output.err.flush();
    sayDroppedLines(m_output);
    if (linkLost)
        return fail(session.status().message);
    if (printed == 0)
        return fail(ServoctlTr::tr("no servo answered the telemetry requests"));
    return ExitOk;
}

// --rate HZ (1 to 1000) or "max"; 50 when not given.
double FeetechMonitorCommand::monitorRate() const
{
    if (!m_args.has(QStringLiteral("rate")))
        return kDefaultMonitorRate;
    const QString text = m_args.value(QStringLiteral("rate"));
    if (text == u"max")
        return 0.0;
    bool ok = false;
    const double rate = text.toDouble(&ok);
    if (!ok || rate < 1.0 || rate > 1000.0)
        throw UsageError {
            ServoctlTr::tr("--rate must be a number of samples per second from 1 to 1000, or max")};
    return rate;
}

void FeetechMonitorCommand::printSample(const feetech::FeedbackSample &sample, qint64 startUs,
                                        const QVector<ServoInfo> &servos)
{
    const double seconds = double(sample.steadyUs - startUs) / 1e6;
    const auto servo = std::find_if(servos.begin(), servos.end(),
                                    [&sample](const auto &s) { return s.id == sample.id; });
    const QString status = servo != servos.end()
        ? feetech::servoStatusText(servo->table(), sample.servoStatus)
        : QString::number(sample.servoStatus);
    if (m_output.json) {
        // One JSON document per line, so the stream can be piped and read as it runs.
        QJsonObject row {{QStringLiteral("time_s"), seconds}, {QStringLiteral("id"), sample.id}};
        for (const feetech::Quantity quantity : feetech::kAllQuantities) {
            const auto value = sample.value(quantity);
            row.insert(feetech::quantityKey(quantity), value ? QJsonValue(*value) : QJsonValue());
        }
        row.insert(QStringLiteral("status"), sample.servoStatus);
        row.insert(QStringLiteral("status_bits"), status);
        row.insert(QStringLiteral("moving"), sample.moving);
        m_output.out << QJsonDocument(row).toJson(QJsonDocument::Compact) << '\n';
        return;
    }
    QStringList cells {QString::number(seconds, 'f', 3), QStringLiteral("id=%1").arg(sample.id)};
    for (const feetech::Quantity quantity : feetech::kAllQuantities) {
        const auto value = sample.value(quantity);
        if (value)
            cells.append(QStringLiteral("%1=%2").arg(feetech::quantityKey(quantity),
                                                     QString::number(*value)));
    }
    cells.append(QStringLiteral("moving=%1").arg(sample.moving ? 1 : 0));
    cells.append(QStringLiteral("status=%1").arg(status));
    m_output.out << cells.join(QLatin1Char(' ')) << '\n';
}

} // namespace cli
