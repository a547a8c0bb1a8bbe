// Replay of a recorded motion: read, check, hold, ease in, play at the recorded times, hold.
#include "motionreplay.h"

#include "feetechsessiontr.h"
#include "feetechvalue.h"
#include "goalrange.h"
#include "registerkeys.h"
#include "torqueonhold.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>

#include <algorithm>
#include <cmath>

namespace feetech {

using namespace registerkeys;

struct MotionReplay::Run
{
    ReplayPlan plan;
    Hooks hooks;
    QVector<std::shared_ptr<ServoInfo>> targets;
    QVector<QHash<QString, qint32>> before; // each servo's registers as read at the start
    QVector<qint32> rates; // the rates of the servos, each once, in the plan's order
    QElapsedTimer clock; // the current ease or loop
    QElapsedTimer reported;
    // The ease under way.
    QVector<qint32> easeFrom;
    qint64 easeNs = 0;
    int loop = 0;
    int sent = -1; // the frame of this loop sent last
    bool easing = false;
    int clamped = 0; // goals a little past a joint's limits, played at the limit
};

namespace {

constexpr double kNsPerSecond = 1e9;
// How far past a joint's limit a recorded position may lie and still be played, at the limit:
// a hand moving a joint to its end overshoots by a few steps (some 4° here); farther is no
// overshoot but a recording of another arm, refused.
constexpr qint64 kOvershootSteps = 50;
const double kPi = std::acos(-1.0);

// The frame's time on the run's clock, at the plan's speed.
qint64 dueNs(const ReplayPlan &plan, int frame)
{
    return qint64(
        std::llround((plan.times.at(frame) - plan.times.first()) / plan.speed * kNsPerSecond));
}

} // namespace

MotionReplay::MotionReplay(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

void MotionReplay::run(const ReplayPlan &plan, Hooks hooks)
{
    auto run = std::make_shared<Run>();
    run->plan = plan;
    run->hooks = std::move(hooks);
    if (plan.servos.isEmpty() || plan.frames.isEmpty() || plan.times.size() != plan.frames.size()
        || plan.speed <= 0.0 || plan.loops < 1) {
        end(run, OperationFailure::InvalidRequest,
            FeetechSessionTr::tr("There is nothing to replay."));
        return;
    }
    std::vector<Step> steps;
    for (const ServoInfo &servo : plan.servos) {
        const RegisterTable &table = servo.table();
        if (!servo.hasTable() || !table.find(kGoalPosition) || !table.find(kPresentPosition)
            || !table.find(kTorqueEnable) || !table.torqueValue(TorqueMode::On)
            || !table.torqueValue(TorqueMode::Off)) {
            end(run, OperationFailure::Unsupported,
                FeetechSessionTr::tr(
                    "%1 is of a model ServoBench does not move (%2): nothing was replayed.")
                    .arg(servoName(servo), servo.model.name));
            return;
        }
        const int index = int(run->targets.size());
        run->targets.append(std::make_shared<ServoInfo>(servo));
        run->before.append(QHash<QString, qint32>());
        if (!run->rates.contains(servo.baud))
            run->rates.append(servo.baud);
        steps.push_back(m_bus.setBaud(servo.baud));
        for (Step &step : m_bus.readValues(
                 run->targets.last(),
                 {kMinAngleLimit, kMaxAngleLimit, kMode, kTorqueEnable, kPresentPosition},
                 [run, index](const QString &key, qint32 value) {
                     run->before[index].insert(key, value);
                 }))
            steps.push_back(std::move(step));
    }
    m_bus.runSteps(std::move(steps), [this, run](bool ok, const QString &message) {
        if (!ok) {
            end(run, m_bus.stepFailure(),
                FeetechSessionTr::tr("A servo does not answer: %1 Nothing was replayed.")
                    .arg(message));
            return;
        }
        begin(run);
    });
}

void MotionReplay::begin(std::shared_ptr<Run> run)
{
    const ReplayPlan &plan = run->plan;
    QVector<bool> torqueWasOn(plan.servos.size(), false);
    QVector<qint32> present;
    for (int j = 0; j < plan.servos.size(); ++j) {
        const ServoInfo &servo = plan.servos.at(j);
        const QHash<QString, qint32> &before = run->before.at(j);
        bool on = false;
        if (const QString refusal = whyNotToMove(servo, before, &on); !refusal.isEmpty()) {
            end(run, OperationFailure::Unsupported, refusal);
            return;
        }
        torqueWasOn[j] = on;
        const auto read = [&before](const QString &key) -> std::optional<qint64> {
            if (!before.contains(key))
                return std::nullopt;
            return before.value(key);
        };
        const auto range = goalRange(servo.table(), read(kMinAngleLimit), read(kMaxAngleLimit));
        for (int i = 0; range && i < plan.frames.size(); ++i) {
            const qint32 goal = plan.frames.at(i).at(j);
            if (range->contains(goal))
                continue;
            if (goal >= range->minimum - kOvershootSteps
                && goal <= range->maximum + kOvershootSteps) {
                run->plan.frames[i][j] = qBound(range->minimum, goal, range->maximum);
                ++run->clamped;
                continue;
            }
            end(run, OperationFailure::InvalidRequest,
                FeetechSessionTr::tr(
                    "Frame %1 (at %2 s) asks %3 for %4, outside the positions it accepts "
                    "(%5 to %6): nothing was moved.")
                    .arg(i + 1)
                    .arg(plan.times.at(i) - plan.times.first(), 0, 'f', 3)
                    .arg(servoName(servo))
                    .arg(goal)
                    .arg(range->minimum)
                    .arg(range->maximum));
            return;
        }
        present.append(before.value(kPresentPosition));
    }
    if (m_cancelled) {
        end(run, OperationFailure::Stopped,
            FeetechSessionTr::tr("The replay was stopped; nothing was moved."));
        return;
    }
    // The goal first: torque switched on over a stale goal would jump there.
    std::vector<Step> steps;
    for (int j = 0; j < plan.servos.size(); ++j) {
        const auto &target = run->targets.at(j);
        steps.push_back(m_bus.setBaud(target->baud));
        steps.push_back(m_bus.writeValue(target, kGoalPosition, present.at(j), [] {}));
        if (!torqueWasOn.at(j))
            steps.push_back(m_bus.writeValue(target, kTorqueEnable,
                                             *target->table().torqueValue(TorqueMode::On), [] {}));
    }
    m_bus.runSteps(std::move(steps), [this, run, present](bool ok, const QString &message) {
        if (!ok) {
            end(run, m_bus.stepFailure(),
                FeetechSessionTr::tr("The servos could not be held where they stand: %1")
                    .arg(message));
            return;
        }
        run->reported.start();
        startEase(run, present);
    });
}

void MotionReplay::startEase(std::shared_ptr<Run> run, const QVector<qint32> &from)
{
    const QVector<qint32> &to = run->plan.frames.first();
    qint32 distance = 0;
    for (int j = 0; j < from.size(); ++j)
        distance = std::max(distance, std::abs(to.at(j) - from.at(j)));
    const double fastest = distance / kFastestEaseSpeed;
    const double seconds = run->plan.easeSeconds
        ? std::max(*run->plan.easeSeconds, fastest)
        : std::max(distance / kEaseSpeed, distance > 0 ? kShortestEaseSeconds : 0.0);
    run->easing = true;
    run->easeFrom = from;
    run->easeNs = qint64(std::llround(seconds * kNsPerSecond));
    run->clock.start();
    report(run, true);
    // The first goal a step away from where the move starts: that one is held already.
    const qint64 interval = std::chrono::nanoseconds(kEaseInterval).count();
    waitUntil(run, std::min(interval, run->easeNs), [this, run] { easeTick(run); });
}

void MotionReplay::easeTick(std::shared_ptr<Run> run)
{
    if (m_cancelled) {
        stop(run);
        return;
    }
    const qint64 now = run->clock.nsecsElapsed();
    const QVector<qint32> &to = run->plan.frames.first();
    if (now >= run->easeNs) {
        run->easing = false;
        startLoop(run);
        return;
    }
    // A cosine's half period: the move starts and ends at rest.
    const double share = (1.0 - std::cos(kPi * double(now) / double(run->easeNs))) / 2.0;
    QVector<qint32> goals;
    for (int j = 0; j < to.size(); ++j) {
        const qint32 from = run->easeFrom.at(j);
        goals.append(from + qint32(std::lround((to.at(j) - from) * share)));
    }
    send(run, goals, [this, run, now] {
        report(run, false);
        const qint64 interval = std::chrono::nanoseconds(kEaseInterval).count();
        waitUntil(run, std::min(now + interval, run->easeNs), [this, run] { easeTick(run); });
    });
}

void MotionReplay::startLoop(std::shared_ptr<Run> run)
{
    run->sent = -1;
    run->clock.start();
    report(run, true);
    playTick(run);
}

void MotionReplay::playTick(std::shared_ptr<Run> run)
{
    if (m_cancelled) {
        stop(run);
        return;
    }
    const ReplayPlan &plan = run->plan;
    const qint64 now = run->clock.nsecsElapsed();
    // The newest frame that is due; one the bus fell behind on is skipped rather than sent late.
    int frame = run->sent;
    while (frame + 1 < plan.frames.size() && dueNs(plan, frame + 1) <= now)
        ++frame;
    if (frame == run->sent) {
        waitUntil(run, dueNs(plan, frame + 1), [this, run] { playTick(run); });
        return;
    }
    run->sent = frame;
    send(run, plan.frames.at(frame), [this, run] {
        const bool last = run->sent + 1 >= run->plan.frames.size();
        report(run, last);
        if (last) {
            endLoop(run);
            return;
        }
        waitUntil(run, dueNs(run->plan, run->sent + 1), [this, run] { playTick(run); });
    });
}

void MotionReplay::endLoop(std::shared_ptr<Run> run)
{
    const ReplayPlan &plan = run->plan;
    if (run->loop + 1 < plan.loops) {
        ++run->loop;
        startEase(run, plan.frames.last());
        return;
    }
    QString played = FeetechSessionTr::tr("Played %n frame(s)", nullptr, int(plan.frames.size()));
    if (run->clamped > 0)
        played += FeetechSessionTr::tr(" (%n position(s) a little past a joint's limit played at "
                                       "the limit)",
                                       nullptr, run->clamped);
    const QString loops = FeetechSessionTr::tr("%n time(s)", nullptr, plan.loops);
    if (!plan.release) {
        end(run, OperationFailure::None,
            FeetechSessionTr::tr("%1 %2; the arm holds the last frame.").arg(played, loops));
        return;
    }
    std::vector<Step> steps;
    for (const auto &target : run->targets) {
        steps.push_back(m_bus.setBaud(target->baud));
        steps.push_back(m_bus.writeValue(target, kTorqueEnable,
                                         *target->table().torqueValue(TorqueMode::Off), [] {}));
    }
    m_bus.runSteps(std::move(steps), [this, run, played, loops](bool ok, const QString &message) {
        if (!ok) {
            end(run, m_bus.stepFailure(),
                FeetechSessionTr::tr("%1 %2, but torque could not be switched off: %3")
                    .arg(played, loops, message));
            return;
        }
        end(run, OperationFailure::None,
            FeetechSessionTr::tr("%1 %2; torque is off.").arg(played, loops));
    });
}

void MotionReplay::send(std::shared_ptr<Run> run, const QVector<qint32> &goals,
                        std::function<void()> then)
{
    std::vector<Step> steps;
    for (const qint32 baud : std::as_const(run->rates)) {
        QVector<SyncWriteEntry> entries;
        const Register *goal = nullptr;
        for (int j = 0; j < run->targets.size(); ++j) {
            const ServoInfo &servo = *run->targets.at(j);
            if (servo.baud != baud)
                continue;
            const Register *reg = servo.table().find(kGoalPosition);
            const auto bytes = encodeValue(goals.at(j), servo.table().format(*reg));
            // Same address and size across a rate's servos: one SYNC WRITE carries them all.
            if (!bytes || (goal && (goal->address != reg->address || goal->size != reg->size))) {
                end(run, OperationFailure::Unsupported,
                    FeetechSessionTr::tr(
                        "%1 cannot take goal %2 with the others in one SYNC WRITE.")
                        .arg(servoName(servo))
                        .arg(goals.at(j)));
                return;
            }
            goal = reg;
            entries.append({servo.id, *bytes});
        }
        const auto frame = syncWrite(quint8(goal->address), quint8(goal->size), entries);
        if (!frame) {
            end(run, OperationFailure::InvalidRequest,
                FeetechSessionTr::tr("The SYNC WRITE does not fit in one packet."));
            return;
        }
        if (run->hooks.sent)
            run->hooks.sent(baud, goal->address, entries);
        steps.push_back(m_bus.setBaud(baud));
        steps.push_back(
            m_bus.instruction(kBroadcastId, *frame, false,
                              FeetechSessionTr::tr("SYNC WRITE at %1").arg(baudText(baud))));
    }
    m_bus.runSteps(std::move(steps),
                   [this, run, then = std::move(then)](bool ok, const QString &message) {
                       if (!ok) {
                           end(run, m_bus.stepFailure(),
                               FeetechSessionTr::tr("The replay stopped: %1").arg(message));
                           return;
                       }
                       then();
                   });
}

void MotionReplay::waitUntil(std::shared_ptr<Run> run, qint64 dueNs, std::function<void()> then)
{
    const qint64 left = std::max<qint64>(0, dueNs - run->clock.nsecsElapsed());
    const auto delay = std::chrono::milliseconds((left + 999999) / 1000000);
    run->hooks.pause(delay, [this, run, then = std::move(then)](bool torqueOff) {
        if (torqueOff) {
            end(run, OperationFailure::AfterTorqueOff,
                FeetechSessionTr::tr("All torque off: the replay was stopped."));
            return;
        }
        then();
    });
}

void MotionReplay::report(std::shared_ptr<Run> run, bool force)
{
    if (!run->hooks.progress || (!force && run->reported.elapsed() < kProgressInterval.count()))
        return;
    run->reported.start();
    const ReplayPlan &plan = run->plan;
    const int frames = int(plan.frames.size());
    ReplayPosition position;
    position.loop = run->loop;
    position.easing = run->easing;
    position.frame = run->easing ? -1 : run->sent;
    position.seconds =
        position.frame >= 0 ? plan.times.at(position.frame) - plan.times.first() : 0.0;
    OperationProgress progress;
    progress.done = run->loop * frames + std::max(0, position.frame + 1);
    progress.total = plan.loops * frames;
    if (run->easing)
        progress.text = FeetechSessionTr::tr("Loop %1 of %2: easing to the first frame")
                            .arg(run->loop + 1)
                            .arg(plan.loops);
    else if (position.frame < 0)
        progress.text = FeetechSessionTr::tr("Loop %1 of %2: playing %3 frames over %4 s")
                            .arg(run->loop + 1)
                            .arg(plan.loops)
                            .arg(frames)
                            .arg(plan.duration() / plan.speed, 0, 'f', 2);
    else
        progress.text = FeetechSessionTr::tr("Loop %1 of %2: frame %3 of %4")
                            .arg(run->loop + 1)
                            .arg(plan.loops)
                            .arg(position.frame + 1)
                            .arg(frames);
    progress.detail = QVariant::fromValue(position);
    run->hooks.progress(progress);
}

void MotionReplay::stop(std::shared_ptr<Run> run)
{
    // Each servo holds where it stands now, not where its last goal would have taken it.
    std::vector<Step> steps;
    for (const auto &target : run->targets) {
        steps.push_back(m_bus.setBaud(target->baud));
        steps.push_back(holdAtPresentPosition(m_bus, target));
    }
    const ReplayPlan &plan = run->plan;
    const QString where = run->easing
        ? FeetechSessionTr::tr("while easing to the first frame (loop %1 of %2)")
              .arg(run->loop + 1)
              .arg(plan.loops)
        : FeetechSessionTr::tr("at %1 s of %2 s (loop %3 of %4)")
              .arg(run->sent >= 0 ? plan.times.at(run->sent) - plan.times.first() : 0.0, 0, 'f', 2)
              .arg(plan.times.last() - plan.times.first(), 0, 'f', 2)
              .arg(run->loop + 1)
              .arg(plan.loops);
    m_bus.runSteps(std::move(steps), [this, run, where](bool ok, const QString &message) {
        end(run, ok ? OperationFailure::Stopped : m_bus.stepFailure(),
            ok ? FeetechSessionTr::tr("The replay was stopped %1; the arm holds where it stood.")
                     .arg(where)
               : FeetechSessionTr::tr(
                     "The replay was stopped %1, but the arm could not be held: %2")
                     .arg(where, message));
    });
}

void MotionReplay::end(std::shared_ptr<Run> run, OperationFailure failure, const QString &message)
{
    if (!run->hooks.finish)
        return; // ended already
    OperationResult result {Operation::Replay,
                            failure == OperationFailure::None,
                            message,
                            run->plan.servos.isEmpty() ? ServoInfo {} : run->plan.servos.first(),
                            {}};
    result.failure = failure;
    const auto finish = std::move(run->hooks.finish);
    run->hooks.finish = {};
    finish(result);
}

} // namespace feetech
