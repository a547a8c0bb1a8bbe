// The health check's move test, run only once confirmed: a small step around where the horn
// stands, recorded and measured (rise time, overshoot, steady-state error), then the horn put
// back and its torque, goal and limits as they were.
#pragma once

#include "busexchange.h"
#include "servohealth.h"

#include <QObject>

#include <chrono>
#include <functional>
#include <memory>

namespace feetech {

// Lives in the session's thread; between its polls the bus is free for telemetry and All
// torque off (which ends the test with the torque left off).
class HealthMoveTest : public QObject
{
    Q_OBJECT

public:
    static constexpr qint32 kAmplitude = 100; // steps, up where there is room, else down
    static constexpr qint32 kReachTolerance = 15; // steps
    static constexpr std::chrono::milliseconds kPollInterval {10};
    static constexpr std::chrono::milliseconds kRecordTime {700};
    static constexpr std::chrono::milliseconds kReturnTimeout {2500};

    // Gives the bus up for `delay`; `resume` gets whether All torque off came meanwhile.
    using Pause = std::function<void(std::chrono::milliseconds delay,
                                     std::function<void(bool torqueOff)> resume)>;

    explicit HealthMoveTest(BusExchange &bus, QObject *parent = nullptr);

    // Reads mode, torque, goal, position and angle limits; refuses (nothing written) a servo of
    // an unknown model, not in position mode, or without room to move. Then goal = present
    // position before torque on (never a jump), the step, the way back, the restore.
    void run(const ServoInfo &servo, Pause pause, std::function<void(const MoveTestResult &)> done);
    // The guard held or switched off the servo at `id` and `baud`: a test running on it ends at
    // its next poll; its torque is put back as it was, its goal stays where the guard put it.
    void stopForGuard(quint8 id, qint32 baud);

private:
    struct Run;
    std::vector<Step> readSteps(std::shared_ptr<Run> run, const QStringList &keys);
    Step writeStep(std::shared_ptr<Run> run, const QString &key, qint32 value);
    void begin(std::shared_ptr<Run> run);
    void runOrRestore(std::shared_ptr<Run> run, std::vector<Step> steps,
                      std::function<void()> then);
    void poll(std::shared_ptr<Run> run);
    void afterPoll(std::shared_ptr<Run> run);
    // Puts back what was changed; `failure` (of kind `kind`) is why it ended early.
    void restore(std::shared_ptr<Run> run, bool torqueOff, OperationFailure kind,
                 const QString &failure);
    // Succeeds when `failure` is None.
    void end(std::shared_ptr<Run> run, OperationFailure failure, const QString &message);

    BusExchange &m_bus;
    std::weak_ptr<Run> m_running;
};

} // namespace feetech
