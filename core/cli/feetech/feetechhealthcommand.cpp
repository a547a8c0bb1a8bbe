// servoctl feetech health and check: the health check with its move test, the settings check
// with its fixes.
#include "feetechhealthcommand.h"

#include "healthmovetest.h"
#include "robottemplate.h"
#include "servoctltr.h"

#include <QDir>
#include <QFileInfo>

#include <QCoreApplication>

namespace cli {

namespace {

QString measuredText(const std::optional<double> &value, int decimals, const QString &unit)
{
    return value ? QString::number(*value, 'f', decimals) + QLatin1Char(' ') + unit
                 : ServoctlTr::tr("not read");
}

} // namespace

template<typename Reading>
std::optional<FeetechHealthCommand::Readings<Reading>> FeetechHealthCommand::readEach(
    FeetechDevice &device, const QVector<quint8> &ids,
    const std::function<feetech::BusOperation(const QVector<ServoInfo> &)> &operation)
{
    Readings<Reading> read;
    read.readings.resize(ids.size());
    const QVector<Identified> identified = identifyEach(device, ids);
    for (int i = 0; i < ids.size(); ++i) {
        read.readings[i].servo = identified.at(i).servo;
        read.readings[i].failure = identified.at(i).failure;
        if (identified.at(i).failure.isEmpty())
            read.reachable.append(identified.at(i).servo);
    }
    if (read.reachable.isEmpty())
        return read;
    const auto connection =
        QObject::connect(&device.session(), &feetech::Session::operationProgress,
                         [&read, &ids](const feetech::OperationProgress &progress) {
                             const auto reading = progress.detail.value<Reading>();
                             read.readings[ids.indexOf(reading.servo.id)] = reading;
                         });
    const auto result = device.operate(operation(read.reachable));
    QObject::disconnect(connection);
    if (!result || !result->ok) {
        fail(result ? result->message : device.error());
        return std::nullopt;
    }
    return read;
}

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
    const auto read =
        readEach<feetech::HealthReading>(device, ids, [](const QVector<ServoInfo> &servos) {
            return feetech::operations::checkHealth(servos, feetech::kDefaultHealthReads);
        });
    if (!read)
        return ExitDeviceFailure;
    const QVector<feetech::HealthReading> &readings = read->readings;
    const QVector<ServoInfo> &reachable = read->reachable;
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
            m_output.err << ServoctlTr::tr("moving servo %1 by %2 steps from %3 and back…")
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

auto FeetechHealthCommand::identifyEach(FeetechDevice &device, const QVector<quint8> &ids)
    -> QVector<Identified>
{
    QVector<Identified> identified(ids.size());
    for (int i = 0; i < ids.size(); ++i) {
        identified[i].servo.id = ids.at(i);
        identified[i].servo.baud = busBaud();
        // Addresses 0-8 by READ, not PING first: a servo with its voltage bit set answers a
        // PING with status 0x01, a frame byte for byte the PING itself, taken for its echo.
        const auto memory = device.read(identified.at(i).servo,
                                        {{feetech::kIdentityAddress, feetech::kIdentitySize}});
        const auto servo = memory ? feetech::servoInfoFromIdentity(
                               ids.at(i), busBaud(), memory->value(feetech::kIdentityAddress))
                                  : std::nullopt;
        if (servo)
            identified[i].servo = *servo;
        else
            identified[i].failure = memory
                ? ServoctlTr::tr("its identity (addresses 0-8) could not be read")
                : device.error();
    }
    return identified;
}

feetech::SettingsExpectations FeetechHealthCommand::expectations(const QString &what) const
{
    if (!m_args.has(QStringLiteral("robot")))
        return {};
    const QString name = m_args.value(QStringLiteral("robot"));
    const QString builtIn = QStringLiteral(":/robots/%1.json").arg(name);
    const QString path = QFileInfo::exists(builtIn) ? builtIn : name;
    util::FileError error;
    const auto robot = feetech::loadRobotTemplate(path, &error);
    if (!robot)
        throw UsageError {ServoctlTr::tr("%1 --robot: %2").arg(what, error.describe())};
    return feetech::settingsExpectations(*robot);
}

int FeetechHealthCommand::check(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("ids"), QStringLiteral("robot"), QStringLiteral("fix")});
    expectOperands(what, operands, 0, {});
    const QVector<quint8> ids = jointIds(what);
    const feetech::SettingsExpectations expected = expectations(what);
    const bool fix = m_args.flag(QStringLiteral("fix"));
    FeetechDevice device(m_args, m_output);
    if (!device.open(busBaud()))
        return fail(device.error());

    const auto read = readEach<feetech::SettingsReading>(
        device, ids, [&expected](const QVector<ServoInfo> &servos) {
            return feetech::operations::checkSettings(servos, expected.keys());
        });
    if (!read)
        return ExitDeviceFailure;
    const QVector<feetech::SettingsFinding> findings =
        feetech::checkSettings(read->readings, expected);

    if (!fix || findings.isEmpty()) {
        if (m_output.json) {
            QJsonArray rows;
            for (const feetech::SettingsFinding &finding : findings)
                rows.append(feetech::settingsFindingJson(finding));
            printJson(m_output.out, rows);
        } else {
            printFindings(findings, int(ids.size()));
        }
        return findings.isEmpty() ? ExitOk : ExitDeviceFailure;
    }

    QVector<feetech::SettingsFinding> fixable;
    for (const feetech::SettingsFinding &finding : findings) {
        if (finding.fixable())
            fixable.append(finding);
    }
    QVector<feetech::SettingsFixOutcome> outcomes;
    if (!fixable.isEmpty()) {
        m_output.err << ServoctlTr::tr("fixing %n setting(s)…", nullptr, int(fixable.size()))
                     << '\n';
        m_output.err.flush();
        const auto result = device.operate(feetech::operations::fixSettings(fixable));
        if (!result || !result->detail.canConvert<QVector<feetech::SettingsFixOutcome>>())
            return fail(result ? result->message : device.error());
        outcomes = result->detail.value<QVector<feetech::SettingsFixOutcome>>();
    }
    // Every finding once, in the check's order: fixed or not, and why.
    QVector<feetech::SettingsFixOutcome> rows;
    int pending = 0;
    for (const feetech::SettingsFinding &finding : findings) {
        if (finding.fixable()) {
            rows.append(outcomes.value(pending++));
            continue;
        }
        feetech::SettingsFixOutcome notFixable;
        notFixable.finding = finding;
        notFixable.code = feetech::SettingsFixOutcome::Code::NotFixable;
        notFixable.why = ServoctlTr::tr("nothing to write fixes this");
        rows.append(notFixable);
    }
    if (m_output.json) {
        QJsonArray json;
        for (const feetech::SettingsFixOutcome &outcome : std::as_const(rows))
            json.append(feetech::settingsFixJson(outcome));
        printJson(m_output.out, json);
    } else {
        printFixes(rows);
    }
    const bool allFixed = std::all_of(rows.begin(), rows.end(),
                                      [](const auto &outcome) { return outcome.verified(); });
    return allFixed ? ExitOk : ExitDeviceFailure;
}

namespace {

QString valueText(const feetech::SettingsFinding &finding)
{
    if (!finding.valueText.isEmpty())
        return finding.valueText;
    return finding.value ? QString::number(*finding.value) : QStringLiteral("-");
}

QString expectedText(const feetech::SettingsFinding &finding)
{
    return finding.expected ? QString::number(*finding.expected) : QStringLiteral("-");
}

} // namespace

void FeetechHealthCommand::printFindings(const QVector<feetech::SettingsFinding> &findings,
                                         int servos)
{
    QTextStream &out = m_output.out;
    if (findings.isEmpty()) {
        out << ServoctlTr::tr("No problem found in the settings of %n servo(s).", nullptr, servos)
            << '\n';
        out.flush();
        return;
    }
    out << QStringLiteral("%1  %2  %3  %4  %5")
               .arg(ServoctlTr::tr("ID"), -4)
               .arg(ServoctlTr::tr("SETTING"), -18)
               .arg(ServoctlTr::tr("VALUE"), -8)
               .arg(ServoctlTr::tr("EXPECTED"), -8)
               .arg(ServoctlTr::tr("WHY"))
        << '\n';
    for (const feetech::SettingsFinding &finding : findings)
        out << QStringLiteral("%1  %2  %3  %4  %5")
                   .arg(finding.servo.id, -4)
                   .arg(finding.key.isEmpty() ? finding.code : finding.key, -18)
                   .arg(valueText(finding), -8)
                   .arg(expectedText(finding), -8)
                   .arg(finding.why)
            << '\n';
    out << ServoctlTr::tr("%n finding(s); --fix writes the expected values and reads them back.",
                          nullptr, int(findings.size()))
        << '\n';
    out.flush();
}

void FeetechHealthCommand::printFixes(const QVector<feetech::SettingsFixOutcome> &outcomes)
{
    QTextStream &out = m_output.out;
    for (const feetech::SettingsFixOutcome &outcome : outcomes) {
        const feetech::SettingsFinding &finding = outcome.finding;
        out << ServoctlTr::tr("servo %1 %2: %3 → %4: %5")
                   .arg(finding.servo.id)
                   .arg(finding.key.isEmpty() ? finding.code : finding.key, valueText(finding),
                        expectedText(finding), feetech::fixOutcomeText(outcome))
            << '\n';
        if (!outcome.verified())
            out << "  " << finding.why << '\n';
    }
    out.flush();
}

void FeetechHealthCommand::printHealth(const feetech::ServoHealth &health, bool moveAsked)
{
    QTextStream &out = m_output.out;
    if (health.model.isEmpty())
        out << ServoctlTr::tr("servo %1 (no answer): %2")
                   .arg(health.id)
                   .arg(feetech::verdictName(health.verdict))
            << '\n';
    else
        out << ServoctlTr::tr("servo %1 (%2, firmware %3): %4")
                   .arg(health.id)
                   .arg(health.model, health.firmware, feetech::verdictName(health.verdict))
            << '\n';
    out << "  "
        << ServoctlTr::tr("voltage %1, temperature %2, load %3, position %4, status %5")
               .arg(measuredText(health.voltage, 1, QStringLiteral("V")),
                    measuredText(health.temperature, 0, QStringLiteral("°C")),
                    measuredText(health.load, 1, QStringLiteral("%")),
                    measuredText(health.position, 0, ServoctlTr::tr("steps")),
                    health.statusText.isEmpty() ? ServoctlTr::tr("not read") : health.statusText)
        << '\n';
    out << "  " << ServoctlTr::tr("communication: %1").arg(feetech::commText(health.comm)) << '\n';
    if (moveAsked)
        out << "  "
            << ServoctlTr::tr("move test: %1")
                   .arg(health.move ? feetech::moveText(*health.move)
                                    : ServoctlTr::tr("not run (the servo has a fault)"))
            << '\n';
    for (const feetech::HealthFinding &finding : health.findings)
        out << "  - " << feetech::verdictName(finding.severity) << " [" << finding.code << "] "
            << finding.message << '\n';
    out.flush();
}

} // namespace cli
