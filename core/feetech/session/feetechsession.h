// The Feetech bus session: one link, and the operations on it run one at a time in order.
#pragma once

#include "applyflow.h"
#include "busexchange.h"
#include "busscan.h"
#include "bustypes.h"
#include "guardkeeper.h"
#include "guidedflows.h"
#include "healthcheck.h"
#include "healthmovetest.h"
#include "jointidentify.h"
#include "linktypes.h"
#include "motorsetup.h"
#include "requestengine.h"
#include "telemetry.h"
#include "telemetrycycle.h"

#include <QObject>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace seriallink {
class LinkSession;
}

namespace feetech {

// Lives in a link worker thread (or the CLI's main thread); driven only by signals and timers.
// Operations run one at a time in the order they are asked for; a scan can be cancelled.
class Session : public QObject
{
    Q_OBJECT

public:
    explicit Session(const SessionTiming &timing = {}, QObject *parent = nullptr);
    ~Session() override;

    const seriallink::ConnectionStatus &status() const;
    const seriallink::LinkCounters &counters() const;
    seriallink::LinkSession &link() { return *m_link; }
    bool isBusy() const { return m_running || m_paused || !m_queue.empty(); }
    // How quickly servos answer on this port: the median of the last answers (none before the
    // first), from the end of the request to the first byte of the reply.
    std::optional<std::chrono::microseconds> measuredLatency() const;
    std::chrono::microseconds scanAllowance() const;

    // The operation the next call below queues answers under `ticket`: its results carry it,
    // including those of a link that went down first (OperationResult::ticket).
    void setNextTicket(quint64 ticket) { m_nextTicket = ticket; }

    // Slots, called through QMetaObject::invokeMethod from other threads.
    void open(const QString &portName, qint32 baud, seriallink::EchoMode echo);
    void close();

    void scan(const feetech::ScanOptions &options);
    void cancelScan();
    void ping(quint8 id, qint32 baud);
    // Whether several servos answer at the servo's ID (sharedidcheck.h): ok with servo.sharedId
    // set, or not ok when the reads went unanswered.
    void checkSharedId(const feetech::ServoInfo &servo);
    // Every block of the servo's table (the raw view for an unknown model), or only `blocks`.
    // A Refresh is a background read: it runs only when nothing else does.
    void read(const feetech::ServoInfo &servo, const QVector<feetech::Block> &blocks,
              feetech::ReadSource source);
    // EEPROM writes go unlock → write → lock; then every written register is read back.
    // ID and baud changes are refused here: they have their own flows.
    void write(const feetech::ServoInfo &servo, const QVector<feetech::RegisterWrite> &writes);
    // Everything pending, planned by planApply: the registers, then the ID, then the baud rate,
    // each only once the one before succeeded. Every step reports its own result; all but the
    // last have `final` unset.
    void apply(const feetech::ServoInfo &servo, const feetech::ApplyPlan &plan);
    void changeId(const feetech::ServoInfo &servo, int newId, const QVector<int> &idsInUse);
    void changeBaud(const feetech::ServoInfo &servo, qint32 newBaud);
    void calibrateMiddle(const feetech::ServoInfo &servo);
    void factoryReset(const feetech::ServoInfo &servo);
    void reboot(const feetech::ServoInfo &servo);
    void clearStatus(const feetech::ServoInfo &servo);
    // Closes the servo's EEPROM lock (one left open by a write cut short) and reads it back: ok
    // only when it reads back locked.
    void lockEeprom(const feetech::ServoInfo &servo);
    // A frame built by hand, sent once at `baud` (Session::sendPacket): it waits for the
    // answer of `replyId` (`replyDataSize` data bytes), or, without one, listens for a while;
    // what comes back is in the packet log.
    void sendPacket(const QByteArray &frame, qint32 baud, std::optional<quint8> replyId,
                    int replyDataSize);
    // A small, slow, torque-limited wiggle around where the servo stands, then everything it
    // changed put back (see JointIdentify). Between its moves the bus is free for telemetry
    // and All torque off, which stops it with the torque left off.
    void identifyJoint(const feetech::ServoInfo &servo);
    // Not queued: the running identify stops before its next move and restores the servo.
    void cancelIdentify();

    // Telemetry: a cycle of SYNC READs (one READ per servo where the family has no SYNC READ)
    // of the feedback block, at the options' rate, between operations, until stopTelemetry.
    void startTelemetry(const feetech::TelemetryOptions &options);
    void stopTelemetry();
    bool isStreaming() const;
    // Torque enable 0 by broadcast WRITE at each of `bauds`, then read back from `servos`.
    // Runs before anything queued; a running scan is cancelled.
    void torqueOffAll(const QVector<qint32> &bauds, const QVector<feetech::ServoInfo> &servos);
    // One SYNC WRITE (no replies) at `baud`; every entry's data is `length` bytes.
    void syncWrite(qint32 baud, int address, int length,
                   const QVector<feetech::SyncWriteEntry> &entries);

    // The overload and thermal guard (GuardKeeper): on from the start; these replace its
    // settings. Its warnings and actions come as guardEvent and notes in the packet log.
    void setGuardSettings(const feetech::GuardSettings &settings);
    const GuardSettings &guardSettings() const { return m_guard->settings(); }
    // Torque off and on again, then the status checked (see recoverOverload in
    // overloadrecovery.h); with `checkOnly` (after a power cycle) only the status. The result's
    // stillLatched says a power cycle is needed.
    void recoverOverload(const feetech::ServoInfo &servo, bool checkOnly);

    // Motor set-up (MotorSetup): the one servo on the bus found at any rate; found and set up
    // as `target` says; the joints that already answer at their ID at `baud`.
    void findMotor(const feetech::MotorTarget &target);
    void setUpMotor(const feetech::MotorTarget &target);
    void checkJoints(qint32 baud, const QVector<feetech::JointCheck> &joints);
    // Not queued: stops the running one before its next step.
    void cancelMotorSetup();

    // Health check: reads only. Each servo in turn gets its limits
    // and `reads` feedback blocks read (HealthCheck); healthRead and progress follow each one,
    // and the bus is free for All torque off and telemetry between two servos.
    void checkHealth(const QVector<feetech::ServoInfo> &servos, int reads);
    // Not queued: the running check stops before its next servo.
    void cancelHealthCheck();
    // The move test (HealthMoveTest): the caller asks only once the user confirmed it.
    void moveTest(const feetech::ServoInfo &servo);

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void scanProgress(int done, int total, qint32 baud);
    void servoFound(const feetech::ServoInfo &servo);
    void scanFinished(bool completed, const QString &message);
    // Bytes of one block as the servo holds them, with the status byte of its reply.
    void memoryRead(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                    feetech::ReadSource source, quint8 statusByte);
    // The status byte of a reply that carried no data (a PING).
    void statusSeen(quint8 id, qint32 baud, quint8 statusByte);
    void progress(int done, int total);
    void operationFinished(const feetech::OperationResult &result);
    void packetLogged(const seriallink::PacketLogEntry &entry);
    void countersChanged(const seriallink::LinkCounters &counters);
    void telemetry(const QVector<feetech::FeedbackSample> &samples, quint64 stream);
    void telemetryStats(const feetech::TelemetryStats &stats);
    // Before the operationFinished of a find or a set-up, and of a check.
    void motorSetupProgress(int step, int steps, const QString &text);
    void motorSetupFinished(const feetech::MotorSetupResult &result);
    void jointsChecked(const QVector<feetech::JointCheck> &joints);
    // Before the health check's operationFinished, once per servo read.
    void healthRead(const feetech::HealthReading &reading);
    // Before the move test's operationFinished.
    void moveTested(const feetech::MoveTestResult &result);
    void guardEvent(const feetech::GuardEvent &event);

private:
    void onLinkDown(const QString &message);
    void enqueue(Operation operation, std::function<void()> start);
    void finishOperation(const OperationResult &result);
    GuidedFlows::Finish finisher();
    // Ends the running operation's turn on the bus; `resume` runs as the next operation.
    void continueLater(Operation next, std::function<void()> resume);
    // Ends the running operation's turn on the bus for `delay`: meanwhile only telemetry and
    // All torque off use it, then `resume` runs as the next operation.
    void pauseFor(Operation operation, std::chrono::milliseconds delay,
                  std::function<void()> resume);
    void startNextOperation();
    void startQueuedOperation(); // the next operation, whether or not a telemetry cycle is due
    // Telemetry and the guard's reads take turns: a cycle that ended lets the next one go.
    void onCycleEnded();
    bool startCycleIfDue(); // the stream's, else the guard's; true when one started
    bool inCycle() const;
    // The guard's action: ahead of everything queued but All torque off; it ends the
    // operation without an operationFinished (the GuardEvent says what happened).
    void runGuardAction(std::function<void(std::function<void()> finished)> work);
    void onScanFinished(bool completed, const QString &message);
    void checkNextServo(QVector<ServoInfo> servos, int done, int reads);
    // Ends a write queued before the last torque off without sending it; true when it did.
    bool refusedAfterTorqueOff(Operation operation, quint64 epoch);
    // Reads torque enable back after All torque off; counts the servos that confirm it.
    Step confirmTorqueOff(const ServoInfo &servo, std::shared_ptr<int> confirmed);

    SessionTiming m_timing;
    FrameFormat m_format;
    seriallink::LinkSession *m_link = nullptr;
    BusExchange *m_bus = nullptr;
    BusScan *m_scan = nullptr;
    GuidedFlows *m_flows = nullptr;
    TelemetryCycle *m_telemetry = nullptr;
    ApplyFlow *m_apply = nullptr;
    MotorSetup *m_motorSetup = nullptr;
    JointIdentify *m_identify = nullptr;
    HealthCheck *m_health = nullptr;
    HealthMoveTest *m_moveTest = nullptr;
    GuardKeeper *m_guard = nullptr;
    struct Queued
    {
        Operation operation = Operation::Read;
        std::function<void()> start;
        quint64 ticket = 0;
    };
    // The queue entry of a new operation, with the ticket set for it (taken: the next call
    // asks for none unless it is set again).
    Queued newOperation(Operation operation, std::function<void()> start);
    // Where a paused or continued operation goes back in: behind any All torque off.
    std::deque<Queued>::iterator afterTorqueOff();
    std::deque<Queued> m_queue;
    quint64 m_nextTicket = 0;
    bool m_running = false;
    Operation m_currentOperation = Operation::Read;
    quint64 m_currentTicket = 0;
    bool m_paused = false; // the current operation waits in pauseFor
    Operation m_pausedOperation = Operation::Read; // the one waiting, while m_paused
    quint64 m_pausedTicket = 0;
    quint64 m_pauseGeneration = 0; // a pause ended by a lost link never resumes
    quint64 m_torqueOffEpoch = 0; // counts torque-offs: a write queued before one is dropped
    bool m_identifying = false; // an identify runs, paused, or waits to go on
};

} // namespace feetech
