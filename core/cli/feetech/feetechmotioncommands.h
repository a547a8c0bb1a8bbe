// servoctl feetech record and replay: an arm's motion moved by hand, saved as CSV, and played
// back eased in, at its recorded times.
#pragma once

#include "feetechcommandgroup.h"
#include "motionrecording.h"

#include <functional>

namespace cli {

class FeetechMotionCommands : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int record(const QString &what, const QStringList &operands);
    int replay(const QString &what, const QStringList &operands);

private:
    QVector<feetech::MotionJoint> recordedJoints(const QVector<quint8> &ids) const;
    double numberOption(const QString &name, double fallback,
                        const std::function<bool(double)> &accepts, const QString &range) const;
    // The servo of every joint of the recording; usage errors for a joint that matches none;
    // nothing, once the failure is printed, for a lost link or several servos at one ID.
    std::optional<QVector<ServoInfo>>
    replayedServos(FeetechDevice &device, const feetech::MotionRecording &recording, qint32 baud);
};

} // namespace cli
