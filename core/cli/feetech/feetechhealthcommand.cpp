// servoctl feetech health: the health check of servos --ids, and with --move-test their move test.
#include "feetechhealthcommand.h"

#include "healthmovetest.h"

#include <QCoreApplication>

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

} // namespace

namespace cli {

namespace {

QString measuredText(const std::optional<double> &value, int decimals, const QString &unit)
{
    return value ? QString::number(*value, 'f', decimals) + QLatin1Char(' ') + unit
                 : Tr::tr("not read");
}

} // namespace

int FeetechHealthCommand::health(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("ids"), QStringLiteral("move-test")});
    expectOperands(what, operands, 0, {});
    const QVector<quint8> ids = jointIds(what);
    const bool moveTest = m_args.flag(QStringLiteral("move-test"));
    FeetechDevice device(m_args, m_output);
    if (!device.open(busBaud()))
        return fail(device.error());

    // A servo that does not answer is a servo with a fault, not the end of the check.
    QVector<feetech::HealthReading> readings(ids.size());
    QVector<ServoInfo> reachable;
    for (int i = 0; i < ids.size(); ++i) {
        readings[i].servo.id = ids.at(i);
        readings[i].servo.baud = busBaud();
        // Addresses 0-8 by READ, not PING first: a servo with its voltage bit set answers a
        // PING with status 0x01, a frame byte for byte the PING itself, taken for its echo.
        const auto memory = device.read(readings.at(i).servo,
                                        {{feetech::kIdentityAddress, feetech::kIdentitySize}});
        const auto servo = memory ? feetech::servoInfoFromIdentity(
                               ids.at(i), busBaud(), memory->value(feetech::kIdentityAddress))
                                  : std::nullopt;
        if (servo) {
            readings[i].servo = *servo;
            reachable.append(*servo);
        } else {
            readings[i].failure =
                memory ? Tr::tr("its identity (addresses 0-8) could not be read") : device.error();
        }
    }
    if (!reachable.isEmpty()) {
        const auto connection =
            QObject::connect(&device.session(), &feetech::Session::operationProgress,
                             [&readings, &ids](const feetech::OperationProgress &progress) {
                                 const auto reading =
                                     progress.detail.value<feetech::HealthReading>();
                                 readings[ids.indexOf(reading.servo.id)] = reading;
                             });
        const auto result = device.operate(
            feetech::operations::checkHealth(reachable, feetech::kDefaultHealthReads));
        QObject::disconnect(connection);
        if (!result || !result->ok)
            return fail(result ? result->message : device.error());
    }
    QVector<feetech::ServoHealth> servos;
    for (const feetech::HealthReading &reading : std::as_const(readings))
        servos.append(feetech::assessHealth(reading));
    feetech::flagFirmwareMismatches(servos);

    if (moveTest) {
        for (feetech::ServoHealth &servo : servos) {
            // A servo with a fault is not moved: the move could make it worse.
            if (servo.verdict == feetech::Verdict::Fault || !servo.position)
                continue;
            const ServoInfo info = reachable.at(
                int(std::find_if(reachable.begin(), reachable.end(),
                                 [&servo](const ServoInfo &s) { return s.id == servo.id; })
                    - reachable.begin()));
            m_output.err << Tr::tr("moving servo %1 by %2 steps from %3 and back…")
                                .arg(servo.id)
                                .arg(feetech::HealthMoveTest::kAmplitude)
                                .arg(*servo.position, 0, 'f', 0)
                         << '\n';
            m_output.err.flush();
            std::optional<feetech::MoveTestResult> moved;
            const auto result = device.operate(feetech::operations::moveTest(info));
            if (result && result->detail.canConvert<feetech::MoveTestResult>())
                moved = result->detail.value<feetech::MoveTestResult>();
            if (!moved) {
                moved = feetech::MoveTestResult {};
                moved->id = servo.id;
                moved->baud = servo.baud;
                moved->message = result ? result->message : device.error();
            }
            feetech::addMoveTest(servo, *moved);
        }
    }

    if (m_output.json) {
        printJson(m_output.out, feetech::healthJson(servos));
    } else {
        for (const feetech::ServoHealth &servo : std::as_const(servos))
            printHealth(servo, moveTest);
    }
    return feetech::anyFault(servos) ? ExitDeviceFailure : ExitOk;
}

void FeetechHealthCommand::printHealth(const feetech::ServoHealth &health, bool moveAsked)
{
    QTextStream &out = m_output.out;
    if (health.model.isEmpty())
        out << Tr::tr("servo %1 (no answer): %2")
                   .arg(health.id)
                   .arg(feetech::verdictName(health.verdict))
            << '\n';
    else
        out << Tr::tr("servo %1 (%2, firmware %3): %4")
                   .arg(health.id)
                   .arg(health.model, health.firmware, feetech::verdictName(health.verdict))
            << '\n';
    out << "  "
        << Tr::tr("voltage %1, temperature %2, load %3, position %4, status %5")
               .arg(measuredText(health.voltage, 1, QStringLiteral("V")),
                    measuredText(health.temperature, 0, QStringLiteral("°C")),
                    measuredText(health.load, 1, QStringLiteral("%")),
                    measuredText(health.position, 0, Tr::tr("steps")),
                    health.statusText.isEmpty() ? Tr::tr("not read") : health.statusText)
        << '\n';
    out << "  " << Tr::tr("communication: %1").arg(feetech::commText(health.comm)) << '\n';
    if (moveAsked)
        out << "  "
            << Tr::tr("move test: %1")
                   .arg(health.move ? feetech::moveText(*health.move)
                                    : Tr::tr("not run (the servo has a fault)"))
            << '\n';
    for (const feetech::HealthFinding &finding : health.findings)
        out << "  - " << feetech::verdictName(finding.severity) << " [" << finding.code << "] "
            << finding.message << '\n';
    out.flush();
}

} // namespace cli
