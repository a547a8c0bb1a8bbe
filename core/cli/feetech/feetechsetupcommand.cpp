// servoctl feetech setup-motor: the one servo on the bus gets an ID, a rate and settings.
#include "feetechsetupcommand.h"

#include "motorsetup.h"
#include "robottemplate.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonArray>
#include <QJsonObject>

namespace cli {

namespace {

QJsonObject addressJson(const ServoInfo &servo)
{
    return {{QStringLiteral("id"), servo.id}, {QStringLiteral("baud"), servo.baud}};
}

} // namespace

feetech::MotorTarget FeetechSetupCommand::motorTarget(const QString &what) const
{
    feetech::MotorTarget target;
    target.id = servoId(what);
    target.baud = kDefaultBaud;
    if (m_args.has(QStringLiteral("settings"))) {
        const QString path = m_args.value(QStringLiteral("settings"));
        util::FileError error;
        const auto robot = feetech::loadRobotTemplate(path, &error);
        if (!robot)
            throw UsageError {error.describe()};
        const auto joint =
            std::find_if(robot->joints.begin(), robot->joints.end(),
                         [&target](const feetech::RobotJoint &j) { return j.id == target.id; });
        if (joint == robot->joints.end())
            throw UsageError {ServoctlTr::tr("%1: \"%2\" has no joint with ID %3")
                                  .arg(what, QDir::toNativeSeparators(path))
                                  .arg(target.id)};
        target = feetech::motorTarget(*robot, *joint);
    }
    if (m_args.has(QStringLiteral("baud")))
        target.baud = parseBaud(QStringLiteral("--baud"), m_args.value(QStringLiteral("baud")));
    if (m_args.has(QStringLiteral("model"))) {
        const QString model = m_args.value(QStringLiteral("model"));
        const auto known = feetech::ModelTable::builtIn().findByName(model);
        if (!known || !known->family)
            throw UsageError {
                ServoctlTr::tr("--model: \"%1\" is no model with a known register table")
                    .arg(model)};
        if (!target.model.isEmpty()
            && feetech::ModelTable::builtIn().findByName(target.model)->name != known->name)
            throw UsageError {ServoctlTr::tr("--model %1 does not match the template's %2 (a %3)")
                                  .arg(model, target.joint, target.model)};
        target.model = known->name;
    }
    return target;
}

int FeetechSetupCommand::setupMotor(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id"), QStringLiteral("model"), QStringLiteral("settings")});
    expectOperands(what, operands, 0, {});
    const feetech::MotorTarget target = motorTarget(what);
    FeetechDevice device(m_args, m_output);
    if (!device.open(kDefaultBaud))
        return fail(device.error());
    const auto finished = device.operate(feetech::operations::setUpMotor(target));
    if (!finished)
        return fail(device.error()); // too slow, or Ctrl-C: the device says which
    // The link dropped: the session ends the set-up without its MotorSetupResult.
    const std::optional<feetech::MotorSetupResult> result =
        finished->detail.canConvert<feetech::MotorSetupResult>()
        ? std::optional(finished->detail.value<feetech::MotorSetupResult>())
        : std::nullopt;
    if (!result)
        return fail(finished->message.isEmpty()
                        ? ServoctlTr::tr("the set-up ended before it reported; check the port and "
                                         "the cable, then run it again")
                        : finished->message);
    if (!result->ok)
        return fail(result->message);
    if (m_output.json) {
        QJsonObject settings;
        for (auto it = result->verified.cbegin(); it != result->verified.cend(); ++it)
            settings.insert(it.key(), it.value());
        printJson(
            m_output.out,
            QJsonObject {{QStringLiteral("model"), result->to.model.name},
                         {QStringLiteral("from"), addressJson(result->from)},
                         {QStringLiteral("to"), addressJson(result->to)},
                         {QStringLiteral("settings"), settings},
                         {QStringLiteral("steps"), QJsonArray::fromStringList(result->steps)}});
        return ExitOk;
    }
    for (const QString &step : std::as_const(result->steps))
        m_output.out << step << '\n';
    m_output.out << result->message << '\n';
    m_output.out.flush();
    return ExitOk;
}

} // namespace cli
