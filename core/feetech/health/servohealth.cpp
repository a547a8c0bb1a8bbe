// Health verdicts: each reading compared with the servo's own limits, findings by code.
#include "servohealth.h"

#include "registerkeys.h"

#include <QCoreApplication>
#include <QMap>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace {

struct ServoHealthTr
{
    Q_DECLARE_TR_FUNCTIONS(ServoHealth)
};

} // namespace

namespace feetech {

namespace {

QJsonValue optionalJson(const std::optional<double> &value)
{
    return value ? QJsonValue(*value) : QJsonValue();
}

QString number(double value, int decimals)
{
    return QString::number(value, 'f', decimals);
}

// The status register's bits by the names its table gives them.
void addStatusFindings(ServoHealth &health, const RegisterTable &table)
{
    const Register *status = table.find(u"status");
    for (int bit = 0; bit < 8; ++bit) {
        if (!(health.status & (1 << bit)))
            continue;
        QString label;
        if (status) {
            for (const BitName &named : status->bits) {
                if (named.bit == bit)
                    label = named.label;
            }
        }
        const QString code = label.isEmpty() ? QStringLiteral("status-bit-%1").arg(bit)
                                             : QStringLiteral("status-")
                + label.toLower().replace(QLatin1Char(' '), QLatin1Char('-'));
        const QString name = label.isEmpty() ? ServoHealthTr::tr("bit %1").arg(bit) : label;
        health.add(code, Verdict::Fault,
                   ServoHealthTr::tr(
                       "The servo reports a %1 error (status bit %2): its protection tripped.")
                       .arg(name)
                       .arg(bit));
    }
}

void addVoltageFindings(ServoHealth &health, const HealthReading &reading,
                        const HealthLimits &limits)
{
    if (!health.voltage)
        return;
    const double volts = *health.voltage;
    const auto low = reading.minVoltage;
    const auto high = reading.maxVoltage;
    if (high && *high > 0 && volts > *high) {
        health.add(
            QStringLiteral("voltage-high"), Verdict::Fault,
            ServoHealthTr::tr("The supply reads %1 V, above the servo's maximum of %2 V: use a "
                              "supply the servo is made for.")
                .arg(number(volts, 1), number(*high, 1)));
    } else if (low && volts < *low) {
        health.add(QStringLiteral("voltage-low"), Verdict::Fault,
                   ServoHealthTr::tr(
                       "The supply reads %1 V, below the servo's minimum of %2 V: charge the "
                       "battery or check the supply and its wires.")
                       .arg(number(volts, 1), number(*low, 1)));
    } else if (high && *high > 0 && volts > *high * (1.0 - limits.voltageMargin)) {
        health.add(QStringLiteral("voltage-near-max"), Verdict::Warning,
                   ServoHealthTr::tr("The supply reads %1 V, close to the servo's maximum of %2 V.")
                       .arg(number(volts, 1), number(*high, 1)));
    } else if (low && *low > 0 && volts < *low * (1.0 + limits.voltageMargin)) {
        health.add(QStringLiteral("voltage-near-min"), Verdict::Warning,
                   ServoHealthTr::tr("The supply reads %1 V, close to the servo's minimum of %2 V.")
                       .arg(number(volts, 1), number(*low, 1)));
    }
}

void addTemperatureFindings(ServoHealth &health, const HealthReading &reading,
                            const HealthLimits &limits)
{
    if (!health.temperature || !reading.maxTemperature || *reading.maxTemperature <= 0)
        return;
    const double celsius = *health.temperature;
    const double maximum = *reading.maxTemperature;
    if (celsius >= maximum) {
        health.add(
            QStringLiteral("temperature-over"), Verdict::Fault,
            ServoHealthTr::tr("The servo is at %1 °C, at or over its maximum of %2 °C: let it cool "
                              "and look for what makes it work so hard.")
                .arg(number(celsius, 0), number(maximum, 0)));
    } else if (celsius >= maximum - limits.temperatureMargin) {
        health.add(QStringLiteral("temperature-high"), Verdict::Warning,
                   ServoHealthTr::tr("The servo is at %1 °C, within %2 °C of its maximum of %3 °C.")
                       .arg(number(celsius, 0), number(maximum - celsius, 0), number(maximum, 0)));
    }
}

void addCommFindings(ServoHealth &health)
{
    const CommQuality &comm = health.comm;
    if (comm.reads > 0 && comm.answered == 0) {
        health.add(QStringLiteral("comm-silent"), Verdict::Fault,
                   ServoHealthTr::tr(
                       "None of %n feedback read(s) was answered: check the servo's cable and "
                       "power.",
                       nullptr, comm.reads));
    } else if (comm.answered < comm.reads) {
        health.add(
            QStringLiteral("comm-lost"), Verdict::Warning,
            ServoHealthTr::tr("%1 of %n feedback read(s) went unanswered even after retries (%2): "
                              "check the cable, its connectors and the bus's length.",
                              nullptr, comm.reads)
                .arg(comm.reads - comm.answered)
                .arg(commText(comm)));
    } else if (!comm.clean()) {
        health.add(
            QStringLiteral("comm-retries"), Verdict::Warning,
            ServoHealthTr::tr("Every read was answered, but not at the first try (%1): the line is "
                              "noisy or marginal.")
                .arg(commText(comm)));
    }
}

} // namespace

QString verdictKey(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Ok:
        return QStringLiteral("ok");
    case Verdict::Warning:
        return QStringLiteral("warning");
    case Verdict::Fault:
        return QStringLiteral("fault");
    }
    return {};
}

QString verdictName(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Ok:
        return ServoHealthTr::tr("OK");
    case Verdict::Warning:
        return ServoHealthTr::tr("Warning");
    case Verdict::Fault:
        return ServoHealthTr::tr("Fault");
    }
    return {};
}

void ServoHealth::add(const QString &code, Verdict severity, const QString &message)
{
    findings.append({code, message, severity});
    verdict = std::max(verdict, severity);
}

ServoHealth assessHealth(const HealthReading &reading, const HealthLimits &limits)
{
    ServoHealth health;
    const ServoInfo &servo = reading.servo;
    health.id = servo.id;
    health.baud = servo.baud;
    health.model = servo.model.name;
    // A servo that never answered has no firmware to show.
    if (!servo.model.name.isEmpty())
        health.firmware = servo.firmware();
    health.comm = reading.comm;
    if (!reading.failure.isEmpty()) {
        health.add(QStringLiteral("unreadable"), Verdict::Fault,
                   ServoHealthTr::tr("Its settings could not be read: %1").arg(reading.failure));
        return health;
    }
    if (!servo.hasTable())
        health.add(
            QStringLiteral("unknown-model"), Verdict::Warning,
            ServoHealthTr::tr("ServoBench has no register table for model %1: only its answers are "
                              "checked.")
                .arg(servo.model.name));
    double voltageSum = 0;
    double loadSum = 0;
    int voltages = 0;
    int loads = 0;
    for (const FeedbackSample &sample : reading.samples) {
        if (const auto volts = sample.value(Quantity::Voltage)) {
            voltageSum += *volts;
            ++voltages;
        }
        if (const auto celsius = sample.value(Quantity::Temperature))
            health.temperature = std::max(health.temperature.value_or(*celsius), *celsius);
        if (const auto load = sample.value(Quantity::Load)) {
            loadSum += std::abs(*load);
            ++loads;
        }
        if (const auto position = sample.value(Quantity::Position))
            health.position = *position;
        health.status |= sample.servoStatus;
    }
    if (voltages > 0) // the register's resolution is 0.1 V: no more digits than it has
        health.voltage = std::round(voltageSum / voltages * 100.0) / 100.0;
    if (loads > 0)
        health.load = loadSum / loads;
    health.statusText = servoStatusText(servo.table(), health.status);

    addVoltageFindings(health, reading, limits);
    addTemperatureFindings(health, reading, limits);
    addStatusFindings(health, servo.table());
    const double loadLimit = reading.overloadPercent.value_or(limits.loadWarningPercent);
    if (health.load && loadLimit > 0 && *health.load >= loadLimit)
        health.add(
            QStringLiteral("load-high"), Verdict::Warning,
            ServoHealthTr::tr("The servo works at %1 % load while the check reads it, at or over "
                              "its overload level of %2 %: something pushes against the horn.")
                .arg(number(*health.load, 1), number(loadLimit, 0)));
    // Both limits 0 is multi-turn or wheel mode: no limits to stand within.
    const bool limited =
        reading.minAngle && reading.maxAngle && !(*reading.minAngle == 0 && *reading.maxAngle == 0);
    if (health.position && limited
        && (*health.position < *reading.minAngle || *health.position > *reading.maxAngle))
        health.add(QStringLiteral("position-outside-limits"), Verdict::Warning,
                   ServoHealthTr::tr(
                       "The horn stands at %1, outside its angle limits %2 to %3: it cannot be "
                       "sent back there, and the limits may be wrong.")
                       .arg(number(*health.position, 0), number(*reading.minAngle, 0),
                            number(*reading.maxAngle, 0)));
    addCommFindings(health);
    return health;
}

void addMoveTest(ServoHealth &health, const MoveTestResult &move, const HealthLimits &limits)
{
    health.move = move;
    if (!move.ok) {
        health.add(QStringLiteral("move-failed"), Verdict::Fault,
                   ServoHealthTr::tr("The move test did not complete: %1").arg(move.message));
        return;
    }
    const auto &metrics = move.metrics;
    if (!metrics || !metrics->riseTime || !metrics->settled) {
        health.add(
            QStringLiteral("move-not-reached"), Verdict::Fault,
            ServoHealthTr::tr("The horn did not follow a move of %1 steps from %2 to %3: it may be "
                              "blocked, or its torque is limited.")
                .arg(std::abs(move.target - move.start))
                .arg(move.start)
                .arg(move.target));
        return;
    }
    if (metrics->overshootPercent && *metrics->overshootPercent > limits.overshootWarningPercent)
        health.add(QStringLiteral("move-overshoot"), Verdict::Warning,
                   ServoHealthTr::tr("The move overshot by %1 %: its gains may be too high.")
                       .arg(number(*metrics->overshootPercent, 1)));
    if (metrics->steadyStateError
        && std::abs(*metrics->steadyStateError) > limits.steadyErrorWarning)
        health.add(QStringLiteral("move-steady-error"), Verdict::Warning,
                   ServoHealthTr::tr(
                       "The horn stopped %1 steps from its goal: a load holds it off, or its "
                       "dead zone is wide.")
                       .arg(number(std::abs(*metrics->steadyStateError), 0)));
}

void flagFirmwareMismatches(QVector<ServoHealth> &servos)
{
    QMap<QString, QSet<QString>> firmwareByModel;
    for (const ServoHealth &servo : servos) {
        if (!servo.model.isEmpty())
            firmwareByModel[servo.model].insert(servo.firmware);
    }
    for (ServoHealth &servo : servos) {
        const QSet<QString> &firmware = firmwareByModel.value(servo.model);
        if (firmware.size() < 2)
            continue;
        QStringList others;
        for (const ServoHealth &other : servos) {
            if (other.model == servo.model && other.firmware != servo.firmware)
                others.append(
                    ServoHealthTr::tr("servo %1 has %2").arg(other.id).arg(other.firmware));
        }
        servo.add(QStringLiteral("firmware-mismatch"), Verdict::Warning,
                  ServoHealthTr::tr(
                      "Its firmware %1 differs from other %2 servos on the bus (%3): they may "
                      "behave differently with the same settings.")
                      .arg(servo.firmware, servo.model, others.join(QStringLiteral(", "))));
    }
}

bool anyFault(const QVector<ServoHealth> &servos)
{
    return std::any_of(servos.begin(), servos.end(),
                       [](const ServoHealth &servo) { return servo.verdict == Verdict::Fault; });
}

QString commText(const CommQuality &comm)
{
    return ServoHealthTr::tr("%1/%2 answered, %3 retries, %4 timeouts, %5 checksum errors")
        .arg(comm.answered)
        .arg(comm.reads)
        .arg(comm.retries)
        .arg(comm.timeouts)
        .arg(comm.checksumErrors);
}

QString moveText(const MoveTestResult &move)
{
    if (!move.ok || !move.metrics)
        return move.message.isEmpty() ? ServoHealthTr::tr("not measured") : move.message;
    const StepMetrics &m = *move.metrics;
    const QString none = ServoHealthTr::tr("none");
    return ServoHealthTr::tr("%1 → %2: rise %3, overshoot %4, steady-state error %5")
        .arg(move.start)
        .arg(move.target)
        .arg(m.riseTime ? ServoHealthTr::tr("%1 s").arg(number(*m.riseTime, 3)) : none,
             m.overshootPercent ? ServoHealthTr::tr("%1 %").arg(number(*m.overshootPercent, 1))
                                : none,
             m.steadyStateError ? ServoHealthTr::tr("%1 steps").arg(number(*m.steadyStateError, 1))
                                : none);
}

QJsonObject healthJson(const ServoHealth &health)
{
    QJsonArray findings;
    for (const HealthFinding &finding : health.findings)
        findings.append(QJsonObject {{QStringLiteral("code"), finding.code},
                                     {QStringLiteral("message"), finding.message},
                                     {QStringLiteral("severity"), verdictKey(finding.severity)}});
    const CommQuality &comm = health.comm;
    QJsonObject json {{QStringLiteral("id"), health.id},
                      {QStringLiteral("baud"), health.baud},
                      {QStringLiteral("model"), health.model},
                      {QStringLiteral("firmware"),
                       health.firmware.isEmpty() ? QJsonValue() : QJsonValue(health.firmware)},
                      {QStringLiteral("verdict"), verdictKey(health.verdict)},
                      {QStringLiteral("findings"), findings},
                      {QStringLiteral("voltage"), optionalJson(health.voltage)},
                      {QStringLiteral("temperature"), optionalJson(health.temperature)},
                      {QStringLiteral("load"), optionalJson(health.load)},
                      {QStringLiteral("position"), optionalJson(health.position)},
                      {QStringLiteral("status"), health.status},
                      {QStringLiteral("comm"),
                       QJsonObject {{QStringLiteral("reads"), comm.reads},
                                    {QStringLiteral("answered"), comm.answered},
                                    {QStringLiteral("retries"), comm.retries},
                                    {QStringLiteral("timeouts"), comm.timeouts},
                                    {QStringLiteral("checksum_errors"), comm.checksumErrors}}}};
    if (health.move) {
        const MoveTestResult &move = *health.move;
        QJsonObject moved {{QStringLiteral("ok"), move.ok},
                           {QStringLiteral("message"), move.message},
                           {QStringLiteral("start"), move.start},
                           {QStringLiteral("target"), move.target}};
        if (move.metrics) {
            moved.insert(QStringLiteral("rise_time_s"), optionalJson(move.metrics->riseTime));
            moved.insert(QStringLiteral("overshoot_percent"),
                         optionalJson(move.metrics->overshootPercent));
            moved.insert(QStringLiteral("steady_state_error"),
                         optionalJson(move.metrics->steadyStateError));
            moved.insert(QStringLiteral("settled"), move.metrics->settled);
        }
        json.insert(QStringLiteral("move"), moved);
    }
    return json;
}

QJsonArray healthJson(const QVector<ServoHealth> &servos)
{
    QJsonArray array;
    for (const ServoHealth &servo : servos)
        array.append(healthJson(servo));
    return array;
}

} // namespace feetech
