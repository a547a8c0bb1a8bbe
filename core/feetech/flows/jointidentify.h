// Identify a joint: a small, slow, torque-limited wiggle around where a servo stands, then every
// register it changed put back, so a person sees which servo of an arm answers at an ID.
#pragma once

#include "busexchange.h"
#include "bustypes.h"
#include "guidedflows.h"

#include <QObject>

#include <chrono>
#include <functional>
#include <memory>

namespace feetech {

// Lives in the session's thread; the session runs it as one operation that gives the bus up
// while it waits for the horn (telemetry goes on, All torque off goes first).
class JointIdentify : public QObject
{
    Q_OBJECT

public:
    static constexpr qint32 kAmplitude = 100; // steps each way from the start
    static constexpr qint32 kSlowSpeed = 300; // steps per second, where the family has goal_speed
    static constexpr qint32 kGentleAcceleration = 10; // register units (× 100 steps/s²)
    static constexpr double kTorqueShare = 0.3; // of the torque limit register's maximum
    static constexpr qint32 kReachTolerance = 15; // steps

    // Gives the bus up for `delay`; `resume` gets whether All torque off came meanwhile.
    using Pause = std::function<void(std::chrono::milliseconds delay,
                                     std::function<void(bool torqueOff)> resume)>;

    explicit JointIdentify(BusExchange &bus, QObject *parent = nullptr);

    // Reads where the servo stands and what it holds, writes goal = present first (never a
    // jump), a low torque limit, a slow speed and torque on, moves +kAmplitude, -kAmplitude
    // (inside its angle limits) and back, then restores goal, speed, acceleration, torque limit
    // and torque enable and reads them back. Refuses, with nothing written, a servo of an
    // unknown model or not in position mode. A servo that stops answering ends it with that
    // said (the restore is still tried).
    void run(const ServoInfo &servo, GuidedFlows::Finish finish, Pause pause);
    // Stops the running wiggle before its next move and restores the servo as after a failure.
    void cancel() { m_cancelled = true; }
    // Called when an identify is queued, so a stop asked for while it waits still counts.
    void clearCancel() { m_cancelled = false; }

private:
    struct Run;
    std::vector<Step> readSteps(std::shared_ptr<Run> run, const QStringList &keys);
    void begin(std::shared_ptr<Run> run);
    // Runs `steps`, then `then`; a failure means the servo stopped answering: restore.
    void runOrRestore(std::shared_ptr<Run> run, std::vector<Step> steps,
                      std::function<void()> then);
    void nextLeg(std::shared_ptr<Run> run);
    void poll(std::shared_ptr<Run> run);
    // Puts back what was changed; `failure` (of kind `kind`) is why it ended early.
    void restore(std::shared_ptr<Run> run, bool torqueOff, OperationFailure kind,
                 const QString &failure);
    // Succeeds when `failure` is None.
    void end(std::shared_ptr<Run> run, OperationFailure failure, const QString &message);
    Step writeStep(std::shared_ptr<Run> run, const QString &key, qint32 value);

    BusExchange &m_bus;
    bool m_cancelled = false;
};

} // namespace feetech
