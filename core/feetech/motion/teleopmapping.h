// A leader arm's joints onto a follower's, by name, in LeRobot's normalised units: −100…100 for
// body joints and 0…100 for the gripper, drive_mode honoured, so arms of different ranges match.
#pragma once

#include "lerobotcalibration.h"

#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace feetech {

struct TeleopJoint
{
    QString name;
    LeRobotMotor leader;
    LeRobotMotor follower;
    bool gripper = false; // 0…100 rather than −100…100
};

// What LeRobot's motors bus does with a calibration (MotorNormMode RANGE_M100_100 and
// RANGE_0_100): a position clamped to the joint's range, scaled to the mode's span, and the
// direction inverted for drive_mode 1.
class TeleopMapping
{
public:
    // LeRobot's gripper joint: the one joint in 0…100.
    static bool isGripper(const QString &name) { return name == QLatin1String("gripper"); }
    static double normalise(const LeRobotMotor &motor, bool gripper, qint32 position);
    static qint32 position(const LeRobotMotor &motor, bool gripper, double normalised);

    // The joints both files name, in the follower's order; nothing when a joint of either file
    // is missing from the other (missing() then names them, with the file that lacks them).
    static std::optional<TeleopMapping> match(const QVector<LeRobotMotor> &follower,
                                              const QVector<LeRobotMotor> &leader,
                                              QStringList *missing);

    const QVector<TeleopJoint> &joints() const { return m_joints; }
    // Where the follower's joint goes for the leader's position, within the follower's range.
    qint32 followerGoal(int joint, qint32 leaderPosition) const;

private:
    QVector<TeleopJoint> m_joints;
};

} // namespace feetech
