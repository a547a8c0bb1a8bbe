// servoctl detect and doctor: the port probe, a scan of the rates that answered, the findings.
#include "detectcommands.h"

#include "busdoctor.h"
#include "feetechdevice.h"
#include "portprobe.h"
#include "servoctl.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>

namespace cli {

namespace {

void allowOnly(const Arguments &args, const QStringList &allowed, const QString &what)
{
    static const QStringList kGlobal {QStringLiteral("port"), QStringLiteral("echo")};
    for (const QString &name : args.valueNames()) {
        if (!allowed.contains(name) && !kGlobal.contains(name))
            throw UsageError {ServoctlTr::tr("%1 takes no --%2").arg(what, name)};
    }
}

// What detect and doctor both look at: the probe's answers, then a scan of the rates that
// answered.
struct BusLook
{
    feetech::BusObservation seen;
    QString scanError; // the scan did not complete
    std::unique_ptr<FeetechDevice> device; // open after a scan, for the doctor's reads
};

feetech::PortProbeReport probePort(const QString &port)
{
    feetech::PortProbe probe;
    feetech::PortProbeReport report;
    QEventLoop loop;
    QObject::connect(&probe, &feetech::PortProbe::finished, &loop,
                     [&](const feetech::PortProbeReport &done) {
                         report = done;
                         loop.quit();
                     });
    QTimer::singleShot(0, &loop, [&] { probe.start(port); });
    runUntilInterrupted(loop, std::nullopt, [&] { probe.cancel(); });
    return report;
}

BusLook lookAtBus(const Arguments &args, const Output &output, const QString &what)
{
    if (!args.has(QStringLiteral("port")))
        throw UsageError {ServoctlTr::tr("%1 needs --port PATH (see servoctl ports)").arg(what)};
    BusLook look;
    look.seen.probe = probePort(args.value(QStringLiteral("port")));
    const QVector<qint32> bauds = look.seen.probe.answeringBauds();
    if (look.seen.probe.cancelled || look.seen.probe.ptk || bauds.isEmpty())
        return look;
    look.device = std::make_unique<FeetechDevice>(args, output);
    // The probe heard whether the adapter echoes. Deciding it again from the first answer
    // could go wrong: a PING's answer with the voltage bit set has the PING's very bytes.
    if (!args.has(QStringLiteral("echo")))
        look.device->setEchoMode(look.seen.probe.echo ? seriallink::EchoMode::On
                                                      : seriallink::EchoMode::Off);
    if (!look.device->open(bauds.first())) {
        look.scanError = look.device->error();
        return look;
    }
    feetech::ScanOptions options;
    options.bauds = bauds;
    // The probe heard something at each of these rates: every ID is asked there, even when
    // the scan's own opening broadcast happens to go unanswered.
    options.skipSilentRates = false;
    const bool completed =
        look.device->scan(options, [&](const ServoInfo &servo) { look.seen.found.append(servo); });
    look.seen.scanned = true;
    if (!completed)
        look.scanError = look.device->error();
    // The tree's order: fastest rate first, then by ID (a servo asked again comes late).
    std::stable_sort(look.seen.found.begin(), look.seen.found.end(),
                     [](const ServoInfo &a, const ServoInfo &b) {
                         return a.baud != b.baud ? a.baud > b.baud : a.id < b.id;
                     });
    return look;
}

QJsonArray findingsJson(const QVector<feetech::DoctorFinding> &findings)
{
    QJsonArray array;
    for (const feetech::DoctorFinding &finding : findings) {
        QJsonArray ids;
        for (const int id : finding.ids)
            ids.append(id);
        array.append(QJsonObject {{QStringLiteral("finding"), finding.code},
                                  {QStringLiteral("message"), finding.message},
                                  {QStringLiteral("ids"), ids}});
    }
    return array;
}

void printFindings(QTextStream &stream, const QVector<feetech::DoctorFinding> &findings)
{
    for (const feetech::DoctorFinding &finding : findings)
        stream << finding.code << ": " << finding.message << '\n';
    stream.flush();
}

// The rates servos were found at, fastest first; the answering rates when none was.
QVector<qint32> servoBauds(const feetech::BusObservation &seen)
{
    QVector<qint32> bauds;
    for (const ServoInfo &servo : seen.found) {
        if (!bauds.contains(servo.baud))
            bauds.append(servo.baud);
    }
    std::sort(bauds.begin(), bauds.end(), std::greater<>());
    return bauds;
}

} // namespace

int runDetectCommand(const Arguments &args, const QStringList &rest, const Output &output)
{
    allowOnly(args, {}, QStringLiteral("detect"));
    if (!rest.isEmpty())
        throw UsageError {ServoctlTr::tr("detect takes no arguments")};
    const BusLook look = lookAtBus(args, output, QStringLiteral("detect"));
    const feetech::BusObservation &seen = look.seen;
    const bool ptk = seen.probe.ptk;
    const bool feetech = !ptk && !seen.found.isEmpty();
    const QVector<qint32> bauds = ptk ? QVector<qint32> {115200} : servoBauds(seen);
    if (output.json) {
        QJsonArray baudArray;
        for (const qint32 baud : bauds)
            baudArray.append(baud);
        QJsonArray servos;
        for (const ServoInfo &servo : seen.found)
            servos.append(QJsonObject {{QStringLiteral("id"), servo.id},
                                       {QStringLiteral("baud"), servo.baud},
                                       {QStringLiteral("model"), servo.model.name}});
        const QJsonValue protocol = ptk ? QJsonValue(QStringLiteral("ptk"))
            : feetech                   ? QJsonValue(QStringLiteral("feetech"))
                                        : QJsonValue(QJsonValue::Null);
        printJson(output.out,
                  QJsonObject {{QStringLiteral("protocol"), protocol},
                               {QStringLiteral("echo"), seen.probe.echo},
                               {QStringLiteral("bauds"), baudArray},
                               {QStringLiteral("servos"), servos}});
    } else if (ptk) {
        output.out << ServoctlTr::tr("PTK servo at 115200 bps%1")
                          .arg(seen.probe.echo ? ServoctlTr::tr(", adapter echo") : QString())
                   << '\n';
    } else if (feetech) {
        output.out << ServoctlTr::tr("Feetech bus%1: %n servo(s)", nullptr, int(seen.found.size()))
                          .arg(seen.probe.echo ? ServoctlTr::tr(", adapter echo") : QString())
                   << '\n';
        for (const ServoInfo &servo : seen.found)
            output.out << "  " << servoSummary(servo) << '\n';
    }
    output.out.flush();
    if (seen.probe.cancelled) {
        output.err << "servoctl: " << ServoctlTr::tr("interrupted before the probe ended") << '\n';
        output.err.flush();
        return ExitDeviceFailure;
    }
    if (ptk || feetech)
        return ExitOk;
    output.err << "servoctl: " << ServoctlTr::tr("nothing answers on %1").arg(seen.probe.port)
               << '\n';
    if (!look.scanError.isEmpty())
        output.err << "servoctl: " << look.scanError << '\n';
    printFindings(output.err, feetech::diagnoseBus(seen, {}));
    return ExitDeviceFailure;
}

int runDoctorCommand(const Arguments &args, const QStringList &rest, const Output &output)
{
    allowOnly(args, {QStringLiteral("expect"), QStringLiteral("baud")}, QStringLiteral("doctor"));
    if (!rest.isEmpty())
        throw UsageError {
            ServoctlTr::tr("doctor takes no arguments (the expected IDs go in --expect)")};
    if (args.has(QStringLiteral("baud")) && !args.has(QStringLiteral("expect")))
        throw UsageError {ServoctlTr::tr("doctor --baud names the rate of the --expect servos")};
    QVector<feetech::ExpectedServo> expected;
    if (args.has(QStringLiteral("expect"))) {
        qint32 baud = kDefaultBaud;
        if (args.has(QStringLiteral("baud"))) {
            baud = qint32(integerOption(args, QStringLiteral("baud"), 1, 4000000));
            if (!feetech::baudCode(baud))
                throw UsageError {ServoctlTr::tr("--baud %1 is not a Feetech rate (%2)")
                                      .arg(baud)
                                      .arg(baudList())};
        }
        // In the order given: the chain's order, nearest the adapter first.
        for (const quint8 id : idList(args.value(QStringLiteral("expect")), feetech::kMaxServoId))
            expected.append({id, baud});
    }
    BusLook look = lookAtBus(args, output, QStringLiteral("doctor"));
    feetech::BusObservation &seen = look.seen;
    // Each servo's table, for its supply: present voltage, its limits, the status bits.
    if (look.device && look.scanError.isEmpty()) {
        for (const ServoInfo &servo : std::as_const(seen.found)) {
            const auto memory = look.device->read(servo, {});
            seen.conditions.append(feetech::servoCondition(servo, memory.value_or(Memory())));
        }
    }
    const QVector<feetech::DoctorFinding> findings = feetech::diagnoseBus(seen, expected);
    if (output.json) {
        printJson(output.out, findingsJson(findings));
    } else if (findings.isEmpty()) {
        if (seen.probe.ptk)
            output.out << ServoctlTr::tr("A PTK servo answers on %1.").arg(seen.probe.port) << '\n';
        else
            output.out << ServoctlTr::tr("The bus holds what was expected: %n servo(s).", nullptr,
                                         int(seen.found.size()))
                       << '\n';
        output.out.flush();
    } else {
        printFindings(output.out, findings);
    }
    if (!look.scanError.isEmpty()) {
        output.err << "servoctl: " << look.scanError << '\n';
        output.err.flush();
        return ExitDeviceFailure;
    }
    if (seen.probe.cancelled)
        return ExitDeviceFailure;
    return findings.isEmpty() ? ExitOk : ExitDeviceFailure;
}

} // namespace cli
