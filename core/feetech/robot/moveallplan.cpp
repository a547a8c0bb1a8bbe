// Move all planned from a table of targets.
#include "moveallplan.h"

#include <QSet>

namespace feetech {

MoveAllPlan planMoveAll(const QVector<MoveAllJoint> &joints)
{
    MoveAllPlan plan;
    const auto refuse = [](MoveAllPlan::Refusal refusal, int row) {
        MoveAllPlan refused;
        refused.refusal = refusal;
        refused.refusedRow = row;
        return refused;
    };
    QSet<qint32> bauds;
    for (int row = 0; row < joints.size(); ++row) {
        const MoveAllJoint &joint = joints.at(row);
        if (!joint.known || !joint.range) {
            plan.skipped.append(row);
            continue;
        }
        if (!joint.target)
            return refuse(MoveAllPlan::Refusal::NoTarget, row);
        if (!joint.range->contains(*joint.target))
            return refuse(MoveAllPlan::Refusal::OutOfRange, row);
        // In wheel, PWM or step mode the goal register means something else (or nothing).
        if (joint.mode && *joint.mode != 0)
            return refuse(MoveAllPlan::Refusal::NotPositionMode, row);
        if (joint.torqueOff)
            plan.torqueOff.append(row);
        plan.rows.append(row);
        bauds.insert(joint.baud);
    }
    if (plan.rows.isEmpty()) {
        plan.refusal = MoveAllPlan::Refusal::NothingMovable;
        return plan;
    }
    plan.syncWrites = int(bauds.size());
    return plan;
}

} // namespace feetech
