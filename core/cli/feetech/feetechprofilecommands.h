// servoctl feetech save and load: a servo's settings to and from a JSON profile or a robot
// template, and load --ids for the servos of an arm.
#pragma once

#include "feetechcommandgroup.h"
#include "settingsfile.h"

namespace cli {

class FeetechProfileCommands : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int save(const QString &what, const QStringList &operands);
    int load(const QString &what, const QStringList &operands);

private:
    int loadMany(const feetech::SettingsFile &file, const QString &path);
    feetech::ProgramOutcome programOne(FeetechDevice &device, quint8 id,
                                       const feetech::SettingsFile &file);
};

} // namespace cli
