// Identify a joint: read, hold where it is, wiggle slowly with little torque, put everything back.
#include "jointidentify.h"

#include "feetechsessiontr.h"
#include "feetechvalue.h"
#include "goalrange.h"
#include "registerkeys.h"
#include "servoparameters.h"
#include "torqueonhold.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>

#include <algorithm>
#include <cmath>

namespace feetech {

using namespace registerkeys;

namespace {

const QString kTorqueLimit = QStringLiteral("torque_limit");

} // namespace

struct JointIdentify::Run
{
    ServoInfo servo;
    std::shared_ptr<ServoInfo> target;
    GuidedFlows::Finish finish;
    Pause pause;
    QHash<QString, qint32> before; // as read at the start
    QHash<QString, qint32> now; // the latest poll
    QVector<qint32> legs; // goal positions, the last one the start
    int leg = -1;
    QElapsedTimer legClock;
    bool changed = false; // something was written: restore before ending
    bool torqueWasOn = false;
};

JointIdentify::JointIdentify(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

std::vector<Step> JointIdentify::readSteps(std::shared_ptr<Run> run, const QStringList &keys)
{
    return m_bus.readValues(run->target, keys, [run](const QString &key, qint32 value) {
        run->now.insert(key, value);
    });
}

Step JointIdentify::writeStep(std::shared_ptr<Run> run, const QString &key, qint32 value)
{
    return m_bus.writeValue(run->target, key, value, [run] { run->changed = true; });
}

void JointIdentify::run(const ServoInfo &servo, GuidedFlows::Finish finish, Pause pause)
{
    auto run = std::make_shared<Run>();
    run->servo = servo;
    run->target = std::make_shared<ServoInfo>(servo);
    run->finish = std::move(finish);
    run->pause = std::move(pause);
    const RegisterTable &table = servo.table();
    if (!servo.hasTable() || !table.find(kGoalPosition) || !table.find(kPresentPosition)
        || !table.find(kTorqueEnable) || !table.torqueValue(TorqueMode::On)
        || !table.torqueValue(TorqueMode::Off)) {
        end(run, OperationFailure::Unsupported,
            FeetechSessionTr::tr(
                "%1 is of a model ServoBench does not move (%2); it cannot be identified.")
                .arg(servoName(servo), servo.model.name));
        return;
    }
    std::vector<Step> steps {m_bus.setBaud(servo.baud)};
    for (Step &step : readSteps(run,
                                {kMinAngleLimit, kMaxAngleLimit, kMode, kTorqueEnable, kTorqueLimit,
                                 kGoalSpeed, kAcceleration, kGoalPosition, kPresentPosition}))
        steps.push_back(std::move(step));
    m_bus.runSteps(std::move(steps), [this, run](bool ok, const QString &message) {
        if (!ok) {
            end(run, m_bus.stepFailure(),
                FeetechSessionTr::tr("%1 does not answer: %2").arg(servoName(run->servo), message));
            return;
        }
        run->before = run->now;
        begin(run);
    });
}

void JointIdentify::begin(std::shared_ptr<Run> run)
{
    const ServoInfo &servo = run->servo;
    const RegisterTable &table = servo.table();
    const QHash<QString, qint32> &before = run->before;
    if (const QString refusal = whyNotToMove(servo, before, &run->torqueWasOn);
        !refusal.isEmpty()) {
        end(run, OperationFailure::Unsupported, refusal);
        return;
    }
    if (m_cancelled) {
        end(run, OperationFailure::Stopped,
            FeetechSessionTr::tr("Identifying %1 was stopped; nothing was written.")
                .arg(servoName(servo)));
        return;
    }
    const auto read = [&before](const QString &key) -> std::optional<qint64> {
        if (!before.contains(key))
            return std::nullopt;
        return before.value(key);
    };
    const auto range = goalRange(table, read(kMinAngleLimit), read(kMaxAngleLimit));
    const qint32 start = before.value(kPresentPosition);
    if (!range || !range->contains(start)) {
        end(run, OperationFailure::NoRoomToMove,
            FeetechSessionTr::tr(
                "%1 stands at %2, outside the goal positions it accepts: it is not moved.")
                .arg(servoName(servo))
                .arg(start));
        return;
    }
    const qint32 up = std::min(start + kAmplitude, range->maximum);
    const qint32 down = std::max(start - kAmplitude, range->minimum);
    if (up - down < kAmplitude) {
        end(run, OperationFailure::NoRoomToMove,
            FeetechSessionTr::tr("%1's angle limits leave no room to move it around %2.")
                .arg(servoName(servo))
                .arg(start));
        return;
    }
    run->legs = {up, down, start};

    // The goal first: torque switched on over a stale goal would jump there.
    std::vector<Step> steps {writeStep(run, kGoalPosition, start)};
    if (const Register *speed = table.find(kGoalSpeed))
        steps.push_back(writeStep(run, kGoalSpeed, std::min(kSlowSpeed, speed->maximum)));
    if (const Register *acceleration = table.find(kAcceleration))
        steps.push_back(
            writeStep(run, kAcceleration,
                      std::clamp(kGentleAcceleration, std::max(acceleration->minimum, 1),
                                 acceleration->maximum)));
    const Register *limit = table.find(kTorqueLimit);
    if (limit && limit->storage == Storage::Ram && limit->writable()
        && before.contains(kTorqueLimit)) {
        const auto low = qint32(std::lround(limit->maximum * kTorqueShare));
        steps.push_back(writeStep(run, kTorqueLimit, std::min(low, before.value(kTorqueLimit))));
    }
    if (!run->torqueWasOn)
        steps.push_back(writeStep(run, kTorqueEnable, *table.torqueValue(TorqueMode::On)));
    runOrRestore(run, std::move(steps), [this, run] { nextLeg(run); });
}

void JointIdentify::runOrRestore(std::shared_ptr<Run> run, std::vector<Step> steps,
                                 std::function<void()> then)
{
    // Telemetry and All torque off use the bus during the pauses, at other rates: every
    // sequence sets the servo's rate again before talking to it.
    steps.insert(steps.begin(), m_bus.setBaud(run->servo.baud));
    m_bus.runSteps(std::move(steps), [this, run, then](bool ok, const QString &message) {
        if (!ok) {
            restore(run, false, m_bus.stepFailure(),
                    FeetechSessionTr::tr("%1 stopped answering: %2")
                        .arg(servoName(run->servo), message));
            return;
        }
        then();
    });
}

void JointIdentify::nextLeg(std::shared_ptr<Run> run)
{
    ++run->leg;
    if (run->leg >= run->legs.size()) {
        restore(run, false, OperationFailure::None, {});
        return;
    }
    if (m_cancelled) {
        restore(run, false, OperationFailure::Stopped,
                FeetechSessionTr::tr("Identifying %1 was stopped.").arg(servoName(run->servo)));
        return;
    }
    run->legClock.start();
    runOrRestore(run, {writeStep(run, kGoalPosition, run->legs.at(run->leg))},
                 [this, run] { poll(run); });
}

void JointIdentify::poll(std::shared_ptr<Run> run)
{
    run->pause(m_bus.timing().identifyPollInterval, [this, run](bool torqueOff) {
        if (torqueOff) {
            restore(run, true, OperationFailure::AfterTorqueOff,
                    FeetechSessionTr::tr("All torque off: identifying %1 was stopped.")
                        .arg(servoName(run->servo)));
            return;
        }
        if (m_cancelled) {
            restore(run, false, OperationFailure::Stopped,
                    FeetechSessionTr::tr("Identifying %1 was stopped.").arg(servoName(run->servo)));
            return;
        }
        run->now.remove(kMoving);
        runOrRestore(run, readSteps(run, {kPresentPosition, kMoving}), [this, run] {
            const qint32 goal = run->legs.at(run->leg);
            const bool there = std::abs(run->now.value(kPresentPosition) - goal) <= kReachTolerance
                && run->now.value(kMoving) == 0;
            // Held off by a load, say: the wiggle goes on from where it is.
            const bool late = run->legClock.elapsed() >= m_bus.timing().identifyMoveTimeout.count();
            if (there || late)
                nextLeg(run);
            else
                poll(run);
        });
    });
}

void JointIdentify::restore(std::shared_ptr<Run> run, bool torqueOff, OperationFailure kind,
                            const QString &failure)
{
    const RegisterTable &table = run->servo.table();
    const QHash<QString, qint32> &before = run->before;
    std::vector<Step> steps {m_bus.setBaud(run->servo.baud)};
    QStringList restored;
    // Torque off first where it was off, so putting the goal back moves nothing; after All
    // torque off it stays off whatever it was.
    if (!run->torqueWasOn && !torqueOff)
        steps.push_back(writeStep(run, kTorqueEnable, *table.torqueValue(TorqueMode::Off)));
    for (const QString &key : {kGoalPosition, kGoalSpeed, kAcceleration, kTorqueLimit}) {
        if (before.contains(key) && table.find(key) && table.find(key)->writable()) {
            steps.push_back(writeStep(run, key, before.value(key)));
            restored.append(key);
        }
    }
    if (!torqueOff)
        restored.append(kTorqueEnable);
    if (!run->changed) {
        end(run, kind, failure);
        return;
    }
    for (Step &step : readSteps(run, restored))
        steps.push_back(std::move(step));
    m_bus.runSteps(
        std::move(steps), [this, run, restored, kind, failure](bool ok, const QString &message) {
            const OperationFailure restoreFailure =
                ok ? OperationFailure::NotVerified : m_bus.stepFailure();
            const QString problem = ok
                ? notRestoredAsItWas(restored, run->before, run->now)
                : FeetechSessionTr::tr(
                      "its registers could not be restored (%1); check its torque.")
                      .arg(message);
            if (!failure.isEmpty()) {
                end(run, kind, problem.isEmpty() ? failure : failure + QLatin1Char(' ') + problem);
                return;
            }
            if (!problem.isEmpty()) {
                end(run, restoreFailure,
                    FeetechSessionTr::tr("%1 was moved, but %2")
                        .arg(servoName(run->servo), problem));
                return;
            }
            end(run, OperationFailure::None,
                (run->torqueWasOn
                     ? FeetechSessionTr::tr("%1 (%2) wiggled around %3 and is back; its torque is "
                                            "on, as it was.")
                     : FeetechSessionTr::tr("%1 (%2) wiggled around %3 and is back; its torque is "
                                            "off, as it was."))
                    .arg(servoName(run->servo), run->servo.model.name)
                    .arg(run->legs.last()));
        });
}

void JointIdentify::end(std::shared_ptr<Run> run, OperationFailure failure, const QString &message)
{
    OperationResult result {
        Operation::Identify, failure == OperationFailure::None, message, run->servo, {}};
    result.failure = failure;
    run->finish(result);
}

} // namespace feetech
