// The guided recovery of a servo whose overload protection tripped: torque off and on again,
// the status checked, and the power-cycle steps when the overload bit stays set.
#pragma once

#include "busexchange.h"
#include "bustypes.h"

#include <QStringList>

#include <memory>
#include <optional>

namespace feetech {

// Torque off; unless `checkOnly`, the goal set to the present position and torque on again
// (re-arming the torque clears a trip that is not latched); then the status register read:
// *latched says whether its overload bit is still set, and if so the torque is switched off
// again so the register says what the servo does. With `checkOnly` (after a power cycle) only
// the status is read.
Step recoverOverload(BusExchange &bus, std::shared_ptr<ServoInfo> servo, bool checkOnly,
                     std::shared_ptr<std::optional<bool>> latched);

// What to do when the bit stays set, one step per line (the GUI and servoctl show the same).
QStringList powerCycleSteps(const ServoInfo &servo);

} // namespace feetech
