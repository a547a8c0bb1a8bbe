// The Feetech bus session: one link, and the operations on it run one at a time in order.
#pragma once

#include "busoperation.h"
#include "bustypes.h"
#include "linktypes.h"
#include "operationcontext.h"
#include "overloadguard.h"
#include "telemetry.h"

#include <QObject>

#include <functional>
#include <memory>
#include <optional>

namespace seriallink {
class LinkSession;
}

namespace share {
class BusShare;
}

namespace feetech {

struct SessionPrivate;

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
    seriallink::LinkSession &link();
    // The bus shared with another program (off until started). While it shares, telemetry
    // cycles and the guard's reads wait (the program's own reads feed the telemetry instead,
    // and memoryRead as a refresh would), operations go between the program's transactions,
    // and those that would change the port's rate under it (changesPortRate) end at once with
    // OperationFailure::BusShared.
    share::BusShare &share();
    static bool changesPortRate(feetech::Operation kind);
    bool isBusy() const;
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
    // set-up or joint check, a health check, a replay) stops before its next step, cleanly.
    void cancel(feetech::Operation kind);

    // Telemetry: a cycle of SYNC READs (one READ per servo where the family has no SYNC READ)
    // of the feedback block, at the options' rate, between operations, until stopTelemetry.
    void startTelemetry(const feetech::TelemetryOptions &options);
    void stopTelemetry();
    bool isStreaming() const;

    // The overload and thermal guard (GuardKeeper): on from the start; these replace its
    // settings. Its warnings and actions come as guardEvent and notes in the packet log.
    void setGuardSettings(const feetech::GuardSettings &settings);
    const GuardSettings &guardSettings() const;

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

    void connectShare();
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

    std::unique_ptr<SessionPrivate> d;
    OperationContext m_context;
};

} // namespace feetech
