// The Feetech bus session: one link, and the operations on it run one at a time in order.
#pragma once

#include "applyflow.h"
#include "busexchange.h"
#include "busoperation.h"
#include "busscan.h"
#include "bustypes.h"
#include "guardkeeper.h"
#include "guidedflows.h"
#include "healthcheck.h"
#include "healthmovetest.h"
#include "jointidentify.h"
#include "linktypes.h"
#include "motorsetup.h"
#include "operationcontext.h"
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

    // Slots, called through QMetaObject::invokeMethod from other threads.
    void open(const QString &portName, qint32 baud, seriallink::EchoMode echo);
    void close();

    // Queues an operation (busoperations.h makes them): operations run one at a time in the
    // order submitted, All torque off ahead of them; each ends with operationFinished (a scan
    // with scanFinished). Between the steps of a long one the bus is free for telemetry, the
    // guard and All torque off.
    void submit(const feetech::BusOperation &operation);
    // Not queued: a running or waiting operation of this kind (a scan, an identify, a motor
    // set-up or joint check, a health check) stops before its next step, cleanly.
    void cancel(feetech::Operation kind);

    // Telemetry: a cycle of SYNC READs (one READ per servo where the family has no SYNC READ)
    // of the feedback block, at the options' rate, between operations, until stopTelemetry.
    void startTelemetry(const feetech::TelemetryOptions &options);
    void stopTelemetry();
    bool isStreaming() const;

    // The overload and thermal guard (GuardKeeper): on from the start; these replace its
    // settings. Its warnings and actions come as guardEvent and notes in the packet log.
    void setGuardSettings(const feetech::GuardSettings &settings);
    const GuardSettings &guardSettings() const { return m_guard->settings(); }

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
    void operationProgress(const feetech::OperationProgress &progress);
    void operationFinished(const feetech::OperationResult &result);
    void packetLogged(const seriallink::PacketLogEntry &entry);
    void countersChanged(const seriallink::LinkCounters &counters);
    void telemetry(const QVector<feetech::FeedbackSample> &samples, quint64 stream);
    void telemetryStats(const feetech::TelemetryStats &stats);
    void guardEvent(const feetech::GuardEvent &event);

private:
    friend class OperationContext; // how operations report, yield and end their turn

    // An operation waiting for its turn, with the torque-off count when it was submitted.
    struct Queued
    {
        BusOperation operation;
        quint64 epoch = 0;
    };
    void onLinkDown(const QString &message);
    void finishOperation(const OperationResult &result);
    // Ends the running operation's turn on the bus; `resume` runs as the next operation.
    void continueLater(Operation next, std::function<void()> resume);
    // Ends the running operation's turn on the bus for `delay`: meanwhile only telemetry and
    // All torque off use it, then `resume` runs as the next operation.
    void pauseFor(std::chrono::milliseconds delay,
                  std::function<void(bool torqueOffMeanwhile)> resume);
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
    // Where a paused or continued operation goes back in: behind any All torque off.
    std::deque<Queued>::iterator afterTorqueOff();
    // A continuation of the running operation: its kind, ticket and torque-off count.
    Queued continuation(Operation kind, std::function<void()> resume) const;

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
    OperationContext m_context;
    std::deque<Queued> m_queue;
    bool m_running = false;
    Queued m_current; // the running one (its start function spent)
    bool m_paused = false; // the current operation waits in pauseFor
    Queued m_pausedOperation; // the one waiting, while m_paused
    quint64 m_pauseGeneration = 0; // a pause ended by a lost link never resumes
    quint64 m_torqueOffEpoch = 0; // counts torque-offs: a write queued before one is dropped
    bool m_identifying = false; // an identify runs, paused, or waits to go on
};

} // namespace feetech
