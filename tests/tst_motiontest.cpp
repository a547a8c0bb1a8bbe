// Tests feetech::MotionTest on a simulated bus (STS3215 ×2 at 1 Mbps): what it refuses before
// sending anything, a step test's metrics and recording, a sweep's legs, cancelling, and the
// monitor left as the test found it.
#include "feetechbus.h"
#include "motiontest.h"

#include <QtTest>

#include <memory>

using feetech::MotionPlan;
using feetech::MotionTest;
using feetech::MotionTestRefusal;
using Code = feetech::MotionTestRefusal::Code;

namespace {

constexpr qint32 k1M = 1000000;

} // namespace

class TestMotionTest : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<MotionTest> m_test;

    int readServo(quint8 id)
    {
        return testsupport::connectScanAndRead(*m_client, m_simulator->linkPath(), 3, id);
    }

    MotionPlan plan(int index, qint32 from, qint32 to) const
    {
        MotionPlan plan;
        plan.index = index;
        plan.from = from;
        plan.to = to;
        plan.goalSpeed = 1500;
        plan.acceleration = 100;
        plan.recordSeconds = 1.0;
        plan.legs = 2;
        return plan;
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>();
        m_test = std::make_unique<MotionTest>(m_client.get(), testsupport::quickMotionTiming());
    }

    void cleanup()
    {
        m_test.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void nothingStartsWhileTheBusIsNotConnected()
    {
        MotionTestRefusal refusal;
        QVERIFY(!m_test->validate(plan(0, 2000, 2200), MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!refusal.describe().isEmpty());
        refusal = {};
        QVERIFY(!m_test->startStep(plan(0, 2000, 2200), &refusal));
        QCOMPARE(refusal.code(), Code::NotConnected);
        QVERIFY(!m_test->isRunning());
    }

    void plansItCannotRunAreRefusedWithAReasonAndNothingIsSent()
    {
        const int index = readServo(1);
        QVERIFY(index >= 0);
        const qsizetype framesBefore = testsupport::feetechFramesReceived(logPath()).size();
        MotionTestRefusal refusal;
        QVERIFY(!m_test->validate(plan(-1, 2000, 2200), MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), Code::NoServo);
        QVERIFY(!refusal.describe().isEmpty());
        // Closer together than the reach tolerance: nothing to measure.
        QVERIFY(!m_test->validate(plan(index, 2000, 2005), MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), Code::TooClose);
        QCOMPARE(refusal.limit(), m_test->timing().reachTolerance);
        QVERIFY(!refusal.describe().isEmpty());
        MotionPlan tooFast = plan(index, 2000, 2200);
        tooFast.goalSpeed = 100000;
        QVERIFY(!m_test->validate(tooFast, MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), Code::SettingOutOfRange);
        QVERIFY2(refusal.describe().contains(QString::number(refusal.maximum())),
                 qPrintable(refusal.describe()));
        MotionPlan tooLong = plan(index, 2000, 2200);
        tooLong.recordSeconds = MotionPlan::kMaximumRecordSeconds + 1.0;
        QVERIFY(!m_test->validate(tooLong, MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), Code::BadRecordLength);
        QCOMPARE(refusal.limit(), MotionPlan::kMaximumRecordSeconds);
        QVERIFY(m_test->validate(tooLong, MotionTest::Kind::Sweep)); // a sweep records nothing
        MotionPlan noLegs = plan(index, 2000, 2200);
        noLegs.legs = 0;
        QVERIFY(!m_test->validate(noLegs, MotionTest::Kind::Sweep, &refusal));
        QCOMPARE(refusal.code(), Code::BadLegCount);
        QCOMPARE(refusal.maximum(), qint64(MotionPlan::kMaximumLegs));
        m_client->servos()->parameters(index)->setDeviceValue(QStringLiteral("min_angle_limit"),
                                                              1000);
        m_client->servos()->parameters(index)->setDeviceValue(QStringLiteral("max_angle_limit"),
                                                              3000);
        QVERIFY(!m_test->startSweep(plan(index, 500, 2200), &refusal));
        QCOMPARE(refusal.code(), Code::OutsideRange);
        QCOMPARE(refusal.from(), 500);
        QVERIFY(refusal.range().fromAngleLimits);
        QCOMPARE(refusal.range().maximum, 3000);
        QVERIFY2(refusal.describe().contains(QLatin1String("3000")),
                 qPrintable(refusal.describe()));
        QVERIFY(!m_test->isRunning());
        QCOMPARE(testsupport::feetechFramesReceived(logPath()).size(), framesBefore);
    }

    void aStepTestReportsItsResponseAndLeavesTheMonitorOff()
    {
        const int index = readServo(1);
        QVERIFY(index >= 0);
        QVERIFY(!m_client->telemetry()->isStreaming());
        QSignalSpy running(m_test.get(), &MotionTest::runningChanged);
        QSignalSpy finished(m_test.get(), &MotionTest::stepFinished);
        QSignalSpy failed(m_test.get(), &MotionTest::failed);
        MotionTestRefusal refusal;
        QVERIFY2(m_test->startStep(plan(index, 2000, 2200), &refusal),
                 qPrintable(refusal.describe()));
        QVERIFY(m_test->isRunning());
        QCOMPARE(m_test->kind(), MotionTest::Kind::Step);
        QVERIFY(m_client->telemetry()->isStreaming()); // the test needs the stream
        QTRY_COMPARE_WITH_TIMEOUT(finished.size() + failed.size(), 1, 20000);
        QVERIFY2(failed.isEmpty(),
                 failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
        const auto metrics = finished.first().first().value<feetech::StepMetrics>();
        QCOMPARE(metrics.target, 2200.0);
        QVERIFY(std::abs(metrics.start - 2000.0)
                <= testsupport::quickMotionTiming().reachTolerance);
        QVERIFY(metrics.settled);
        QVERIFY(metrics.sampleCount >= 10);
        // Time 0 is the step command; the recording ends near the target.
        const QVector<feetech::TimedValue> &recording = m_test->recording();
        QVERIFY(!recording.isEmpty());
        QVERIFY(recording.last().seconds > 0.0);
        QVERIFY(std::abs(recording.last().value - 2200.0)
                <= testsupport::quickMotionTiming().reachTolerance);
        QCOMPARE(simulatorValue(1, QStringLiteral("goal_position")), 2200);
        QTRY_VERIFY(!m_client->telemetry()->isStreaming());
        QVERIFY(!m_test->isRunning());
        QCOMPARE(running.size(), 2);
        QCOMPARE(running.at(0).at(0).toBool(), true);
        QCOMPARE(running.at(1).at(0).toBool(), false);
    }

    void aSweepReachesEveryLegInTurn()
    {
        const int index = readServo(2);
        QVERIFY(index >= 0);
        QSignalSpy finished(m_test.get(), &MotionTest::sweepFinished);
        QSignalSpy failed(m_test.get(), &MotionTest::failed);
        MotionTestRefusal refusal;
        QVERIFY2(m_test->startSweep(plan(index, 1800, 2100), &refusal),
                 qPrintable(refusal.describe()));
        QCOMPARE(m_test->kind(), MotionTest::Kind::Sweep);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size() + failed.size(), 1, 30000);
        QVERIFY2(failed.isEmpty(),
                 failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
        const auto summary = finished.first().first().value<feetech::SweepSummary>();
        QCOMPARE(summary.legs.size(), 2);
        QCOMPARE(summary.legs.at(0).target, 2100); // to, then back to from
        QCOMPARE(summary.legs.at(1).target, 1800);
        QCOMPARE(summary.reachedCount(), 2);
        QVERIFY(summary.meanReachedSeconds().has_value());
        QCOMPARE(simulatorValue(2, QStringLiteral("goal_position")), 1800);
    }

    void cancelEndsARunningTestWithFailedAndTheMonitorAsItWas()
    {
        const int index = readServo(1);
        QVERIFY(index >= 0);
        MotionPlan longSweep = plan(index, 1500, 2500);
        longSweep.goalSpeed = 400;
        longSweep.legs = 40;
        QSignalSpy failed(m_test.get(), &MotionTest::failed);
        QSignalSpy progress(m_test.get(), &MotionTest::progress);
        MotionTestRefusal refusal;
        QVERIFY2(m_test->startSweep(longSweep, &refusal), qPrintable(refusal.describe()));
        QVERIFY(!m_test->validate(plan(index, 2000, 2200), MotionTest::Kind::Step, &refusal));
        QCOMPARE(refusal.code(), Code::AlreadyRunning);
        QTRY_VERIFY_WITH_TIMEOUT(!progress.isEmpty(), 10000);
        m_test->cancel();
        QVERIFY(!m_test->isRunning());
        QCOMPARE(failed.size(), 1);
        QTRY_VERIFY(!m_client->telemetry()->isStreaming());
        // A second test may start at once.
        QVERIFY2(m_test->validate(plan(index, 2000, 2200), MotionTest::Kind::Step, &refusal),
                 qPrintable(refusal.describe()));
    }
};

QTEST_GUILESS_MAIN(TestMotionTest)
#include "tst_motiontest.moc"
