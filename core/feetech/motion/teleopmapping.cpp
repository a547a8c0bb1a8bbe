// A leader arm's joints onto a follower's in LeRobot's normalised units.
#include "teleopmapping.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace {

struct TeleopMappingTr
{
    Q_DECLARE_TR_FUNCTIONS(TeleopMapping)
};

} // namespace

namespace feetech {

double TeleopMapping::normalise(const LeRobotMotor &motor, bool gripper, qint32 position)
{
    const double span = std::max(1, motor.rangeMax - motor.rangeMin);
    const double bounded = std::clamp(position, motor.rangeMin, motor.rangeMax);
    const double share = (bounded - motor.rangeMin) / span;
    if (gripper)
        return motor.driveMode ? 100.0 - share * 100.0 : share * 100.0;
    const double value = share * 200.0 - 100.0;
    return motor.driveMode ? -value : value;
}

qint32 TeleopMapping::position(const LeRobotMotor &motor, bool gripper, double normalised)
{
    const double span = motor.rangeMax - motor.rangeMin;
    double share = 0;
    if (gripper) {
        const double value = motor.driveMode ? 100.0 - normalised : normalised;
        share = std::clamp(value, 0.0, 100.0) / 100.0;
    } else {
        const double value = motor.driveMode ? -normalised : normalised;
        share = (std::clamp(value, -100.0, 100.0) + 100.0) / 200.0;
    }
    // A limit of 4096 (LeRobot's "no bound") is no position the encoder reaches.
    return std::clamp(qint32(std::lround(motor.rangeMin + share * span)), motor.rangeMin,
                      std::min(motor.rangeMax, kLeRobotMaximumPosition));
}

QString TeleopMapping::normModeKey(NormMode mode)
{
    return mode == NormMode::Degrees ? QStringLiteral("degrees") : QStringLiteral("range_m100_100");
}

std::optional<TeleopMapping::NormMode> TeleopMapping::normModeFromKey(QStringView key)
{
    for (const NormMode mode : {NormMode::Degrees, NormMode::RangeM100_100}) {
        if (key == normModeKey(mode))
            return mode;
    }
    return std::nullopt;
}

std::optional<TeleopMapping> TeleopMapping::match(const QVector<LeRobotMotor> &follower,
                                                  const QVector<LeRobotMotor> &leader,
                                                  QStringList *missing, NormMode mode)
{
    TeleopMapping mapping;
    mapping.m_mode = mode;
    QStringList lacking;
    for (const LeRobotMotor &motor : follower) {
        const auto found = std::find_if(leader.begin(), leader.end(), [&](const auto &other) {
            return other.name == motor.name;
        });
        if (found == leader.end())
            lacking.append(TeleopMappingTr::tr("%1 (not in the leader's file)").arg(motor.name));
        else
            mapping.m_joints.append({motor.name, *found, motor, isGripper(motor.name)});
    }
    for (const LeRobotMotor &motor : leader) {
        const bool known = std::any_of(follower.begin(), follower.end(),
                                       [&](const auto &other) { return other.name == motor.name; });
        if (!known)
            lacking.append(TeleopMappingTr::tr("%1 (not in the follower's file)").arg(motor.name));
    }
    if (missing)
        *missing = lacking;
    if (!lacking.isEmpty() || mapping.m_joints.isEmpty())
        return std::nullopt;
    return mapping;
}

qint32 TeleopMapping::followerGoal(int joint, qint32 leaderPosition) const
{
    const TeleopJoint &pair = m_joints.at(joint);
    if (pair.gripper || m_mode == NormMode::RangeM100_100)
        return position(pair.follower, pair.gripper,
                        normalise(pair.leader, pair.gripper, leaderPosition));
    // LeRobot's DEGREES: (position − middle) × 360 / 4095 on the leader, back with the same
    // scale around the follower's middle, truncated as its int() does.
    constexpr double kStepsPerTurn = kLeRobotMaximumPosition; // the STS3215's 4096 steps less 1
    const double leaderMiddle = (pair.leader.rangeMin + pair.leader.rangeMax) / 2.0;
    const double degrees = (leaderPosition - leaderMiddle) * 360.0 / kStepsPerTurn;
    const double followerMiddle = (pair.follower.rangeMin + pair.follower.rangeMax) / 2.0;
    const auto goal = qint32(std::trunc(degrees * kStepsPerTurn / 360.0 + followerMiddle));
    return std::clamp(goal, pair.follower.rangeMin,
                      std::min(pair.follower.rangeMax, kLeRobotMaximumPosition));
}

} // namespace feetech
