// Tests the step-response metrics on synthetic recordings whose rise, overshoot and settling are
// known in closed form.
#include "stepresponse.h"

#include <QtTest>

#include <cmath>
#include <functional>

using feetech::StepMetrics;
using feetech::TimedValue;

namespace {

// Samples of `response` every `period` seconds from 0 to `duration` inclusive.
QVector<TimedValue> record(const std::function<double(double)> &response, double period,
                           double duration)
{
    QVector<TimedValue> samples;
    const int count = int(std::lround(duration / period));
    for (int i = 0; i <= count; ++i) {
        const double t = i * period;
        samples.append({t, response(t)});
    }
    return samples;
}

// x(t) of a first-order lag from `start` to `end` with time constant `tau`.
std::function<double(double)> firstOrder(double start, double end, double tau)
{
    return [=](double t) {
        return end + (start - end) * std::exp(-t / tau);
    };
}

// The unit step response of an underdamped second-order system, scaled from `start` to `end`.
std::function<double(double)> secondOrder(double start, double end, double zeta, double omega)
{
    const double root = std::sqrt(1.0 - zeta * zeta);
    const double phase = std::acos(zeta);
    return [=](double t) {
        const double unit =
            1.0 - std::exp(-zeta * omega * t) / root * std::sin(omega * root * t + phase);
        return start + (end - start) * unit;
    };
}

double expectedOvershootPercent(double zeta)
{
    return 100.0 * std::exp(-M_PI * zeta / std::sqrt(1.0 - zeta * zeta));
}

// What settling means, checked against the samples themselves: everything after the settling
// time lies within the band, and the sample just before it does not.
void verifySettlingDefinition(const QVector<TimedValue> &samples, const StepMetrics &metrics)
{
    QVERIFY(metrics.settlingTime.has_value());
    const double settling = *metrics.settlingTime;
    int firstAfter = -1;
    for (int i = 0; i < samples.size(); ++i) {
        if (samples.at(i).seconds > settling) {
            if (firstAfter < 0)
                firstAfter = i;
            QVERIFY2(
                std::abs(samples.at(i).value - metrics.target) <= metrics.band,
                qPrintable(QStringLiteral("outside the band at %1 s").arg(samples.at(i).seconds)));
        }
    }
    QVERIFY(firstAfter > 0);
    QVERIFY(std::abs(samples.at(firstAfter - 1).value - metrics.target) > metrics.band);
}

} // namespace

class TestStepResponse : public QObject
{
    Q_OBJECT

private slots:
    void firstOrderRiseIsTauLn9AndSettlingTauLn50_data()
    {
        QTest::addColumn<double>("period");
        QTest::addColumn<double>("tolerance"); // seconds
        QTest::newRow("1 kHz") << 0.001 << 0.0005;
        QTest::newRow("100 Hz (a telemetry stream)") << 0.01 << 0.004;
    }

    void firstOrderRiseIsTauLn9AndSettlingTauLn50()
    {
        QFETCH(double, period);
        QFETCH(double, tolerance);
        const double tau = 0.1;
        const auto samples = record(firstOrder(1000, 2000, tau), period, 1.0);
        const auto metrics = feetech::analyseStep(samples, 1000, 2000);
        QVERIFY(metrics.has_value());
        QCOMPARE(metrics->start, 1000.0);
        QCOMPARE(metrics->target, 2000.0);
        QVERIFY(metrics->riseTime.has_value());
        QVERIFY2(std::abs(*metrics->riseTime - tau * std::log(9.0)) < tolerance,
                 qPrintable(QString::number(*metrics->riseTime)));
        QCOMPARE(metrics->overshootPercent.value_or(-1.0), 0.0);
        QCOMPARE(metrics->band, 20.0); // 2 % of 1000 steps
        QVERIFY(metrics->settled);
        QVERIFY(metrics->settlingTime.has_value());
        QVERIFY2(std::abs(*metrics->settlingTime - tau * std::log(50.0)) < tolerance,
                 qPrintable(QString::number(*metrics->settlingTime)));
        verifySettlingDefinition(samples, *metrics);
        // After 9 time constants what is left is a fraction of a step.
        QVERIFY(metrics->steadyStateError.has_value());
        QVERIFY(std::abs(*metrics->steadyStateError) < 0.2);
        QCOMPARE(metrics->duration, samples.last().seconds);
        QCOMPARE(metrics->sampleCount, int(samples.size()));
    }

    void underdampedOvershootFollowsTheDampingRatio_data()
    {
        QTest::addColumn<double>("zeta");
        QTest::newRow("zeta 0.2") << 0.2;
        QTest::newRow("zeta 0.3") << 0.3;
        QTest::newRow("zeta 0.5") << 0.5;
        QTest::newRow("zeta 0.7") << 0.7;
    }

    void underdampedOvershootFollowsTheDampingRatio()
    {
        QFETCH(double, zeta);
        const double omega = 20.0; // rad/s
        const auto samples = record(secondOrder(500, 1500, zeta, omega), 0.0005, 3.0);
        const auto metrics = feetech::analyseStep(samples, 500, 1500);
        QVERIFY(metrics.has_value());
        QVERIFY(metrics->overshootPercent.has_value());
        QVERIFY2(std::abs(*metrics->overshootPercent - expectedOvershootPercent(zeta)) < 0.05,
                 qPrintable(QString::number(*metrics->overshootPercent)));
        // It rises before its first peak, at π / ωd.
        const double peakTime = M_PI / (omega * std::sqrt(1.0 - zeta * zeta));
        QVERIFY(metrics->riseTime.has_value());
        QVERIFY(*metrics->riseTime > 0.0);
        QVERIFY(*metrics->riseTime < peakTime);
        // The envelope e^(-ζωt) bounds when it settles into the 2 % band.
        QVERIFY(metrics->settled);
        verifySettlingDefinition(samples, *metrics);
        const double envelopeBound = std::log(50.0 / std::sqrt(1.0 - zeta * zeta)) / (zeta * omega);
        QVERIFY(*metrics->settlingTime <= envelopeBound + 0.001);
        QVERIFY(*metrics->settlingTime > *metrics->riseTime);
        QVERIFY(std::abs(*metrics->steadyStateError) < 0.5);
    }

    void responseThatStopsShortDoesNotSettleAndReportsItsOffset()
    {
        // It heads for 30 steps short of the target: outside the 20-step band for good.
        const double offset = 30.0;
        const auto samples = record(firstOrder(1000, 2000 - offset, 0.05), 0.002, 1.0);
        const auto metrics = feetech::analyseStep(samples, 1000, 2000);
        QVERIFY(metrics.has_value());
        QVERIFY(!metrics->settled);
        QVERIFY(!metrics->settlingTime.has_value());
        QVERIFY(metrics->steadyStateError.has_value());
        QVERIFY2(std::abs(*metrics->steadyStateError - offset) < 0.01,
                 qPrintable(QString::number(*metrics->steadyStateError)));
        QCOMPARE(metrics->overshootPercent.value_or(-1.0), 0.0);
        QVERIFY(metrics->riseTime.has_value()); // it does pass 90 %
    }

    void responseThatNeverReaches90PercentHasNoRiseTime()
    {
        const auto samples = record(firstOrder(0, 500, 0.05), 0.002, 0.5);
        const auto metrics = feetech::analyseStep(samples, 0, 1000);
        QVERIFY(metrics.has_value());
        QVERIFY(!metrics->riseTime.has_value());
        QVERIFY(!metrics->settled);
        QVERIFY(std::abs(*metrics->steadyStateError - 500.0) < 0.5);
    }

    void downwardStepGivesTheSameMetricsAsUpward()
    {
        const double tau = 0.08;
        const auto samples = record(firstOrder(3000, 1000, tau), 0.001, 1.0);
        const auto metrics = feetech::analyseStep(samples, 3000, 1000);
        QVERIFY(metrics.has_value());
        QVERIFY(std::abs(*metrics->riseTime - tau * std::log(9.0)) < 0.0005);
        QCOMPARE(*metrics->overshootPercent, 0.0);
        QCOMPARE(metrics->band, 40.0);
        QVERIFY(metrics->settled);
        QVERIFY(std::abs(*metrics->settlingTime - tau * std::log(50.0)) < 0.0005);

        // Below the target is beyond it on the way down.
        const double zeta = 0.4;
        const auto ringing = record(secondOrder(3000, 1000, zeta, 25.0), 0.0005, 2.0);
        const auto overshoot = feetech::analyseStep(ringing, 3000, 1000);
        QVERIFY(overshoot.has_value());
        QVERIFY(std::abs(*overshoot->overshootPercent - expectedOvershootPercent(zeta)) < 0.05);

        // Stopping 15 steps above a downward target is a negative error (target - final).
        const auto shortOfIt = record(firstOrder(3000, 1015, 0.05), 0.002, 1.0);
        const auto stopped = feetech::analyseStep(shortOfIt, 3000, 1000);
        QVERIFY(stopped.has_value());
        QVERIFY(std::abs(*stopped->steadyStateError + 15.0) < 0.01);
        QVERIFY(stopped->settled); // within the 40-step band
    }

    void smallStepUsesTheMinimumBand()
    {
        // 2 % of 50 steps is one step, finer than a position can settle: the band is 2 steps.
        const auto samples = record(firstOrder(2000, 2050, 0.02), 0.001, 0.3);
        const auto metrics = feetech::analyseStep(samples, 2000, 2050);
        QVERIFY(metrics.has_value());
        QCOMPARE(metrics->band, 2.0);
        QVERIFY(std::abs(*metrics->settlingTime - 0.02 * std::log(25.0)) < 0.0005);
    }

    void samplesOutOfOrderOrBeforeTheStepDoNotChangeTheResult()
    {
        const double tau = 0.1;
        auto samples = record(firstOrder(1000, 2000, tau), 0.001, 1.0);
        const auto inOrder = feetech::analyseStep(samples, 1000, 2000);
        QVERIFY(inOrder.has_value());
        // Resting at the start before the command.
        QVector<TimedValue> shuffled = {{-0.02, 1000}, {-0.01, 1000}};
        for (int i = int(samples.size()) - 1; i >= 0; --i)
            shuffled.append(samples.at(i));
        const auto metrics = feetech::analyseStep(shuffled, 1000, 2000);
        QVERIFY(metrics.has_value());
        QCOMPARE(*metrics->riseTime, *inOrder->riseTime);
        QCOMPARE(*metrics->settlingTime, *inOrder->settlingTime);
        QCOMPARE(*metrics->overshootPercent, *inOrder->overshootPercent);
    }

    void tooFewSamplesOrNoStepGiveNothing()
    {
        QVERIFY(!feetech::analyseStep({}, 0, 100).has_value());
        QVERIFY(!feetech::analyseStep({{0.0, 0}, {0.1, 100}}, 0, 100).has_value());
        const QVector<TimedValue> three = {{0.0, 0}, {0.1, 50}, {0.2, 100}};
        QVERIFY(feetech::analyseStep(three, 0, 100).has_value());
        QVERIFY(!feetech::analyseStep(three, 100, 100).has_value());
        // Values that are not numbers do not count as samples.
        const QVector<TimedValue> broken = {{0.0, 0}, {0.1, std::nan("")}, {0.2, 100}};
        QVERIFY(!feetech::analyseStep(broken, 0, 100).has_value());
    }
};

QTEST_APPLESS_MAIN(TestStepResponse)
#include "tst_stepresponse.moc"
