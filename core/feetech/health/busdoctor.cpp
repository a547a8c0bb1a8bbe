// Bus doctor: findings from the port, the probe's answers per rate, the scan and each servo.
#include "busdoctor.h"

#include "servoparameters.h"

#include <QCoreApplication>
#include <QHash>
#include <QSettings>

#include <algorithm>

namespace {

struct BusDoctorTr
{
    Q_DECLARE_TR_FUNCTIONS(BusDoctor)
};

} // namespace

namespace feetech {

namespace {

constexpr quint8 kVoltageErrorBit = 0x01;

QString idList(const QVector<int> &ids)
{
    QStringList texts;
    for (const int id : ids)
        texts.append(QString::number(id));
    return texts.join(QStringLiteral(", "));
}

DoctorFinding finding(const QString &code, const QString &message, QVector<int> ids = {})
{
    return {code, message, std::move(ids), {}};
}

std::optional<DoctorFinding> portFinding(const PortProbeReport &probe)
{
    using Problem = seriallink::PortAccess::Problem;
    const QString port = probe.port;
    switch (probe.access.problem) {
    case Problem::None:
        return std::nullopt;
    case Problem::Permission:
#ifdef Q_OS_LINUX
        return finding(
            doctorcodes::kPortPermission,
            BusDoctorTr::tr("You may not open %1. Add yourself to the dialout group (sudo "
                            "usermod -aG dialout $USER, then log out and back in), or give "
                            "the adapter a udev rule that lets your account use it.")
                .arg(port));
#else
        return finding(
            doctorcodes::kPortPermission,
            BusDoctorTr::tr("You may not open %1: ask for access to serial ports.").arg(port));
#endif
    case Problem::Busy:
        if (!probe.access.holder.isEmpty())
            return finding(
                doctorcodes::kPortBusy,
                BusDoctorTr::tr("%1 is in use by %2. Close that program (or its connection "
                                "to the port) and try again.")
                    .arg(port, probe.access.holder));
        return finding(doctorcodes::kPortBusy,
                       BusDoctorTr::tr("%1 is in use by another program (a terminal, another "
                                       "ServoBench, a modem manager). Close it and try again.")
                           .arg(port));
    case Problem::Missing:
        return finding(
            doctorcodes::kPortMissing,
            BusDoctorTr::tr("%1 does not exist. Plug the adapter in, or choose another port.")
                .arg(port));
    case Problem::Other:
        break;
    }
    return finding(doctorcodes::kPortFailed,
                   BusDoctorTr::tr("%1 could not be used: %2.").arg(port, probe.access.detail));
}

DoctorFinding silenceFinding(const PortProbeReport &probe)
{
    QString message = BusDoctorTr::tr(
        "Not a single byte came back at any rate. Check the servos' power supply (the USB "
        "adapter does not power them), the wiring (signal and ground), the adapter's direction "
        "switch or jumper, and that a TTL servo (SCS, STS) is not on an RS485 adapter, or an "
        "RS485 servo on a TTL one.");
    if (probe.echo)
        message += QLatin1Char(' ')
            + BusDoctorTr::tr(
                       "The adapter sends back what it sends, so it works: the servos do not "
                       "answer.");
    return finding(doctorcodes::kNoBytes, message);
}

// Rates where bytes came but no servo was found: the bytes never made an answer.
std::optional<DoctorFinding> unframedFinding(const BusObservation &seen)
{
    QStringList rates;
    for (const RateProbe &rate : seen.probe.rates) {
        const bool servoThere =
            std::any_of(seen.found.cbegin(), seen.found.cend(),
                        [&](const ServoInfo &s) { return s.baud == rate.baud; });
        const bool unclear = rate.heard == RateHeard::Unframed
            || (seen.scanned && rate.heard == RateHeard::Frames && !servoThere);
        if (unclear && !servoThere)
            rates.append(baudText(rate.baud));
    }
    if (rates.isEmpty())
        return std::nullopt;
    return finding(
        doctorcodes::kUnframedBytes,
        BusDoctorTr::tr("At %1, bytes came back but never a valid answer. A servo may be at "
                        "another rate, the adapter may send back what it sends (try Echo "
                        "On), or two servos may share one ID (connect them one at a time).")
            .arg(rates.join(QStringLiteral(", "))));
}

const ServoInfo *foundAt(const QVector<ServoInfo> &found, quint8 id, qint32 baud)
{
    for (const ServoInfo &servo : found) {
        if (servo.id == id && (baud == 0 || servo.baud == baud))
            return &servo;
    }
    return nullptr;
}

void expectationFindings(const BusObservation &seen, const QVector<ExpectedServo> &expected,
                         QVector<DoctorFinding> &findings)
{
    if (expected.isEmpty())
        return; // nothing to compare with: every servo that answers is welcome
    QVector<int> missing;
    QVector<bool> answers; // in chain order: the expected servo answers (at any rate)
    for (const ExpectedServo &want : expected) {
        const ServoInfo *atRate = foundAt(seen.found, want.id, want.baud);
        const ServoInfo *anywhere = atRate ? atRate : foundAt(seen.found, want.id, 0);
        answers.append(anywhere != nullptr);
        if (!anywhere) {
            missing.append(want.id);
        } else if (!atRate) {
            DoctorFinding wrongRate =
                finding(doctorcodes::kUnexpectedBaud,
                        BusDoctorTr::tr("Servo %1 answers at %2, not at %3. Move it to %3.")
                            .arg(want.id)
                            .arg(baudText(anywhere->baud), baudText(want.baud)),
                        {want.id});
            wrongRate.moves.append({*anywhere, -1, want.baud});
            findings.append(wrongRate);
        }
    }
    const auto isExpected = [&](const ServoInfo &servo) {
        return std::any_of(expected.cbegin(), expected.cend(),
                           [&](const ExpectedServo &want) { return want.id == servo.id; });
    };
    QVector<int> offered; // missing IDs already offered to a stray servo
    for (const ServoInfo &servo : seen.found) {
        if (isExpected(servo))
            continue;
        DoctorFinding stray =
            finding(doctorcodes::kUnexpectedId,
                    BusDoctorTr::tr("A servo (%1) answers at ID %2, %3: no servo is "
                                    "expected at that ID.")
                        .arg(servo.model.name)
                        .arg(servo.id)
                        .arg(baudText(servo.baud)),
                    {servo.id});
        const auto target = std::find_if(missing.cbegin(), missing.cend(),
                                         [&](int id) { return !offered.contains(id); });
        if (target != missing.cend()) {
            offered.append(*target);
            const qint32 wantedBaud =
                std::find_if(expected.cbegin(), expected.cend(), [&](const ExpectedServo &want) {
                    return want.id == *target;
                })->baud;
            const bool otherRate = wantedBaud != 0 && wantedBaud != servo.baud;
            stray.message += QLatin1Char(' ')
                + (otherRate
                       ? BusDoctorTr::tr("If it is the missing servo %1, move it to ID %1 at %2.")
                             .arg(*target)
                             .arg(baudText(wantedBaud))
                       : BusDoctorTr::tr("If it is the missing servo %1, move it to ID %1.")
                             .arg(*target));
            stray.moves.append({servo, *target, otherRate ? wantedBaud : 0});
        }
        findings.append(stray);
    }
    if (missing.isEmpty())
        return;
    // A prefix of the chain answers and the rest does not: the break is after the last one.
    const int answering =
        int(std::find(answers.cbegin(), answers.cend(), false) - answers.cbegin());
    const bool restSilent = std::none_of(answers.cbegin() + answering, answers.cend(),
                                         [](bool answered) { return answered; });
    if (answering > 0 && restSilent && expected.size() > 1) {
        const int last = expected.at(answering - 1).id;
        const QString notAnswering = missing.size() == 1
            ? BusDoctorTr::tr("Servo %1 does not answer").arg(missing.first())
            : BusDoctorTr::tr("Servos %1 do not answer").arg(idList(missing));
        findings.append(
            finding(doctorcodes::kChainBreak,
                    BusDoctorTr::tr("%1, while every servo up to ID %2 in the chain "
                                    "does: check the cable after ID %2 (and its connectors "
                                    "at both ends).")
                        .arg(notAnswering)
                        .arg(last),
                    missing));
        return;
    }
    const QString notAnswering = missing.size() == 1
        ? BusDoctorTr::tr("Expected servo %1 does not answer").arg(missing.first())
        : BusDoctorTr::tr("Expected servos %1 do not answer").arg(idList(missing));
    findings.append(
        finding(doctorcodes::kMissingServos,
                BusDoctorTr::tr("%1. Check power and cables; a new servo is at ID 1 until it "
                                "is set up (Set up motors, or servoctl feetech setup-motor).")
                    .arg(notAnswering),
                missing));
}

void conditionFindings(const BusObservation &seen, QVector<DoctorFinding> &findings)
{
    for (const ServoCondition &condition : seen.conditions) {
        const int id = condition.servo.id;
        if (!condition.readable) {
            findings.append(
                finding(doctorcodes::kSharedId,
                        BusDoctorTr::tr("Servo %1 answers a PING but its registers come back "
                                        "garbled: two servos may share ID %1. Connect them "
                                        "one at a time and give each its own ID.")
                            .arg(id),
                        {id}));
            continue;
        }
        const bool flagged = condition.status & kVoltageErrorBit;
        // Both limits 0 turn the servo's voltage check off (as the servos do): no voltage is
        // outside them.
        const bool limited = condition.minVoltage && condition.maxVoltage
            && (*condition.minVoltage != 0 || *condition.maxVoltage != 0);
        const bool outside = condition.voltage && limited
            && (*condition.voltage < *condition.minVoltage
                || *condition.voltage > *condition.maxVoltage);
        if (!flagged && !outside)
            continue;
        const QString limits = limited ? BusDoctorTr::tr("%1–%2 V")
                                             .arg(*condition.minVoltage, 0, 'f', 1)
                                             .arg(*condition.maxVoltage, 0, 'f', 1)
                                       : BusDoctorTr::tr("its limits");
        const QString measured = condition.voltage
            ? BusDoctorTr::tr("%1 V").arg(*condition.voltage, 0, 'f', 1)
            : BusDoctorTr::tr("an unknown voltage");
        findings.append(
            finding(doctorcodes::kVoltage,
                    BusDoctorTr::tr("Servo %1 reports %2 and a voltage error; it accepts %3. "
                                    "Check the supply: a 12 V supply on a 7.4 V servo, or a "
                                    "supply too weak for the load.")
                        .arg(id)
                        .arg(measured, limits),
                    {id}));
    }
}

} // namespace

ServoCondition servoCondition(const ServoInfo &servo, const QMap<int, QByteArray> &memory)
{
    QHash<QString, qint32> values;
    if (servo.hasTable()) {
        for (auto it = memory.cbegin(); it != memory.cend(); ++it) {
            for (const DecodedRegister &item : decodeRegisters(servo.table(), it.key(), it.value()))
                values.insert(item.reg->key, item.value);
        }
    }
    return servoCondition(servo, !memory.isEmpty(),
                          [&values](const QString &key) -> std::optional<qint64> {
                              const auto found = values.constFind(key);
                              if (found == values.cend())
                                  return std::nullopt;
                              return *found;
                          });
}

ServoCondition servoCondition(const ServoInfo &servo, bool readable,
                              const std::function<std::optional<qint64>(const QString &)> &value)
{
    ServoCondition condition;
    condition.servo = servo;
    condition.readable = readable;
    if (!readable || !servo.hasTable())
        return condition;
    const RegisterTable &table = servo.table();
    const auto volts = [&](const QString &key) -> std::optional<double> {
        const Register *reg = table.find(key);
        const auto raw = reg ? value(key) : std::nullopt;
        if (!raw)
            return std::nullopt;
        return double(*raw) * reg->scale;
    };
    condition.voltage = volts(QStringLiteral("present_voltage"));
    condition.minVoltage = volts(QStringLiteral("min_voltage"));
    condition.maxVoltage = volts(QStringLiteral("max_voltage"));
    if (const auto status = value(QStringLiteral("status")))
        condition.status = quint8(*status);
    return condition;
}

QString doctorTitle(const QString &code)
{
    using namespace doctorcodes;
    static const QHash<QString, const char *> titles {
        {kPortPermission, QT_TRANSLATE_NOOP("BusDoctor", "You may not open the port")},
        {kPortBusy, QT_TRANSLATE_NOOP("BusDoctor", "Another program has the port")},
        {kPortMissing, QT_TRANSLATE_NOOP("BusDoctor", "The port is not there")},
        {kPortFailed, QT_TRANSLATE_NOOP("BusDoctor", "The port could not be opened")},
        {kNoBytes, QT_TRANSLATE_NOOP("BusDoctor", "Nothing answers")},
        {kUnframedBytes, QT_TRANSLATE_NOOP("BusDoctor", "Bytes come back, but no answer")},
        {kPtkServo, QT_TRANSLATE_NOOP("BusDoctor", "A PTK servo, not a Feetech bus")},
        {kNoServoFound, QT_TRANSLATE_NOOP("BusDoctor", "No servo found")},
        {kUnexpectedId, QT_TRANSLATE_NOOP("BusDoctor", "A servo at an unexpected ID")},
        {kUnexpectedBaud, QT_TRANSLATE_NOOP("BusDoctor", "A servo at another rate")},
        {kChainBreak, QT_TRANSLATE_NOOP("BusDoctor", "The chain is broken")},
        {kMissingServos, QT_TRANSLATE_NOOP("BusDoctor", "Servos are missing")},
        {kSharedId, QT_TRANSLATE_NOOP("BusDoctor", "Two servos may share an ID")},
        {kVoltage, QT_TRANSLATE_NOOP("BusDoctor", "The supply voltage is wrong")},
    };
    const auto title = titles.constFind(code);
    return title == titles.cend() ? code : BusDoctorTr::tr(*title);
}

QVector<DoctorFinding> diagnoseBus(const BusObservation &seen,
                                   const QVector<ExpectedServo> &expected)
{
    QVector<DoctorFinding> findings;
    if (const auto port = portFinding(seen.probe)) {
        findings.append(*port);
        return findings; // nothing else was asked
    }
    if (seen.probe.ptk) {
        // A PTK servo is one servo on its programmer: nothing of a bus to expect there.
        if (!expected.isEmpty())
            findings.append(finding(doctorcodes::kPtkServo,
                                    BusDoctorTr::tr("A PTK servo answers on %1, not a Feetech bus: "
                                                    "connect the Feetech adapter, or use the PTK "
                                                    "workspace.")
                                        .arg(seen.probe.port)));
        return findings;
    }
    if (seen.probed && seen.probe.silent() && seen.found.isEmpty()) {
        findings.append(silenceFinding(seen.probe));
        return findings;
    }
    if (!seen.probed && seen.found.isEmpty()) {
        QStringList rates;
        for (const qint32 baud : seen.scannedBauds)
            rates.append(baudText(baud));
        findings.append(
            finding(doctorcodes::kNoServoFound,
                    BusDoctorTr::tr("No servo answered at %1. Re-scan with the port probed: "
                                    "it listens at every rate and tells silence from "
                                    "bytes that never make an answer.")
                        .arg(rates.join(QStringLiteral(", ")))));
    }
    if (const auto unframed = seen.probed ? unframedFinding(seen) : std::nullopt)
        findings.append(*unframed);
    expectationFindings(seen, expected, findings);
    conditionFindings(seen, findings);
    return findings;
}

QVector<ExpectedServo> rememberedServos(const QString &port)
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("doctor"));
    const QStringList entries =
        settings.value(QStringLiteral("servos/") + QString(port).replace(u'/', u'|'))
            .toStringList();
    QVector<ExpectedServo> servos;
    for (const QString &entry : entries) {
        const QStringList parts = entry.split(u'@');
        bool idOk = false;
        bool baudOk = false;
        const int id = parts.value(0).toInt(&idOk);
        const qint32 baud = parts.value(1).toInt(&baudOk);
        if (idOk && baudOk && id >= 0 && id <= kMaxServoId)
            servos.append({quint8(id), baud});
    }
    return servos;
}

void rememberServos(const QString &port, const QVector<ServoInfo> &servos)
{
    if (servos.isEmpty())
        return; // a bus that came back empty keeps what it held before
    QStringList entries;
    for (const ServoInfo &servo : servos)
        entries.append(QStringLiteral("%1@%2").arg(servo.id).arg(servo.baud));
    QSettings settings;
    settings.beginGroup(QStringLiteral("doctor"));
    settings.setValue(QStringLiteral("servos/") + QString(port).replace(u'/', u'|'), entries);
}

} // namespace feetech
