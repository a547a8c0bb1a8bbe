// servoctl feetech health: the health check of servos --ids, and with --move-test their move test.
#pragma once

#include "feetechcommandgroup.h"
#include "servohealth.h"

namespace cli {

class FeetechHealthCommand : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int health(const QString &what, const QStringList &operands);

private:
    void printHealth(const feetech::ServoHealth &health, bool moveAsked);
};

} // namespace cli
