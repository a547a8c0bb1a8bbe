// The goal positions a Feetech servo accepts.
// One computation for the control page, the joint table and the motion tests, so that all of
// them refuse the same targets.
#pragma once

#include <QtGlobal>

#include <optional>

namespace feetech {

class RegisterTable;

// The goal positions a servo accepts, in steps: its angle limits (min_angle_limit,
// max_angle_limit) as the servo reported them, or the goal_position register's range when they
// are not known yet or are both 0, which means multi-turn / wheel: no limit.
struct PositionRange
{
    qint32 minimum = 0;
    qint32 maximum = 0;
    bool fromAngleLimits = false;

    bool contains(qint64 position) const { return position >= minimum && position <= maximum; }
};

// From the table and the angle limits as read (none where not read yet); nothing for a table
// without goal_position.
std::optional<PositionRange> goalRange(const RegisterTable &table, std::optional<qint64> low,
                                       std::optional<qint64> high);

} // namespace feetech
