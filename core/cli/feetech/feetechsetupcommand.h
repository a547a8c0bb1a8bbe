// servoctl feetech setup-motor: the one servo on the bus gets an ID, a rate and settings.
#pragma once

#include "feetechcommandgroup.h"
#include "motorsetup.h"

namespace cli {

class FeetechSetupCommand : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int setupMotor(const QString &what, const QStringList &operands);

private:
    // What --id, --baud, --model and --settings ask for; usage errors before anything is sent.
    feetech::MotorTarget motorTarget(const QString &what) const;
};

} // namespace cli
