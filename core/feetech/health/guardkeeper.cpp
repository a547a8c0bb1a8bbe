// The guard on a session's bus: driven servos, their feedback, and the guard's actions.
#include "guardkeeper.h"

#include "feetechguardtr.h"
#include "linksession.h"
#include "registertable.h"
#include "torqueonhold.h"

#include <QCoreApplication>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

// Names the guard's own stream: no client asks for this one.
constexpr quint64 kGuardStream = ~quint64(0);

bool writes(const RegisterWrite &write, const Register &reg)
{
    return write.address <= reg.address && reg.address < write.address + int(write.bytes.size());
}

} // namespace

GuardKeeper::GuardKeeper(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
    , m_cycle(new TelemetryCycle(bus, this))
{
    qRegisterMetaType<feetech::GuardEvent>();
    qRegisterMetaType<feetech::GuardSettings>();
    connect(m_cycle, &TelemetryCycle::telemetry, this,
            [this](const QVector<FeedbackSample> &samples, quint64) { observe(samples); });
}

void GuardKeeper::setSettings(const GuardSettings &settings)
{
    m_guard.setSettings(settings);
    updateCycle();
}

void GuardKeeper::noteServo(const ServoInfo &servo)
{
    if (servo.hasTable())
        m_known.insert({servo.id, servo.baud}, servo);
}

void GuardKeeper::noteWrites(const ServoInfo &servo, const QVector<RegisterWrite> &written)
{
    noteServo(servo);
    if (!servo.hasTable())
        return;
    const RegisterTable &table = servo.table();
    const Register *torque = table.find(u"torque_enable");
    const Register *goal = table.find(u"goal_position");
    std::optional<bool> driven;
    for (const RegisterWrite &write : written) {
        if (torque && writes(write, *torque)) {
            const int value = quint8(write.bytes.at(torque->address - write.address));
            driven = table.torqueMode(value) == TorqueMode::On;
        }
        if (goal && writes(write, *goal) && !driven)
            driven = true;
    }
    if (!driven)
        return;
    if (*driven)
        m_guard.rearm(servo.id, servo.baud); // a new goal: after an action, a new episode
    setDriven(servo, *driven);
}

void GuardKeeper::noteSyncWrite(qint32 baud, int address, const QVector<SyncWriteEntry> &entries)
{
    for (const SyncWriteEntry &entry : entries) {
        const auto known = m_known.constFind({entry.id, baud});
        if (known == m_known.constEnd())
            continue; // a servo no scan found: the guard does not know how to read it
        noteWrites(*known, {{address, entry.data}});
    }
}

void GuardKeeper::noteDriven(const ServoInfo &servo)
{
    noteServo(servo);
    if (servo.hasTable())
        setDriven(servo, true);
}

void GuardKeeper::noteAllTorqueOff()
{
    m_driven.clear();
    updateCycle();
}

void GuardKeeper::noteLinkDown()
{
    m_driven.clear();
    m_guard.clear();
    updateCycle();
}

void GuardKeeper::noteStream(const TelemetryOptions &options)
{
    m_streamed.clear();
    // A stream at least as fast as the guard's own reads feeds it; a slower one does not.
    if (options.rateHz == 0.0 || options.rateHz >= kGuardRateHz) {
        for (const ServoInfo &servo : options.servos)
            m_streamed.append({servo.id, servo.baud});
    }
    updateCycle();
}

void GuardKeeper::setDriven(const ServoInfo &servo, bool driven)
{
    const Key key {servo.id, servo.baud};
    if (driven == m_driven.contains(key))
        return;
    if (driven)
        m_driven.insert(key, servo);
    else
        m_driven.remove(key);
    updateCycle();
}

void GuardKeeper::updateCycle()
{
    QVector<Key> wanted;
    TelemetryOptions options;
    if (m_guard.settings().enabled) {
        for (auto it = m_driven.constBegin(); it != m_driven.constEnd(); ++it) {
            if (!m_streamed.contains(it.key()) && m_guard.limitsFor(it.value()).enabled) {
                wanted.append(it.key());
                options.servos.append(it.value());
            }
        }
    }
    std::sort(wanted.begin(), wanted.end());
    if (wanted == m_cycled)
        return;
    m_cycled = wanted;
    if (options.servos.isEmpty()) {
        m_cycle->stop();
        return;
    }
    options.rateHz = kGuardRateHz;
    options.stream = kGuardStream;
    m_cycle->start(options);
}

void GuardKeeper::observe(const QVector<FeedbackSample> &samples)
{
    for (const FeedbackSample &sample : samples) {
        const auto known = m_known.constFind({sample.id, sample.baud});
        if (known == m_known.constEnd())
            continue;
        const ServoInfo servo = *known;
        const GuardLimits limits = m_guard.limitsFor(servo);
        for (const GuardDecision &decision : m_guard.observe(servo, sample)) {
            GuardEvent event;
            event.id = servo.id;
            event.baud = servo.baud;
            event.cause = decision.cause;
            event.stage = decision.stage;
            event.action = limits.action;
            event.value = decision.value;
            event.limit = decision.limit;
            event.current = decision.current;
            event.steadyUs = sample.steadyUs;
            // A hot servo nothing drives gets the warning only: there is nothing to stop (a
            // high load, though, proves its torque is on, whoever switched it on).
            if (decision.stage == GuardStage::Acted && decision.cause == GuardCause::Heat
                && !isDriven(servo.id, servo.baud))
                continue;
            if (decision.stage == GuardStage::Acted)
                act(servo, event, limits);
            else
                report(event, limits);
        }
    }
}

void GuardKeeper::report(GuardEvent event, const GuardLimits &limits)
{
    event.message = guardEventText(event, limits);
    const bool alarm = event.stage == GuardStage::Acted || event.stage == GuardStage::StillLoaded
        || (event.cause == GuardCause::LatchedOverload && event.stage == GuardStage::Warning);
    m_bus.logNote(event.message, alarm);
    emit guardEvent(event);
}

void GuardKeeper::act(const ServoInfo &servo, const GuardEvent &seen, const GuardLimits &limits)
{
    if (!m_runUrgent)
        return;
    auto target = std::make_shared<ServoInfo>(servo);
    m_runUrgent([this, target, seen, limits](std::function<void()> finished) {
        const ServoInfo &info = *target;
        auto heldAt = std::make_shared<std::optional<qint32>>();
        auto otherMode = std::make_shared<bool>(false);
        const RegisterTable &table = info.table();
        // A held motor keeps its current and keeps warming: heat is always met with torque off.
        const bool hold = limits.action == GuardAction::Hold && seen.cause != GuardCause::Heat
            && table.find(u"goal_position") && table.find(u"present_position");
        std::vector<Step> steps {m_bus.setBaud(info.baud)};
        if (hold)
            steps.push_back(holdAtPresentPosition(m_bus, target, heldAt, otherMode));
        else
            steps.push_back(torqueOff(target));
        m_bus.runSteps(std::move(steps),
                       [this, target, seen, limits, heldAt, otherMode, hold,
                        finished](bool ok, const QString &message) {
                           GuardEvent event = seen;
                           GuardLimits used = limits;
                           if (!hold)
                               used.action = event.action = GuardAction::TorqueOff;
                           const auto done = [this, target, heldAt,
                                              finished](GuardEvent event, GuardLimits used, bool ok,
                                                        const QString &message) {
                               event.ok = ok;
                               event.heldAt = *heldAt;
                               event.message = message;
                               if (ok && event.action == GuardAction::TorqueOff)
                                   setDriven(*target, false);
                               report(event, used);
                               if (m_acted)
                                   m_acted(*target);
                               finished();
                           };
                           if (hold && !ok && *otherMode) {
                               // Not in position mode: a goal cannot hold it, so its torque goes
                               // off.
                               used.action = event.action = GuardAction::TorqueOff;
                               m_bus.runSteps({torqueOff(target)},
                                              [done, event, used](bool off, const QString &why) {
                                                  done(event, used, off, why);
                                              });
                               return;
                           }
                           done(event, used, ok, message);
                       });
    });
}

Step GuardKeeper::torqueOff(std::shared_ptr<ServoInfo> target)
{
    return [this, target](StepDone next) {
        const RegisterTable &table = target->table();
        const Register *torque = table.find(u"torque_enable");
        const auto off = table.torqueValue(TorqueMode::Off);
        if (!torque || !off) {
            m_bus.fail(next, OperationFailure::Unsupported,
                       FeetechGuardTr::tr("Servo %1 has no torque switch the guard could use.")
                           .arg(target->id));
            return;
        }
        m_bus.runSteps(
            {m_bus.write(target->id, torque->address, QByteArray(1, char(*off)),
                         target->repliesToWrites(),
                         FeetechGuardTr::tr("Guard: torque off of servo %1").arg(target->id)),
             m_bus.read(target, torque->address, torque->size, ReadSource::ReadBack)},
            next);
    };
}

} // namespace feetech
