// Step-response metrics: crossings interpolated between samples so the sample rate matters little.
#include "stepresponse.h"

#include <algorithm>
#include <cmath>

namespace feetech {

namespace {

constexpr int kMinimumSamples = 3;
constexpr double kRiseLow = 0.1;
constexpr double kRiseHigh = 0.9;

// Where a straight line through (t0, v0) and (t1, v1) takes `level`.
double interpolate(double t0, double v0, double t1, double v1, double level)
{
    if (v1 == v0)
        return t1;
    const double at = t0 + (level - v0) / (v1 - v0) * (t1 - t0);
    return std::clamp(at, std::min(t0, t1), std::max(t0, t1));
}

// The first time at or after sample `from` that progress reaches `level`, and its sample.
std::optional<std::pair<double, int>> crossing(const QVector<TimedValue> &samples,
                                               const QVector<double> &progress, double level,
                                               int from)
{
    for (int i = from; i < samples.size(); ++i) {
        if (progress.at(i) < level)
            continue;
        if (i == 0)
            return std::make_pair(samples.at(0).seconds, 0);
        return std::make_pair(interpolate(samples.at(i - 1).seconds, progress.at(i - 1),
                                          samples.at(i).seconds, progress.at(i), level),
                              i);
    }
    return std::nullopt;
}

} // namespace

std::optional<StepMetrics> analyseStep(const QVector<TimedValue> &input, double start,
                                       double target, const StepOptions &options)
{
    if (!std::isfinite(start) || !std::isfinite(target) || start == target)
        return std::nullopt;
    QVector<TimedValue> samples;
    samples.reserve(input.size());
    for (const TimedValue &sample : input) {
        if (std::isfinite(sample.seconds) && std::isfinite(sample.value))
            samples.append(sample);
    }
    if (samples.size() < kMinimumSamples)
        return std::nullopt;
    std::stable_sort(samples.begin(), samples.end(), [](const TimedValue &a, const TimedValue &b) {
        return a.seconds < b.seconds;
    });

    const double amplitude = target - start;
    QVector<double> progress;
    progress.reserve(samples.size());
    for (const TimedValue &sample : std::as_const(samples))
        progress.append((sample.value - start) / amplitude);

    StepMetrics metrics;
    metrics.start = start;
    metrics.target = target;
    metrics.sampleCount = int(samples.size());
    metrics.duration = samples.last().seconds;

    // Rise time: 10 % and then 90 % of the way.
    if (const auto low = crossing(samples, progress, kRiseLow, 0)) {
        if (const auto high = crossing(samples, progress, kRiseHigh, low->second))
            metrics.riseTime = std::max(0.0, high->first - low->first);
    }

    const double peak = *std::max_element(progress.cbegin(), progress.cend());
    metrics.overshootPercent = std::max(0.0, peak - 1.0) * 100.0;

    // Settling: the last sample outside the band decides it.
    metrics.band = std::max(options.bandFraction * std::abs(amplitude), options.minimumBand);
    int lastOutside = -1;
    for (int i = int(samples.size()) - 1; i >= 0; --i) {
        if (std::abs(samples.at(i).value - target) > metrics.band) {
            lastOutside = i;
            break;
        }
    }
    if (lastOutside < 0) {
        metrics.settled = true;
        metrics.settlingTime =
            std::abs(amplitude) <= metrics.band ? 0.0 : std::max(0.0, samples.first().seconds);
    } else if (lastOutside < samples.size() - 1) {
        const TimedValue &out = samples.at(lastOutside);
        const TimedValue &in = samples.at(lastOutside + 1);
        const double edge = target + (out.value > target ? metrics.band : -metrics.band);
        metrics.settled = true;
        metrics.settlingTime = interpolate(out.seconds, out.value, in.seconds, in.value, edge);
    }

    // Steady state: the mean of the final part of the recording.
    const double span = samples.last().seconds - samples.first().seconds;
    const double from = samples.last().seconds - std::clamp(options.finalFraction, 0.0, 1.0) * span;
    double sum = 0.0;
    int count = 0;
    for (const TimedValue &sample : std::as_const(samples)) {
        if (sample.seconds >= from) {
            sum += sample.value;
            ++count;
        }
    }
    metrics.steadyStateError = target - sum / count; // count ≥ 1: the last sample is in
    return metrics;
}

} // namespace feetech
