// The allowed goal range of a servo, from its register table and the angle limits it reported.
#include "goalrange.h"

#include "registerkeys.h"
#include "registertable.h"

#include <algorithm>

namespace feetech {

std::optional<PositionRange> goalRange(const RegisterTable &table, std::optional<qint64> low,
                                       std::optional<qint64> high)
{
    const Register *goal = table.find(registerkeys::kGoalPosition);
    if (!goal)
        return std::nullopt;
    PositionRange range {goal->minimum, goal->maximum, false};
    // Both limits 0 selects multi-turn or motor mode: the limits then bound nothing. Limits are
    // kept inside the register's range, so a misread limit cannot widen what may be written.
    if (low && high && !(*low == 0 && *high == 0) && *low <= *high) {
        range.minimum = qint32(std::max<qint64>(*low, goal->minimum));
        range.maximum = qint32(std::min<qint64>(*high, goal->maximum));
        range.fromAngleLimits = true;
    }
    return range;
}

} // namespace feetech
