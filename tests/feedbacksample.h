// Test support for plots and readouts: a plausible feedback sample of one servo at 1 Mbps.
#pragma once

#include "telemetry.h"

namespace testsupport {

// Servo `id`'s sample at `us` (steady clock), every quantity reported, at `position`.
inline feetech::FeedbackSample feedbackSample(quint8 id, qint64 us, double position)
{
    feetech::FeedbackSample sample;
    sample.id = id;
    sample.baud = 1000000;
    sample.steadyUs = us;
    sample.values = {position, 120.0, 8.5, 12.1, 35.0, 40.0};
    return sample;
}

} // namespace testsupport
