// Move all planned from a table of targets: the servos one SYNC WRITE per baud rate sends, or
// the first servo that refuses it, so nothing is sent.
#pragma once

#include "goalrange.h"

#include <QVector>

#include <optional>

namespace feetech {

// One servo of the table as Move all sees it.
struct MoveAllJoint
{
    qint32 baud = 0;
    bool known = false; // on the bus with a model that has a goal register
    std::optional<qint32> target;
    std::optional<PositionRange> range;
    std::optional<qint64> mode; // the operating mode as read; 0 is position mode
    bool torqueOff = false; // torque reads off: it will not move
};

struct MoveAllPlan
{
    enum class Refusal { None, NoTarget, OutOfRange, NotPositionMode, NothingMovable };

    Refusal refusal = Refusal::None;
    int refusedRow = -1; // the servo that refused, for all but NothingMovable
    QVector<int> rows; // the servos sent their target, in order
    QVector<int> skipped; // servos of unknown model, not moved
    QVector<int> torqueOff; // servos sent a target that torque off keeps still
    int syncWrites = 0; // one per baud rate of the servos sent

    bool isRefused() const { return refusal != Refusal::None; }
};

MoveAllPlan planMoveAll(const QVector<MoveAllJoint> &joints);

} // namespace feetech
