// servoctl feetech teleop: a leader arm drives a follower, joint by joint through their LeRobot
// calibration files, with a safe start, a speed limit and a stop that holds.
#pragma once

#include "feetechcommandgroup.h"
#include "teleopmapping.h"

namespace cli {

class FeetechTeleopCommand : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int teleop(const QString &what, const QStringList &operands);

private:
    // Each joint's servo on its bus, identified; nothing after a refusal or failure (printed,
    // with *exitCode set).
    std::optional<QVector<ServoInfo>> identifyArm(FeetechDevice &device,
                                                  const QVector<feetech::LeRobotMotor> &motors,
                                                  const QString &calibrationPath, int *exitCode);
    // Present positions of `servos`, in their order.
    std::optional<QVector<qint32>> presentPositions(FeetechDevice &device,
                                                    const QVector<ServoInfo> &servos);
    // One SYNC WRITE of `values` to `address` (2 bytes) or torque enable (1 byte), waited for.
    bool writeAll(FeetechDevice &device, const QVector<ServoInfo> &servos, const QString &key,
                  const QVector<qint32> &values);
};

} // namespace cli
