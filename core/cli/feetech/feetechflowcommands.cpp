// servoctl feetech set-id, set-baud, calibrate-middle, factory-reset, reboot, lock, recover and
// identify: guided flows.
#include "feetechflowcommands.h"

#include "hex.h"
#include "profile.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QJsonObject>

namespace cli {

// Runs one flow and reports it: its message, the servo as it is reached afterwards.
int FeetechFlowCommands::report(Target &target, const feetech::BusOperation &operation,
                                const std::function<void(QJsonObject &, const Memory &)> &more)
{
    Memory readBack;
    const auto result = target.device->operate(operation, &readBack);
    if (!result)
        return fail(target.device->error());
    if (!result->ok)
        return fail(result->message);
    if (m_output.json) {
        QJsonObject object {{QStringLiteral("ok"), true},
                            {QStringLiteral("message"), result->message},
                            {QStringLiteral("servo"), servoJson(result->servo)}};
        if (more)
            more(object, readBack);
        printJson(m_output.out, object);
    } else {
        m_output.out << result->message << '\n';
        if (more) {
            QJsonObject object;
            more(object, readBack);
            for (auto it = object.constBegin(); it != object.constEnd(); ++it)
                m_output.out << it.key() << ": " << it.value().toVariant().toString() << '\n';
        }
        m_output.out.flush();
    }
    return ExitOk;
}

// Nothing to do: the servo already is as asked.
int FeetechFlowCommands::alreadyDone(const ServoInfo &servo, const QString &message)
{
    if (m_output.json)
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("ok"), true},
                               {QStringLiteral("message"), message},
                               {QStringLiteral("servo"), servoJson(servo)}});
    else
        m_output.out << message << '\n';
    m_output.out.flush();
    return ExitOk;
}

int FeetechFlowCommands::setId(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 1, ServoctlTr::tr("the NEW ID"));
    const auto newId = util::parseInteger(operands.first());
    if (!newId || *newId < 0 || *newId > feetech::kMaxServoId)
        throw UsageError {ServoctlTr::tr("%1: \"%2\" is not an ID (0 to %3)")
                              .arg(what, operands.first())
                              .arg(feetech::kMaxServoId)};
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    if (sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    if (*newId == target->servo.id)
        return alreadyDone(
            target->servo,
            ServoctlTr::tr("servo %1 already has ID %1; nothing written").arg(target->servo.id));
    // No list of IDs in use: the session's PING of the new ID refuses an occupied one.
    return report(*target, feetech::operations::changeId(target->servo, int(*newId), {}));
}

int FeetechFlowCommands::setBaud(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 1, ServoctlTr::tr("the new BAUD rate in bits per second"));
    const qint32 newBaud = parseBaud(what, operands.first());
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    if (sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    if (newBaud == servo.baud)
        return alreadyDone(servo,
                           ServoctlTr::tr("servo %1 already runs at %2; nothing written")
                               .arg(servo.id)
                               .arg(baudNumberText(servo.baud)));
    if (const feetech::Register *reg = servo.table().find(u"baud_rate")) {
        if (servo.hasTable() && *feetech::baudCode(newBaud) > reg->maximum)
            throw UsageError {ServoctlTr::tr("%1 servos do not support %2")
                                  .arg(familyText(servo), baudNumberText(newBaud))};
    }
    return report(*target, feetech::operations::changeBaud(target->servo, newBaud));
}

int FeetechFlowCommands::calibrateMiddle(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    if (sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    const feetech::RegisterTable &table = target->servo.table();
    return report(*target, feetech::operations::calibrateMiddle(target->servo),
                  [&table](QJsonObject &object, const Memory &readBack) {
                      const QHash<QString, qint32> values =
                          valuesByKey(decodeMemory(table, readBack));
                      if (values.contains(QStringLiteral("position_offset")))
                          object.insert(QStringLiteral("position_offset"),
                                        values.value(QStringLiteral("position_offset")));
                  });
}

int FeetechFlowCommands::factoryReset(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id"), QStringLiteral("backup")});
    expectOperands(what, operands, 0, {});
    const quint8 id = servoId(what);
    QString backup = m_args.value(QStringLiteral("backup"));
    if (m_args.has(QStringLiteral("backup"))) {
        if (backup.isEmpty())
            throw UsageError {ServoctlTr::tr("--backup needs a FILE")};
        checkFolder(backup);
    } else {
        backup = QDir::current().filePath(
            QStringLiteral("servo-%1-backup-%2.json")
                .arg(id)
                .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"))));
    }
    auto target = identifyKnownServo(
        what,
        ServoctlTr::tr("servo %1 is of an unknown model (%2): no backup can be saved, so "
                       "it is not reset"));
    if (!target)
        return ExitDeviceFailure;
    if (sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QString error;
    util::FileError notSaved;
    // The backup first: without it on disk, nothing is reset.
    const auto saved = takeProfile(*target, &error);
    if (saved
        && !profile::save(backup, *saved, feetech::profileDefinitions(servo.table()), &notSaved))
        error = notSaved.describe();
    if (!saved || notSaved)
        return fail(ServoctlTr::tr("the backup could not be saved, so the servo was not reset: %1")
                        .arg(error));
    if (!m_output.json) {
        m_output.out << ServoctlTr::tr("backup of servo %1 saved to %2")
                            .arg(servo.id)
                            .arg(QDir::toNativeSeparators(backup))
                     << '\n';
        m_output.out.flush();
    }
    return report(*target, feetech::operations::factoryReset(target->servo),
                  [this, backup](QJsonObject &object, const Memory &) {
                      if (m_output.json)
                          object.insert(QStringLiteral("backup"), backup);
                  });
}

int FeetechFlowCommands::reboot(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    if (sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    return report(*target, feetech::operations::reboot(target->servo));
}

int FeetechFlowCommands::lock(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    auto target = identifyKnownServo(
        what, ServoctlTr::tr("servo %1 is of an unknown model (%2): its EEPROM lock is not known"));
    if (!target)
        return ExitDeviceFailure;
    if (sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    return report(*target, feetech::operations::lockEeprom(target->servo));
}

int FeetechFlowCommands::recover(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id"), QStringLiteral("check")});
    expectOperands(what, operands, 0, {});
    const bool checkOnly = m_args.flag(QStringLiteral("check"));
    auto target = identifyKnownServo(
        what,
        ServoctlTr::tr("servo %1 is of an unknown model (%2): its status bits are not known"));
    if (!target)
        return ExitDeviceFailure;
    if (!checkOnly && sharesItsId(*target->device, target->servo))
        return ExitDeviceFailure;
    // Still tripped, the result's message is the power-cycle steps: printed as the failure.
    const quint8 id = target->servo.id;
    const int code =
        report(*target, feetech::operations::recoverOverload(target->servo, checkOnly));
    if (code != ExitOk && !checkOnly) {
        m_output.err << "servoctl: "
                     << ServoctlTr::tr(
                            "after the power cycle: servoctl feetech recover --id %1 --check")
                            .arg(id)
                     << '\n';
        m_output.err.flush();
    }
    return code;
}

int FeetechFlowCommands::identify(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    auto target = identifyServoToWrite(what);
    if (!target)
        return ExitDeviceFailure;
    if (!m_output.json) {
        m_output.out
            << ServoctlTr::tr("moving servo %1 a little each way, slowly…").arg(target->servo.id)
            << '\n';
        m_output.out.flush();
    }
    return report(*target, feetech::operations::identifyJoint(target->servo));
}

} // namespace cli
