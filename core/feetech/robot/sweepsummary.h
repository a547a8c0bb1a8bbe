// A sweep test's outcome: each leg, how many reached their target and how fast.
#pragma once

#include <QMetaType>
#include <QVector>

#include <optional>

namespace feetech {

struct SweepLeg
{
    qint32 target = 0;
    bool reached = false; // within the tolerance and still before the reach timeout
    double seconds = 0.0; // from the goal write to reaching it (the timeout when not reached)
    std::optional<double> finalPosition; // the last position seen during the leg
};

struct SweepSummary
{
    QVector<SweepLeg> legs;
    int reachedCount() const;
    std::optional<double> meanReachedSeconds() const;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::SweepSummary)
