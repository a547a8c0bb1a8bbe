// servoctl feetech calibrate and calibration save/load: an arm's joints recorded by hand, and
// LeRobot calibration files read from and written to the servos.
#pragma once

#include "armcalibration.h"
#include "feetechcommandgroup.h"

namespace cli {

class FeetechCalibrationCommands : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int calibrate(const QString &what, const QStringList &operands);
    // calibration save|load
    int calibration(const QString &what, const QStringList &operands);

private:
    QStringList jointNames(const QVector<quint8> &ids) const;
    std::optional<QVector<ServoInfo>> identifyJoints(FeetechDevice &device,
                                                     const QVector<quint8> &ids);
    bool recordJoints(FeetechDevice &device, const QVector<ServoInfo> &servos,
                      QVector<feetech::JointRecording> &joints, std::optional<double> duration);
    void printRecording(const QVector<feetech::JointRecording> &joints, bool live);
    int saveCalibration(const QString &what, const QStringList &operands);
    int loadCalibration(const QString &what, const QStringList &operands);
};

} // namespace cli
