// Step-response metrics of a recorded move: rise time, overshoot, settling time, steady-state
// error.
#pragma once

#include <QMetaType>
#include <QVector>

#include <optional>

namespace feetech {

struct TimedValue
{
    double seconds = 0.0; // since the step command (samples before it have negative times)
    double value = 0.0;
};

// Definitions, for a step from `start` to `target` (upward or downward alike; "progress" is
// (value - start) / (target - start), so 0 at the start and 1 at the target):
// - riseTime: from the first time progress reaches 10 % to the first time after that it
//   reaches 90 %, each crossing interpolated linearly between the two samples around it;
//   nothing when the response never reaches 90 %.
// - overshootPercent: how far the peak progress goes beyond the target, as a percentage of
//   |target - start|; 0 when it never goes beyond.
// - band: the settling band's half-width around the target, in the value's unit:
//   max(bandFraction × |target - start|, minimumBand).
// - settlingTime: the time after which every sample stays within the band up to the end of the
//   recording, interpolated where the response last crosses into the band. When no sample is
//   outside, it is 0 if the start itself lies within the band, otherwise the first sample's
//   time (the crossing happened before anything was seen). Nothing when the last sample is
//   still outside (then settled is false).
// - steadyStateError: target - the mean of the samples in the final finalFraction of the
//   recording (at least the last sample), signed, in the value's unit.
struct StepMetrics
{
    double start = 0.0;
    double target = 0.0;
    std::optional<double> riseTime; // seconds
    std::optional<double> overshootPercent;
    std::optional<double> settlingTime; // seconds since the step command
    std::optional<double> steadyStateError; // value units, signed
    double band = 0.0;
    bool settled = false;
    double duration = 0.0; // time of the last sample: how long the response was watched
    int sampleCount = 0;
};

struct StepOptions
{
    double bandFraction = 0.02; // the usual 2 % settling criterion
    double minimumBand = 2.0; // steps: a position cannot settle closer than its resolution
    double finalFraction = 0.1; // the part of the recording that counts as steady state
};

// Nothing when there are fewer than 3 samples or start == target (no step to measure).
// Samples need not be sorted; they are taken in time order.
std::optional<StepMetrics> analyseStep(const QVector<TimedValue> &samples, double start,
                                       double target, const StepOptions &options = {});

} // namespace feetech

Q_DECLARE_METATYPE(feetech::StepMetrics)
