// servoctl feetech set-id, set-baud, calibrate-middle, factory-reset, reboot, lock, recover and
// identify: guided flows on one servo, each run by the session and reported the same way.
#pragma once

#include "feetechcommandgroup.h"

#include <functional>

namespace cli {

class FeetechFlowCommands : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int setId(const QString &what, const QStringList &operands);
    int setBaud(const QString &what, const QStringList &operands);
    int calibrateMiddle(const QString &what, const QStringList &operands);
    int factoryReset(const QString &what, const QStringList &operands);
    int reboot(const QString &what, const QStringList &operands);
    int lock(const QString &what, const QStringList &operands);
    int recover(const QString &what, const QStringList &operands);
    // Moves the servo a little each way, so that the user sees which joint it is.
    int identify(const QString &what, const QStringList &operands);

private:
    int report(Target &target, const feetech::BusOperation &operation,
               const std::function<void(QJsonObject &, const Memory &)> &more = {});
    int alreadyDone(const ServoInfo &servo, const QString &message);
};

} // namespace cli
