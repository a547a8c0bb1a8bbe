// Test helper: one small valid document of each kind ServoBench saves and reads.
#pragma once

#include "lerobotcalibration.h"
#include "pose.h"
#include "profile.h"
#include "ptkparameters.h"

namespace testsupport {

inline profile::Profile samplePtkProfile()
{
    const ptk::ParameterSet sample = ptk::ParameterSet::seedSample(true);
    profile::Profile result;
    result.family = QStringLiteral("ptk");
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
        result.values.append({QLatin1String(meta.key), *sample.value(meta.parameter)});
    return result;
}

inline feetech::Pose samplePose()
{
    feetech::Pose pose;
    pose.servos = {{1, 1000000, 2048}, {2, 1000000, 1024}};
    return pose;
}

inline QVector<feetech::LeRobotMotor> sampleCalibration()
{
    feetech::LeRobotMotor motor;
    motor.name = QStringLiteral("shoulder_pan");
    return {motor};
}

} // namespace testsupport
