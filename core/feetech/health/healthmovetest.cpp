// The move test: hold, step, record, measure with analyseStep, return, restore.
#include "healthmovetest.h"

#include "feetechsessiontr.h"
#include "feetechvalue.h"
#include "goalrange.h"
#include "registerkeys.h"
#include "servoparameters.h"
#include "torqueonhold.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>

#include <cmath>

namespace feetech {

using namespace registerkeys;

struct HealthMoveTest::Run
{
    std::shared_ptr<ServoInfo> servo;
    Pause pause;
    std::function<void(const MoveTestResult &)> done;
    QHash<QString, qint32> before;
    QHash<QString, qint32> now;
    MoveTestResult result;
    bool returning = false; // on the way back to the start
    bool changed = false;
    bool torqueWasOn = false;
    bool stoppedByGuard = false; // its goal is the guard's now: not put back
    QElapsedTimer clock; // since the step's goal write, then since the way back began
    QVector<TimedValue> samples;
};

HealthMoveTest::HealthMoveTest(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

std::vector<Step> HealthMoveTest::readSteps(std::shared_ptr<Run> run, const QStringList &keys)
{
    return m_bus.readValues(
        run->servo, keys, [run](const QString &key, qint32 value) { run->now.insert(key, value); });
}

Step HealthMoveTest::writeStep(std::shared_ptr<Run> run, const QString &key, qint32 value)
{
    return m_bus.writeValue(run->servo, key, value, [run] { run->changed = true; });
}

void HealthMoveTest::run(const ServoInfo &servo, Pause pause,
                         std::function<void(const MoveTestResult &)> done)
{
    auto run = std::make_shared<Run>();
    m_running = run;
    run->servo = std::make_shared<ServoInfo>(servo);
    run->pause = std::move(pause);
    run->done = std::move(done);
    run->result.id = servo.id;
    run->result.baud = servo.baud;
    const RegisterTable &table = servo.table();
    if (!servo.hasTable() || !table.find(kGoalPosition) || !table.find(kPresentPosition)
        || !table.find(kTorqueEnable) || !table.torqueValue(TorqueMode::On)
        || !table.torqueValue(TorqueMode::Off)) {
        end(run, OperationFailure::Unsupported,
            FeetechSessionTr::tr("%1 is of a model ServoBench does not move (%2): no move test.")
                .arg(servoName(servo), servo.model.name));
        return;
    }
    std::vector<Step> steps {m_bus.setBaud(servo.baud)};
    for (Step &step : readSteps(run,
                                {kMinAngleLimit, kMaxAngleLimit, kMode, kTorqueEnable,
                                 kGoalPosition, kPresentPosition}))
        steps.push_back(std::move(step));
    m_bus.runSteps(std::move(steps), [this, run](bool ok, const QString &message) {
        if (!ok) {
            end(run, m_bus.stepFailure(),
                FeetechSessionTr::tr("%1 does not answer: %2")
                    .arg(servoName(*run->servo), message));
            return;
        }
        run->before = run->now;
        begin(run);
    });
}

void HealthMoveTest::begin(std::shared_ptr<Run> run)
{
    const ServoInfo &servo = *run->servo;
    const RegisterTable &table = servo.table();
    const QHash<QString, qint32> &before = run->before;
    if (const QString refusal = whyNotToMove(servo, before, &run->torqueWasOn);
        !refusal.isEmpty()) {
        end(run, OperationFailure::Unsupported, refusal);
        return;
    }
    const auto read = [&before](const QString &key) -> std::optional<qint64> {
        if (!before.contains(key))
            return std::nullopt;
        return before.value(key);
    };
    const auto range = goalRange(table, read(kMinAngleLimit), read(kMaxAngleLimit));
    const qint32 start = before.value(kPresentPosition);
    qint32 target = start + kAmplitude;
    if (range && !range->contains(target))
        target = start - kAmplitude;
    if (!range || !range->contains(start) || !range->contains(target)) {
        end(run, OperationFailure::NoRoomToMove,
            FeetechSessionTr::tr(
                "%1 stands at %2: its angle limits leave no room for a move of %3 steps.")
                .arg(servoName(servo))
                .arg(start)
                .arg(kAmplitude));
        return;
    }
    run->result.start = start;
    run->result.target = target;
    // Where the horn stands becomes its goal before torque goes on: it holds, it never jumps.
    std::vector<Step> steps;
    if (!run->torqueWasOn) {
        steps.push_back(holdBeforeTorqueOn(m_bus, run->servo));
        steps.push_back([run](StepDone next) {
            run->changed = true;
            next(true, {});
        });
        steps.push_back(writeStep(run, kTorqueEnable, *table.torqueValue(TorqueMode::On)));
    }
    steps.push_back(writeStep(run, kGoalPosition, target));
    runOrRestore(run, std::move(steps), [this, run] {
        run->clock.start();
        run->samples.append({0.0, double(run->result.start)});
        poll(run);
    });
}

void HealthMoveTest::runOrRestore(std::shared_ptr<Run> run, std::vector<Step> steps,
                                  std::function<void()> then)
{
    // Others use the bus during the pauses, maybe at another rate.
    steps.insert(steps.begin(), m_bus.setBaud(run->servo->baud));
    m_bus.runSteps(std::move(steps), [this, run, then](bool ok, const QString &message) {
        if (!ok) {
            restore(run, false, m_bus.stepFailure(),
                    FeetechSessionTr::tr("%1 stopped answering: %2")
                        .arg(servoName(*run->servo), message));
            return;
        }
        then();
    });
}

void HealthMoveTest::stopForGuard(quint8 id, qint32 baud)
{
    if (const auto run = m_running.lock(); run && run->servo->id == id && run->servo->baud == baud)
        run->stoppedByGuard = true;
}

void HealthMoveTest::poll(std::shared_ptr<Run> run)
{
    run->pause(kPollInterval, [this, run](bool torqueOff) {
        if (run->stoppedByGuard) {
            restore(run, false, OperationFailure::GuardStopped,
                    FeetechSessionTr::tr(
                        "The overload guard stopped the move test of %1; its goal stays where "
                        "the guard held it.")
                        .arg(servoName(*run->servo)));
            return;
        }
        if (torqueOff) {
            restore(run, true, OperationFailure::AfterTorqueOff,
                    FeetechSessionTr::tr("All torque off: the move test of %1 was stopped.")
                        .arg(servoName(*run->servo)));
            return;
        }
        run->now.remove(kMoving);
        runOrRestore(run, readSteps(run, {kPresentPosition, kMoving}),
                     [this, run] { afterPoll(run); });
    });
}

void HealthMoveTest::afterPoll(std::shared_ptr<Run> run)
{
    const qint32 position = run->now.value(kPresentPosition);
    const qint64 elapsedMs = run->clock.elapsed();
    if (!run->returning) {
        run->samples.append({double(run->clock.nsecsElapsed()) / 1e9, double(position)});
        if (elapsedMs < kRecordTime.count()) {
            poll(run);
            return;
        }
        run->result.metrics = analyseStep(run->samples, run->result.start, run->result.target);
        run->returning = true;
        run->clock.start();
        runOrRestore(run, {writeStep(run, kGoalPosition, run->result.start)},
                     [this, run] { poll(run); });
        return;
    }
    const bool there =
        std::abs(position - run->result.start) <= kReachTolerance && run->now.value(kMoving) == 0;
    if (there || elapsedMs >= kReturnTimeout.count()) {
        restore(run, false, there ? OperationFailure::None : OperationFailure::NotVerified,
                there ? QString()
                      : FeetechSessionTr::tr("%1 did not get back to %2 (it stands at %3).")
                            .arg(servoName(*run->servo))
                            .arg(run->result.start)
                            .arg(position));
        return;
    }
    poll(run);
}

void HealthMoveTest::restore(std::shared_ptr<Run> run, bool torqueOff, OperationFailure kind,
                             const QString &failure)
{
    if (!run->changed) { // nothing was moved, so nothing was tested
        end(run, kind == OperationFailure::None ? OperationFailure::NotVerified : kind, failure);
        return;
    }
    const RegisterTable &table = run->servo->table();
    std::vector<Step> steps {m_bus.setBaud(run->servo->baud)};
    QStringList restored;
    // Torque off first where it was off, so putting the goal back moves nothing; after All
    // torque off it stays off whatever it was.
    if (!run->torqueWasOn && !torqueOff)
        steps.push_back(writeStep(run, kTorqueEnable, *table.torqueValue(TorqueMode::Off)));
    if (!torqueOff)
        restored.append(kTorqueEnable);
    if (run->before.contains(kGoalPosition) && !run->stoppedByGuard) {
        steps.push_back(writeStep(run, kGoalPosition, run->before.value(kGoalPosition)));
        restored.append(kGoalPosition);
    }
    for (Step &step : readSteps(run, restored))
        steps.push_back(std::move(step));
    m_bus.runSteps(
        std::move(steps), [this, run, restored, kind, failure](bool ok, const QString &message) {
            const OperationFailure restoreFailure =
                ok ? OperationFailure::NotVerified : m_bus.stepFailure();
            const QString problem = ok
                ? notRestoredAsItWas(restored, run->before, run->now)
                : FeetechSessionTr::tr("it could not be restored (%1); check its torque.")
                      .arg(message);
            if (!failure.isEmpty() || !problem.isEmpty()) {
                end(run, failure.isEmpty() ? restoreFailure : kind,
                    QStringList {failure, problem}.join(QLatin1Char(' ')).trimmed());
                return;
            }
            end(run, OperationFailure::None,
                (run->torqueWasOn
                     ? FeetechSessionTr::tr(
                         "%1 moved from %2 to %3 and back; its torque is on, as it was.")
                     : FeetechSessionTr::tr(
                         "%1 moved from %2 to %3 and back; its torque is off, as it was."))
                    .arg(servoName(*run->servo))
                    .arg(run->result.start)
                    .arg(run->result.target));
        });
}

void HealthMoveTest::end(std::shared_ptr<Run> run, OperationFailure failure, const QString &message)
{
    run->result.ok = failure == OperationFailure::None;
    run->result.failure = failure;
    run->result.message = message;
    run->done(run->result);
}

} // namespace feetech
