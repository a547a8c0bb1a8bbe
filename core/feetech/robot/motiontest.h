// Step and sweep tests of one Feetech servo: goal writes paced by timers and the telemetry stream,
// with step-response metrics computed from the recorded positions.
#pragma once

#include "bustypes.h"
#include "motiontestrefusal.h"
#include "parametermodel.h"
#include "stepresponse.h"
#include "sweepsummary.h"
#include "telemetry.h"

#include <QMetaType>
#include <QObject>
#include <QPointer>
#include <QVector>

#include <chrono>
#include <optional>

class QTimer;

namespace seriallink {
struct ConnectionStatus;
}

namespace feetech {

class BusClient;
struct OperationResult;

// Timing and thresholds of the tests; tests inject short ones.
struct MotionTiming
{
    static constexpr std::chrono::milliseconds kDefaultReachTimeout {8000};
    static constexpr std::chrono::milliseconds kDefaultDwell {400};
    static constexpr std::chrono::milliseconds kDefaultFinalSamplesGrace {200};
    static constexpr double kDefaultMonitorRateHz = 100.0;
    static constexpr double kDefaultReachTolerance = 10.0; // steps

    // How long to wait for the servo to reach a position (the step's start, a sweep leg's end)
    // before going on without it.
    std::chrono::milliseconds reachTimeout = kDefaultReachTimeout;
    // A sweep's pause at each end.
    std::chrono::milliseconds dwell = kDefaultDwell;
    // After a step's recording window: time for the last telemetry batch to arrive.
    std::chrono::milliseconds finalSamplesGrace = kDefaultFinalSamplesGrace;
    // The stream rate the tests need; a slower (or absent) stream is raised to it meanwhile.
    double monitorRateHz = kDefaultMonitorRateHz;
    // "Reached": this close to the goal and the moving flag clear.
    double reachTolerance = kDefaultReachTolerance;
};

// What to move and how; positions, speed and acceleration in register units.
struct MotionPlan
{
    static constexpr double kMaximumRecordSeconds = 30.0;
    static constexpr int kMaximumLegs = 1000;

    int index = -1; // the servo, as BusClient numbers them
    qint32 from = 0;
    qint32 to = 0;
    qint32 goalSpeed = 0; // written where the family has goal_speed (0: the servo's maximum)
    qint32 acceleration = 0; // written where the family has acceleration (0: the maximum)
    double recordSeconds = 2.0; // step test: how long the response is recorded after the step
    int legs = 4; // sweep: moves, alternating from → to, to → from, ...
};

class MotionTest : public QObject
{
    Q_OBJECT

public:
    enum class Kind { Step, Sweep };

    explicit MotionTest(BusClient *client, const MotionTiming &timing = {},
                        QObject *parent = nullptr);
    ~MotionTest() override; // a running test leaves the monitor as it found it

    const MotionTiming &timing() const { return m_timing; }
    void setTiming(const MotionTiming &timing); // for the next test

    // Whether `plan` can run now; *refusal says why not.
    bool validate(const MotionPlan &plan, Kind kind, MotionTestRefusal *refusal = nullptr) const;
    // Step test: torque on, goal = from, wait until it is there and still, then goal = to at
    // t0 and record the position for plan.recordSeconds; stepFinished with the metrics.
    // False and *refusal when nothing was started (and nothing sent).
    bool startStep(const MotionPlan &plan, MotionTestRefusal *refusal = nullptr);
    // Sweep: torque on, goal = from, then plan.legs moves alternating between to and from, each
    // waiting until it is reached (or the reach timeout), then a dwell; sweepFinished.
    bool startSweep(const MotionPlan &plan, MotionTestRefusal *refusal = nullptr);
    // Stops a running test (failed is emitted); the horn is held where it was last seen.
    void cancel();

    bool isRunning() const { return m_phase != Phase::Idle; }
    Kind kind() const { return m_kind; }
    const MotionPlan &plan() const { return m_plan; }
    // The position samples of the last test: a step test's in seconds since the step command
    // (the one before the command has a negative time), a sweep's since its first leg began.
    const QVector<TimedValue> &recording() const { return m_recording; }

signals:
    void runningChanged(bool running);
    void progress(const QString &message);
    void stepFinished(const feetech::StepMetrics &metrics);
    void sweepFinished(const feetech::SweepSummary &summary);
    void failed(const QString &message);

private:
    enum class Phase { Idle, Approaching, Recording, Collecting, Leg, Dwell };

    bool start(const MotionPlan &plan, Kind kind, MotionTestRefusal *refusal);
    int servoIndex() const; // -1 once the servo is gone
    bool write(const QVector<model::WriteItem> &values, MotionTestRefusal *refusal);
    // The stream of its servo: subscribed while the test runs.
    bool ensureMonitor(int index, MotionTestRefusal *refusal);
    void restoreMonitor();
    void onTelemetry(const QVector<feetech::FeedbackSample> &samples);
    void onWriteFinished(const feetech::OperationResult &result);
    void onStatusChanged(const seriallink::ConnectionStatus &status);
    void onTimeout();
    void startApproach();
    void beginStep();
    void finishStep();
    void beginLeg();
    void endLeg(bool reached, qint64 atUs);
    void finish();
    void fail(const QString &message);
    void setPhase(Phase phase, std::chrono::milliseconds timeout);
    bool isReached(double position, bool moving, double goal) const;
    QString servoName() const;

    QPointer<BusClient> m_client; // the page may outlive the bus client at shutdown
    MotionTiming m_timing;
    QTimer *m_timer = nullptr; // the current phase's deadline
    Phase m_phase = Phase::Idle;
    Kind m_kind = Kind::Step;
    MotionPlan m_plan;
    ServoAddress m_servo; // the plan's servo, by its address once the test starts
    int m_writesInFlight = 0;
    qint64 m_commandUs = 0; // when the current goal was written (steady clock)
    std::optional<double> m_lastPosition;
    std::optional<qint64> m_lastSampleUs;
    std::optional<qint64> m_sweepStartUs; // when the sweep's first leg began (steady clock)
    // Step test.
    QVector<TimedValue> m_recording;
    double m_stepStart = 0.0;
    // Sweep.
    int m_leg = 0;
    qint32 m_legTarget = 0;
    SweepSummary m_summary;
};

} // namespace feetech
