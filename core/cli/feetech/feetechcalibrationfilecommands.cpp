// servoctl feetech calibration save and load: the servos' offsets and limits to and from a
// LeRobot calibration file.
#include "feetechcalibration.h"
#include "feetechcommand.h"

#include "lerobotcalibration.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonArray>
#include <QJsonObject>

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

} // namespace

namespace cli {

int FeetechCommand::calibration(const QString &what, const QStringList &operands)
{
    if (operands.isEmpty())
        throw UsageError {Tr::tr("%1 needs save or load").arg(what)};
    const QString sub = operands.first();
    const QString named = what + u' ' + sub;
    if (sub == u"save")
        return saveCalibration(named, operands.mid(1));
    if (sub == u"load")
        return loadCalibration(named, operands.mid(1));
    throw UsageError {Tr::tr("unknown %1 command \"%2\": use save or load").arg(what, sub)};
}

int FeetechCommand::saveCalibration(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("ids"), QStringLiteral("names")});
    expectOperands(what, operands, 1, Tr::tr("one FILE"));
    const QVector<quint8> ids = jointIds(what);
    const QStringList names = jointNames(ids);
    const QString path = operands.first();
    checkFolder(path);

    FeetechDevice device(m_args, m_output);
    const auto servos = identifyJoints(device, ids);
    if (!servos)
        return ExitDeviceFailure;
    QVector<feetech::LeRobotMotor> motors;
    for (int i = 0; i < servos->size(); ++i) {
        const ServoInfo &servo = servos->at(i);
        const auto values = readCalibrationRegisters(device, servo);
        if (!values)
            return fail(device.error());
        const feetech::LeRobotMotor motor {
            names.at(i),
            servo.id,
            0,
            values->value(QString::fromUtf16(feetech::kOffsetKey)),
            values->value(QString::fromUtf16(feetech::kMinimumLimitKey)),
            values->value(QString::fromUtf16(feetech::kMaximumLimitKey))};
        // A file LeRobot (and load) could not use is not written.
        if (motor.rangeMin >= motor.rangeMax)
            return fail(Tr::tr("servo %1 holds the limits %2 to %3, which are no calibrated range "
                               "(min = max = 0 is multi-turn mode); %4 was not written")
                            .arg(servo.id)
                            .arg(motor.rangeMin)
                            .arg(motor.rangeMax)
                            .arg(QDir::toNativeSeparators(path)));
        motors.append(motor);
    }
    feetech::keepDriveModes(motors, path);
    QString error;
    if (!feetech::saveLeRobotCalibration(motors, path, &error))
        return fail(error);
    QJsonObject joints;
    for (const feetech::LeRobotMotor &motor : std::as_const(motors))
        joints.insert(motor.name,
                      QJsonObject {{QStringLiteral("id"), motor.id},
                                   {QStringLiteral("drive_mode"), motor.driveMode},
                                   {QStringLiteral("homing_offset"), motor.homingOffset},
                                   {QStringLiteral("range_min"), motor.rangeMin},
                                   {QStringLiteral("range_max"), motor.rangeMax}});
    if (m_output.json)
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("file"), path}, {QStringLiteral("joints"), joints}});
    else
        m_output.out << Tr::tr("saved the calibration of %n servo(s) to %1", nullptr,
                               int(motors.size()))
                            .arg(QDir::toNativeSeparators(path))
                     << '\n';
    m_output.out.flush();
    return ExitOk;
}

int FeetechCommand::loadCalibration(const QString &what, const QStringList &operands)
{
    allowOptions(what, {});
    expectOperands(what, operands, 1, Tr::tr("one FILE"));
    const QString path = operands.first();
    QString error;
    const auto motors = feetech::loadLeRobotCalibration(path, &error);
    if (!motors)
        throw UsageError {error};

    FeetechDevice device(m_args, m_output);
    QVector<quint8> ids;
    for (const feetech::LeRobotMotor &motor : *motors)
        ids.append(quint8(motor.id));
    const auto servos = identifyJoints(device, ids);
    if (!servos)
        return ExitDeviceFailure;
    bool allDone = true;
    QJsonArray reports;
    for (int i = 0; i < motors->size(); ++i) {
        const feetech::LeRobotMotor &motor = motors->at(i);
        const ServoInfo &servo = servos->at(i);
        const auto current = readCalibrationRegisters(device, servo);
        if (!current)
            return fail(device.error());
        const QVector<model::WriteItem> wanted =
            feetech::calibrationWrites(motor.homingOffset, motor.rangeMin, motor.rangeMax);
        QVector<model::WriteItem> changes;
        QJsonArray changesJson;
        QStringList described;
        for (const model::WriteItem &item : wanted) {
            const qint32 now = current->value(item.key);
            // A servo LeRobot gave the limit 4096 holds what the file says.
            const bool asInFile =
                item.key == QString::fromUtf16(feetech::kMaximumLimitKey) && now == motor.rangeMax;
            if (now == item.value || asInFile)
                continue;
            changes.append(item);
            changesJson.append(QJsonObject {{QStringLiteral("key"), item.key},
                                            {QStringLiteral("from"), now},
                                            {QStringLiteral("to"), qint64(item.value)}});
            described.append(QStringLiteral("%1 %2 → %3").arg(item.key).arg(now).arg(item.value));
        }
        QJsonObject report {{QStringLiteral("name"), motor.name},
                            {QStringLiteral("id"), motor.id},
                            {QStringLiteral("drive_mode"), motor.driveMode},
                            {QStringLiteral("changes"), changesJson}};
        const QString joint = Tr::tr("%1 (servo %2)").arg(motor.name).arg(motor.id);
        if (motor.driveMode != 0) {
            const QString kept = Tr::tr("drive_mode %1 is LeRobot's software setting (the "
                                        "direction inverted), held by no register: it is kept "
                                        "in the file only")
                                     .arg(motor.driveMode);
            report.insert(QStringLiteral("drive_mode_note"), kept);
            if (!m_output.json)
                m_output.out << Tr::tr("%1: note: %2").arg(joint, kept) << '\n';
        }
        // A new offset under torque would move the horn to the old goal in new coordinates.
        const bool torqueOn = current->value(QStringLiteral("torque_enable")) != 0;
        QString line;
        if (changes.isEmpty()) {
            report.insert(QStringLiteral("verified"), true);
            line = Tr::tr("%1: already holds the file's values").arg(joint);
        } else if (sharesItsId(device, servo)) {
            return ExitDeviceFailure;
        } else if (torqueOn) {
            allDone = false;
            const QString refusal = Tr::tr("torque is on: the new offset would move the horn; "
                                           "switch torque off (support the arm) and load again");
            report.insert(QStringLiteral("refusal"), refusal);
            line = Tr::tr("%1: %2; refused, nothing written: %3")
                       .arg(joint, described.join(QStringLiteral(", ")), refusal);
        } else {
            const Programmed outcome = writeVerified(device, servo, changes);
            const QJsonObject written = writeJson(outcome, true);
            for (auto it = written.begin(); it != written.end(); ++it)
                report.insert(it.key(), it.value());
            allDone = allDone && isVerified(outcome);
            line = isVerified(outcome)
                ? Tr::tr("%1: %2; written and verified")
                      .arg(joint, described.join(QStringLiteral(", ")))
                : Tr::tr("%1: %2; NOT verified: %3")
                      .arg(joint, described.join(QStringLiteral(", ")), problemText(outcome));
        }
        reports.append(report);
        if (!m_output.json)
            m_output.out << line << '\n';
    }
    if (m_output.json)
        printJson(
            m_output.out,
            QJsonObject {{QStringLiteral("file"), path}, {QStringLiteral("joints"), reports}});
    m_output.out.flush();
    if (!allDone)
        return fail(Tr::tr("the calibration of %1 was not loaded whole: see above")
                        .arg(QDir::toNativeSeparators(path)));
    return ExitOk;
}

} // namespace cli
