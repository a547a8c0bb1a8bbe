// Names of the Feetech registers that code addresses directly.
// The register tables under resources/feetech define them; they are spelt once, here, so that a
// misspelt key cannot quietly match nothing in one caller while working in another.
#pragma once

#include <QString>

namespace feetech::registerkeys {

inline const QString kTorqueEnable = QStringLiteral("torque_enable");
inline const QString kGoalPosition = QStringLiteral("goal_position");
inline const QString kGoalSpeed = QStringLiteral("goal_speed");
inline const QString kAcceleration = QStringLiteral("acceleration");
inline const QString kMode = QStringLiteral("mode");
inline const QString kPresentPosition = QStringLiteral("present_position");
inline const QString kMoving = QStringLiteral("moving");
inline const QString kMinAngleLimit = QStringLiteral("min_angle_limit");
inline const QString kMaxAngleLimit = QStringLiteral("max_angle_limit");

} // namespace feetech::registerkeys
