// Replay of a recorded motion on a Feetech bus: torque on without a jump, an eased move to the
// first frame, the frames at their recorded times by SYNC WRITE, then a hold or torque off.
#pragma once

#include "busexchange.h"
#include "bustypes.h"
#include "feetechpacket.h"

#include <QMetaType>
#include <QObject>
#include <QVector>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>

namespace feetech {

// What to play: the servos, and frames of one goal per servo (in position steps) at times in
// seconds. Times never go back; they count from the first frame, whatever its own time.
struct ReplayPlan
{
    QVector<ServoInfo> servos;
    QVector<double> times;
    QVector<QVector<qint32>> frames; // frames[i][j]: servo j's goal at times[i]
    double speed = 1.0; // 2 plays twice as fast, 0.5 at half speed
    // How long the move from where the arm stands to the first frame takes; none: from the
    // distance at MotionReplay::kEaseSpeed. Never quicker than kFastestEaseSpeed allows.
    std::optional<double> easeSeconds;
    int loops = 1; // between two, an eased move from the last frame back to the first
    bool release = false; // torque off at the end instead of holding the last frame

    double duration() const { return times.isEmpty() ? 0.0 : times.last() - times.first(); }
};

// Where a replay is: its progress detail.
struct ReplayPosition
{
    int loop = 0; // from 0
    int frame = -1; // the frame sent last in this loop; -1 while easing to the first
    double seconds = 0.0; // that frame's time from the first frame
    bool easing = false;
};

// Lives in the session's thread; the session runs it as one operation that gives the bus up
// between two goals (telemetry goes on, All torque off goes first).
class MotionReplay : public QObject
{
    Q_OBJECT

public:
    static constexpr double kEaseSpeed = 400.0; // steps per second, on average, by default
    static constexpr double kFastestEaseSpeed = 1000.0; // steps per second, whatever --ease says
    static constexpr double kShortestEaseSeconds = 0.2;
    static constexpr std::chrono::milliseconds kEaseInterval {20};
    static constexpr std::chrono::milliseconds kProgressInterval {100};

    struct Hooks
    {
        std::function<void(const OperationResult &result)> finish;
        // Gives the bus up for `delay`; `resume` gets whether All torque off came meanwhile.
        std::function<void(std::chrono::milliseconds delay,
                           std::function<void(bool torqueOff)> resume)>
            pause;
        std::function<void(const OperationProgress &progress)> progress;
        // Each SYNC WRITE of goals as it goes out (the guard follows the goals).
        std::function<void(qint32 baud, int address, const QVector<SyncWriteEntry> &entries)> sent;
    };

    explicit MotionReplay(BusExchange &bus, QObject *parent = nullptr);

    // Reads each servo's mode, torque, angle limits and position; refuses, with nothing
    // written, a servo that is not in position mode and a frame beyond a servo's angle limits.
    // Then goal = present and torque on, the eased move, the frames, the loops, and the end.
    void run(const ReplayPlan &plan, Hooks hooks);
    // Stops before the next goal: each servo then holds where it stands (goal = present).
    void cancel() { m_cancelled = true; }
    // Called when a replay is queued, so a stop asked for while it waits still counts.
    void clearCancel() { m_cancelled = false; }

private:
    struct Run;
    void begin(std::shared_ptr<Run> run);
    void startEase(std::shared_ptr<Run> run, const QVector<qint32> &from);
    void easeTick(std::shared_ptr<Run> run);
    void startLoop(std::shared_ptr<Run> run);
    void playTick(std::shared_ptr<Run> run);
    void endLoop(std::shared_ptr<Run> run);
    // Sends `goals` (one per servo) by SYNC WRITE, one per rate, then `then`.
    void send(std::shared_ptr<Run> run, const QVector<qint32> &goals, std::function<void()> then);
    // Gives the bus up until `dueNs` on the run's clock, then `then` (or the stop).
    void waitUntil(std::shared_ptr<Run> run, qint64 dueNs, std::function<void()> then);
    void report(std::shared_ptr<Run> run, bool force);
    void stop(std::shared_ptr<Run> run);
    void end(std::shared_ptr<Run> run, OperationFailure failure, const QString &message);

    BusExchange &m_bus;
    bool m_cancelled = false;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::ReplayPosition)
