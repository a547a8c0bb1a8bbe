// A pose met with the servos of a bus, and the pose their targets make.
#include "posematch.h"

namespace feetech {

namespace {

bool listed(const QVector<JointTarget> &joints, const PoseEntry &entry)
{
    for (const JointTarget &joint : joints) {
        if (joint.servo == entry.address())
            return true;
    }
    return false;
}

} // namespace

PoseMatch matchPose(const Pose &pose, const QVector<JointTarget> &joints,
                    const QString &fallbackName)
{
    PoseMatch match;
    match.name = pose.name.isEmpty() ? fallbackName : pose.name;
    for (const PoseEntry &entry : pose.servos) {
        if (!listed(joints, entry))
            match.notOnBus.append(entry);
    }
    match.targets.resize(joints.size());
    for (int row = 0; row < joints.size(); ++row) {
        const JointTarget &joint = joints.at(row);
        const PoseEntry *entry = pose.find(joint.servo);
        if (!entry) {
            match.rowsWithoutEntry.append(row);
            continue;
        }
        match.targets[row] = entry->position;
        ++match.filled;
        if (joint.range && !joint.range->contains(entry->position))
            match.rowsOutOfRange.append(row);
    }
    return match;
}

Pose poseFromTargets(const QString &name, const QVector<JointTarget> &joints)
{
    Pose pose;
    pose.name = name;
    for (const JointTarget &joint : joints) {
        if (joint.target)
            pose.servos.append({joint.servo.id, joint.servo.baud, *joint.target});
    }
    return pose;
}

} // namespace feetech
