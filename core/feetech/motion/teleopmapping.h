// A leader arm's joints onto a follower's, by name, in LeRobot's normalised units, as LeRobot's
// teleoperation sends them: body joints in degrees from the middle of their range (use_degrees,
// the SO arms' default) or −100…100 of it, the gripper in 0…100.
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

// What LeRobot's motors bus does with a calibration (its MotorNormMode): RANGE_M100_100 and
// RANGE_0_100 clamp a position to the joint's range, scale it to the mode's span and invert it
// for drive_mode 1; DEGREES takes the offset from the range's middle in degrees, unscaled and
// unclamped, drive_mode aside. What reaches the follower is within its range here, as its angle
// limits (written by the calibration) keep it there with LeRobot.
class TeleopMapping
{
public:
    // How body joints map, named as LeRobot names them; the gripper is RANGE_0_100 in both.
    enum class NormMode {
        Degrees, // MotorNormMode.DEGREES (use_degrees=True): the SO arms' configs' default
        RangeM100_100, // MotorNormMode.RANGE_M100_100 (use_degrees=False): range onto range
    };
    static constexpr NormMode kDefaultNormMode = NormMode::Degrees;
    // "degrees", "range_m100_100": the names of the command line and the JSON.
    static QString normModeKey(NormMode mode);
    static std::optional<NormMode> normModeFromKey(QStringView key);

    // LeRobot's gripper joint: the one joint in 0…100.
    static bool isGripper(const QString &name) { return name == QLatin1String("gripper"); }
    static double normalise(const LeRobotMotor &motor, bool gripper, qint32 position);
    static qint32 position(const LeRobotMotor &motor, bool gripper, double normalised);

    // The joints both files name, in the follower's order; nothing when a joint of either file
    // is missing from the other (missing() then names them, with the file that lacks them).
    static std::optional<TeleopMapping> match(const QVector<LeRobotMotor> &follower,
                                              const QVector<LeRobotMotor> &leader,
                                              QStringList *missing,
                                              NormMode mode = kDefaultNormMode);

    const QVector<TeleopJoint> &joints() const { return m_joints; }
    NormMode normMode() const { return m_mode; }
    // Where the follower's joint goes for the leader's position, within the follower's range.
    qint32 followerGoal(int joint, qint32 leaderPosition) const;

private:
    QVector<TeleopJoint> m_joints;
    NormMode m_mode = kDefaultNormMode;
};

} // namespace feetech
