// A sweep test's summary: the legs that reached their target, and their mean time.
#include "sweepsummary.h"

#include <algorithm>

namespace feetech {

int SweepSummary::reachedCount() const
{
    return int(
        std::count_if(legs.cbegin(), legs.cend(), [](const SweepLeg &leg) { return leg.reached; }));
}

std::optional<double> SweepSummary::meanReachedSeconds() const
{
    double sum = 0.0;
    int count = 0;
    for (const SweepLeg &leg : legs) {
        if (leg.reached) {
            sum += leg.seconds;
            ++count;
        }
    }
    if (count == 0)
        return std::nullopt;
    return sum / count;
}

} // namespace feetech
