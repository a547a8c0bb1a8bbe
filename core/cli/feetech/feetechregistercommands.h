// servoctl feetech scan, ping, read, get and set: finding servos and their registers.
#pragma once

#include "feetechcommandgroup.h"

namespace cli {

class FeetechRegisterCommands : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int scan(const QString &what, const QStringList &operands);
    int ping(const QString &what, const QStringList &operands);
    int read(const QString &what, const QStringList &operands);
    int get(const QString &what, const QStringList &operands);
    int set(const QString &what, const QStringList &operands);
};

} // namespace cli
