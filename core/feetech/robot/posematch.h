// A pose met with the servos of a bus: the targets it fills, and the entries and servos that
// did not meet; and the pose the servos' targets make.
#pragma once

#include "goalrange.h"
#include "pose.h"

#include <QVector>

#include <optional>

namespace feetech {

// One servo of the bus as a table of targets lists it.
struct JointTarget
{
    ServoAddress servo;
    std::optional<qint32> target; // nothing until one is set
    std::optional<PositionRange> range; // where it may be sent; nothing for an unknown model
};

// How a pose met the servos on the bus.
struct PoseMatch
{
    QString name;
    QVector<std::optional<qint32>> targets; // per servo: the pose's position, or nothing
    int filled = 0; // servos whose target the pose sets
    QVector<PoseEntry> notOnBus; // entries for servos the list does not have
    QVector<int> rowsWithoutEntry; // servos the pose says nothing about (targets unchanged)
    QVector<int> rowsOutOfRange; // servos given a target outside their range

    bool isClean() const
    {
        return notOnBus.isEmpty() && rowsWithoutEntry.isEmpty() && rowsOutOfRange.isEmpty();
    }
};

// Matches by ID and baud rate; `fallbackName` names a pose that has no name of its own.
PoseMatch matchPose(const Pose &pose, const QVector<JointTarget> &joints,
                    const QString &fallbackName);

// The servos' targets as a pose, in their order; servos without a target are left out.
Pose poseFromTargets(const QString &name, const QVector<JointTarget> &joints);

} // namespace feetech
