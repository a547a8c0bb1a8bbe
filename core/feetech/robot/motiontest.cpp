// Step and sweep tests: a phase enum advanced by telemetry samples and one deadline timer.
#include "motiontest.h"

#include "busclient.h"
#include "goalrange.h"
#include "registerkeys.h"

#include <QLocale>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace feetech {

using namespace registerkeys;

namespace {

constexpr qint32 kPositionMode = 0; // register 33: every family's mode 0 holds a position
constexpr double kMicroseconds = 1e6;

std::chrono::milliseconds millisecondsOf(double seconds)
{
    return std::chrono::milliseconds(qint64(std::ceil(seconds * 1000.0)));
}

} // namespace

MotionTest::MotionTest(BusClient *client, const MotionTiming &timing, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_timing(timing)
    , m_timer(new QTimer(this))
{
    m_timer->setSingleShot(true);
    connect(m_timer, &QTimer::timeout, this, &MotionTest::onTimeout);
    connect(m_client->telemetry(), &TelemetryHub::samplesReceived, this, &MotionTest::onTelemetry);
    connect(m_client, &BusClient::statusChanged, this, &MotionTest::onStatusChanged);
    connect(m_client, &BusClient::allTorqueOffRequested, this,
            [this] { fail(tr("All torque off: the test was stopped.")); });
    // The guard held the servo or switched it off: the next leg must not drive it again.
    connect(m_client->guard(), &BusGuard::event, this, [this](const GuardEvent &event) {
        if (isRunning() && event.stage == GuardStage::Acted
            && ServoAddress {event.id, event.baud} == m_servo)
            fail(tr("The test was stopped: %1").arg(event.message));
    });
    connect(m_client->servos(), &ServoList::servosChanged, this, [this] {
        if (isRunning() && servoIndex() < 0)
            fail(tr("%1 is no longer on the bus: the test was stopped.").arg(servoName()));
    });
}

MotionTest::~MotionTest()
{
    if (isRunning() && m_client) {
        m_client->identify()->release(m_servo);
        restoreMonitor();
    }
}

void MotionTest::setTiming(const MotionTiming &timing)
{
    m_timing = timing;
}

bool MotionTest::validate(const MotionPlan &plan, Kind kind, MotionTestRefusal *refusal) const
{
    const auto refuse = [refusal](const MotionTestRefusal &why) {
        if (refusal)
            *refusal = why;
        return false;
    };
    using Code = MotionTestRefusal::Code;
    if (isRunning())
        return refuse(MotionTestRefusal(Code::AlreadyRunning));
    if (!m_client->link()->isConnected())
        return refuse(MotionTestRefusal(Code::NotConnected));
    if (plan.index < 0 || plan.index >= m_client->servos()->count())
        return refuse(MotionTestRefusal(Code::NoServo));
    const ServoInfo &info = m_client->servos()->at(plan.index).info;
    if (m_client->identify()->isRunning(plan.index))
        return refuse(MotionTestRefusal::beingIdentified(info.id));
    if (!info.hasTable())
        return refuse(MotionTestRefusal(Code::UnknownModel));
    const RegisterTable &table = info.table();
    const auto range = goalRange(*m_client, plan.index);
    if (!range || !table.find(kTorqueEnable))
        return refuse(MotionTestRefusal(Code::NotMovable));
    const auto mode = m_client->servos()->parameters(plan.index)->deviceValue(kMode);
    if (table.find(kMode) && mode && *mode != kPositionMode)
        return refuse(MotionTestRefusal::notInPositionMode(info.id));
    if (!range->contains(plan.from) || !range->contains(plan.to))
        return refuse(MotionTestRefusal::outsideRange(plan.from, plan.to, *range));
    if (std::abs(double(plan.to) - double(plan.from)) <= m_timing.reachTolerance)
        return refuse(MotionTestRefusal::tooClose(m_timing.reachTolerance));
    for (const auto &[key, value] :
         {std::pair(kGoalSpeed, plan.goalSpeed), std::pair(kAcceleration, plan.acceleration)}) {
        const Register *reg = table.find(key);
        if (reg && (value < reg->minimum || value > reg->maximum))
            return refuse(
                MotionTestRefusal::settingOutOfRange(reg->label, reg->minimum, reg->maximum));
    }
    if (kind == Kind::Step
        && !(plan.recordSeconds > 0.0 && plan.recordSeconds <= MotionPlan::kMaximumRecordSeconds))
        return refuse(MotionTestRefusal::badRecordLength(MotionPlan::kMaximumRecordSeconds));
    if (kind == Kind::Sweep && (plan.legs < 1 || plan.legs > MotionPlan::kMaximumLegs))
        return refuse(MotionTestRefusal::badLegCount(MotionPlan::kMaximumLegs));
    return true;
}

bool MotionTest::startStep(const MotionPlan &plan, MotionTestRefusal *refusal)
{
    return start(plan, Kind::Step, refusal);
}

bool MotionTest::startSweep(const MotionPlan &plan, MotionTestRefusal *refusal)
{
    return start(plan, Kind::Sweep, refusal);
}

bool MotionTest::start(const MotionPlan &plan, Kind kind, MotionTestRefusal *refusal)
{
    if (!validate(plan, kind, refusal))
        return false;
    const ServoInfo &info = m_client->servos()->at(plan.index).info;
    m_plan = plan;
    m_kind = kind;
    m_servo = info.address();
    m_writesInFlight = 0;
    m_lastPosition.reset();
    m_lastSampleUs.reset();
    m_recording.clear();
    m_summary = {};
    m_leg = 0;
    m_sweepStartUs.reset();
    if (!ensureMonitor(plan.index, refusal))
        return false;

    // The goal before the torque: a servo switched on first would head for a stale goal.
    const RegisterTable &table = info.table();
    QVector<model::WriteItem> values;
    if (table.find(kAcceleration))
        values.append({kAcceleration, plan.acceleration});
    if (table.find(kGoalSpeed))
        values.append({kGoalSpeed, plan.goalSpeed});
    values.append({kGoalPosition, plan.from});
    const auto on = table.torqueValue(TorqueMode::On);
    if (on
        && m_client->servos()->parameters(plan.index)->deviceValue(kTorqueEnable)
            != std::optional<qint64>(*on))
        values.append({kTorqueEnable, *on});
    if (!write(values, refusal)) {
        restoreMonitor();
        return false;
    }
    startApproach();
    m_client->identify()->hold(plan.index,
                               tr("A motion test is running on servo ID %1.").arg(m_servo.id));
    emit runningChanged(true); // isRunning() is true by now
    return true;
}

void MotionTest::cancel()
{
    if (!isRunning())
        return;
    // Stop where it is rather than let it finish a move nobody watches any more.
    const int index = servoIndex();
    if (m_lastPosition && index >= 0) {
        const auto range = goalRange(*m_client, index);
        const qint64 here = std::llround(*m_lastPosition);
        if (range && range->contains(here))
            m_client->writeValues(index, {{kGoalPosition, here}});
    }
    fail(tr("The test was stopped."));
}

int MotionTest::servoIndex() const
{
    return m_client->servos()->indexOf(m_servo);
}

QString MotionTest::servoName() const
{
    return tr("Servo ID %1").arg(m_servo.id);
}

bool MotionTest::write(const QVector<model::WriteItem> &values, MotionTestRefusal *refusal)
{
    const int index = servoIndex();
    if (index < 0) {
        if (refusal)
            *refusal = MotionTestRefusal::servoGone(m_servo.id);
        return false;
    }
    Refusal refused;
    OperationReply *reply = m_client->writeValues(index, values, &refused);
    if (!reply) {
        if (refusal)
            *refusal = MotionTestRefusal::clientRefused(refused);
        return false;
    }
    connect(reply, &OperationReply::finished, this, &MotionTest::onWriteFinished);
    ++m_writesInFlight;
    m_commandUs = steadyMicroseconds();
    return true;
}

bool MotionTest::ensureMonitor(int index, MotionTestRefusal *refusal)
{
    // Its servo at its rate, beside whatever else streams; nothing of another's stream changes.
    Refusal refused;
    if (m_client->telemetry()->subscribe(this, {index}, m_timing.monitorRateHz, &refused))
        return true;
    if (refusal)
        *refusal = MotionTestRefusal::clientRefused(refused);
    return false;
}

void MotionTest::restoreMonitor()
{
    m_client->telemetry()->unsubscribe(this);
}

void MotionTest::setPhase(Phase phase, std::chrono::milliseconds timeout)
{
    m_phase = phase;
    m_timer->start(timeout);
}

bool MotionTest::isReached(double position, bool moving, double goal) const
{
    return !moving && std::abs(position - goal) <= m_timing.reachTolerance;
}

void MotionTest::startApproach()
{
    setPhase(Phase::Approaching, m_timing.reachTimeout);
    emit progress(tr("Moving to the start position %1…").arg(m_plan.from));
}

void MotionTest::onTelemetry(const QVector<FeedbackSample> &samples)
{
    if (!isRunning())
        return;
    for (const FeedbackSample &sample : samples) {
        if (ServoAddress {sample.id, sample.baud} != m_servo)
            continue;
        const auto position = sample.value(Quantity::Position);
        if (!position)
            continue;
        // A sample from before the current goal went out says nothing about reaching it.
        const bool current = sample.steadyUs >= m_commandUs;
        switch (m_phase) {
        case Phase::Approaching:
            if (current && isReached(*position, sample.moving, m_plan.from)) {
                m_lastPosition = position;
                m_lastSampleUs = sample.steadyUs;
                if (m_kind == Kind::Step)
                    beginStep();
                else
                    beginLeg();
                return; // the rest of the batch belongs to the next phase's clock
            }
            break;
        case Phase::Recording:
        case Phase::Collecting: {
            const double seconds = double(sample.steadyUs - m_commandUs) / kMicroseconds;
            if (seconds >= 0.0 && seconds <= m_plan.recordSeconds)
                m_recording.append({seconds, *position});
            break;
        }
        case Phase::Leg:
            m_summary.legs[m_leg].finalPosition = *position;
            // The sweep as a line too: each position from the first leg's start on.
            if (m_sweepStartUs && sample.steadyUs >= *m_sweepStartUs)
                m_recording.append(
                    {double(sample.steadyUs - *m_sweepStartUs) / kMicroseconds, *position});
            if (current && isReached(*position, sample.moving, m_legTarget)) {
                m_lastPosition = position;
                endLeg(true, sample.steadyUs);
                return;
            }
            break;
        case Phase::Dwell:
        case Phase::Idle:
            break;
        }
        m_lastPosition = position;
        m_lastSampleUs = sample.steadyUs;
    }
}

void MotionTest::beginStep()
{
    // The last position before the step is where the step starts from: a servo held a few
    // steps off `from` (or one that never got there) is measured from where it really was.
    m_stepStart = m_lastPosition.value_or(double(m_plan.from));
    MotionTestRefusal refusal;
    if (!write({{kGoalPosition, m_plan.to}}, &refusal)) {
        fail(refusal.describe());
        return;
    }
    m_recording.clear();
    if (m_lastSampleUs)
        m_recording.append({double(*m_lastSampleUs - m_commandUs) / kMicroseconds, m_stepStart});
    setPhase(Phase::Recording, millisecondsOf(m_plan.recordSeconds));
    emit progress(tr("Step to %1: recording for %2 s…")
                      .arg(m_plan.to)
                      .arg(QLocale().toString(m_plan.recordSeconds, 'g', 3)));
}

void MotionTest::finishStep()
{
    const auto metrics = analyseStep(m_recording, m_stepStart, double(m_plan.to));
    if (!metrics) {
        fail(tr("Too few position samples arrived during the recording (%1): does %2 answer?")
                 .arg(m_recording.size())
                 .arg(servoName()));
        return;
    }
    finish();
    emit progress(tr("Step test done."));
    emit stepFinished(*metrics);
}

void MotionTest::beginLeg()
{
    // Legs alternate from → to, to → from, starting at `from`.
    m_legTarget = m_leg % 2 == 0 ? m_plan.to : m_plan.from;
    SweepLeg leg;
    leg.target = m_legTarget;
    m_summary.legs.append(leg);
    MotionTestRefusal refusal;
    if (!write({{kGoalPosition, m_legTarget}}, &refusal)) {
        fail(refusal.describe());
        return;
    }
    setPhase(Phase::Leg, m_timing.reachTimeout);
    if (!m_sweepStartUs)
        m_sweepStartUs = m_commandUs;
    emit progress(
        tr("Sweep leg %1 of %2: moving to %3…").arg(m_leg + 1).arg(m_plan.legs).arg(m_legTarget));
}

void MotionTest::endLeg(bool reached, qint64 atUs)
{
    SweepLeg &leg = m_summary.legs[m_leg];
    leg.reached = reached;
    leg.seconds = double(atUs - m_commandUs) / kMicroseconds;
    ++m_leg;
    if (m_leg >= m_plan.legs) {
        const SweepSummary summary = m_summary;
        finish();
        emit progress(tr("Sweep done: %1 of %2 legs reached their goal.")
                          .arg(summary.reachedCount())
                          .arg(summary.legs.size()));
        emit sweepFinished(summary);
        return;
    }
    setPhase(Phase::Dwell, m_timing.dwell);
}

void MotionTest::onTimeout()
{
    switch (m_phase) {
    case Phase::Approaching:
        if (!m_lastPosition) {
            fail(tr("No position samples arrived from %1: is it answering?").arg(servoName()));
            return;
        }
        // Held off by a load, say: the test goes on from where the servo is.
        emit progress(tr("%1 did not settle at %2 within %3 s; going on from %4.")
                          .arg(servoName())
                          .arg(m_plan.from)
                          .arg(double(m_timing.reachTimeout.count()) / 1000.0)
                          .arg(std::lround(*m_lastPosition)));
        if (m_kind == Kind::Step)
            beginStep();
        else
            beginLeg();
        break;
    case Phase::Recording:
        setPhase(Phase::Collecting, m_timing.finalSamplesGrace);
        break;
    case Phase::Collecting:
        finishStep();
        break;
    case Phase::Leg:
        endLeg(false, steadyMicroseconds());
        break;
    case Phase::Dwell:
        beginLeg();
        break;
    case Phase::Idle:
        break;
    }
}

void MotionTest::onWriteFinished(const OperationResult &result)
{
    if (!isRunning() || m_writesInFlight <= 0)
        return;
    if (result.failure == OperationFailure::LinkLost) { // onStatusChanged says so
        --m_writesInFlight;
        return;
    }
    --m_writesInFlight;
    if (!result.ok)
        fail(tr("Writing to %1 failed: %2").arg(servoName(), result.message));
}

void MotionTest::onStatusChanged(const seriallink::ConnectionStatus &status)
{
    if (status.state == seriallink::ConnectionState::Disconnected
        || status.state == seriallink::ConnectionState::Lost)
        fail(tr("The bus was disconnected: the test was stopped."));
}

void MotionTest::finish()
{
    m_timer->stop();
    m_phase = Phase::Idle;
    if (m_client)
        m_client->identify()->release(m_servo);
    restoreMonitor();
    emit runningChanged(false);
}

void MotionTest::fail(const QString &message)
{
    if (!isRunning())
        return;
    finish();
    emit failed(message);
}

} // namespace feetech
