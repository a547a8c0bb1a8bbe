// servoctl feetech monitor: streams servos' feedback as text, JSON lines or CSV.
#pragma once

#include "feetechcommandgroup.h"

namespace cli {

class FeetechMonitorCommand : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int monitor(const QString &what, const QStringList &operands);

private:
    double monitorRate() const;
    void printSample(const feetech::FeedbackSample &sample, qint64 startUs,
                     const QVector<ServoInfo> &servos);
};

} // namespace cli
