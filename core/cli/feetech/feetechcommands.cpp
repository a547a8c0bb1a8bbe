// servoctl feetech: picks the command group that runs the command.
#include "feetechcommands.h"

#include "feetechcalibrationcommands.h"
#include "feetechflowcommands.h"
#include "feetechhealthcommand.h"
#include "feetechmonitorcommand.h"
#include "feetechmotioncommands.h"
#include "feetechprofilecommands.h"
#include "feetechregistercommands.h"
#include "feetechsetupcommand.h"
#include "feetechteleopcommand.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QVector>

#include <utility>

namespace cli {

namespace {

using Runner = int (*)(const Arguments &, const Output &, const QString &, const QStringList &);

// A fresh group for each command: what a group notes (such as an unlocked servo) is noted once
// per command.
template<typename Group, int (Group::*command)(const QString &, const QStringList &)>
int runIn(const Arguments &args, const Output &output, const QString &what,
          const QStringList &operands)
{
    Group group(args, output);
    return (group.*command)(what, operands);
}

} // namespace

int runFeetechCommand(const Arguments &args, const QStringList &rest, const Output &output)
{
    if (rest.isEmpty())
        throw UsageError {ServoctlTr::tr("feetech needs a command (try servoctl --help)")};
    const QString command = rest.first();
    const QStringList operands = rest.mid(1);
    static const QVector<std::pair<const char *, Runner>> kCommands {
        {"scan", &runIn<FeetechRegisterCommands, &FeetechRegisterCommands::scan>},
        {"ping", &runIn<FeetechRegisterCommands, &FeetechRegisterCommands::ping>},
        {"read", &runIn<FeetechRegisterCommands, &FeetechRegisterCommands::read>},
        {"get", &runIn<FeetechRegisterCommands, &FeetechRegisterCommands::get>},
        {"set", &runIn<FeetechRegisterCommands, &FeetechRegisterCommands::set>},
        {"save", &runIn<FeetechProfileCommands, &FeetechProfileCommands::save>},
        {"load", &runIn<FeetechProfileCommands, &FeetechProfileCommands::load>},
        {"set-id", &runIn<FeetechFlowCommands, &FeetechFlowCommands::setId>},
        {"set-baud", &runIn<FeetechFlowCommands, &FeetechFlowCommands::setBaud>},
        {"calibrate-middle", &runIn<FeetechFlowCommands, &FeetechFlowCommands::calibrateMiddle>},
        {"factory-reset", &runIn<FeetechFlowCommands, &FeetechFlowCommands::factoryReset>},
        {"reboot", &runIn<FeetechFlowCommands, &FeetechFlowCommands::reboot>},
        {"recover", &runIn<FeetechFlowCommands, &FeetechFlowCommands::recover>},
        {"lock", &runIn<FeetechFlowCommands, &FeetechFlowCommands::lock>},
        {"setup-motor", &runIn<FeetechSetupCommand, &FeetechSetupCommand::setupMotor>},
        {"monitor", &runIn<FeetechMonitorCommand, &FeetechMonitorCommand::monitor>},
        {"identify", &runIn<FeetechFlowCommands, &FeetechFlowCommands::identify>},
        {"health", &runIn<FeetechHealthCommand, &FeetechHealthCommand::health>},
        {"check", &runIn<FeetechHealthCommand, &FeetechHealthCommand::check>},
        {"calibrate", &runIn<FeetechCalibrationCommands, &FeetechCalibrationCommands::calibrate>},
        {"calibration",
         &runIn<FeetechCalibrationCommands, &FeetechCalibrationCommands::calibration>},
        {"teleop", &runIn<FeetechTeleopCommand, &FeetechTeleopCommand::teleop>},
        {"record", &runIn<FeetechMotionCommands, &FeetechMotionCommands::record>},
        {"replay", &runIn<FeetechMotionCommands, &FeetechMotionCommands::replay>},
    };
    for (const auto &[name, runner] : kCommands) {
        if (command == QLatin1String(name))
            return runner(args, output, QStringLiteral("feetech ") + command, operands);
    }
    QStringList names;
    for (const auto &entry : kCommands)
        names.append(QLatin1String(entry.first));
    throw UsageError {ServoctlTr::tr("unknown feetech command \"%1\": use %2")
                          .arg(command, names.join(QStringLiteral(", ")))};
}

} // namespace cli
