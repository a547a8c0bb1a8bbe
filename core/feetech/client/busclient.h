// The GUI thread's handle on a Feetech bus: the session in its worker thread, the servos found,
// and one parameter model per servo kept in step with what the servo reports.
#pragma once

#include "busguard.h"
#include "busoperation.h"
#include "feetechsession.h"
#include "goalrange.h"
#include "healthservice.h"
#include "identifyservice.h"
#include "linkmirror.h"
#include "linktypes.h"
#include "motorsetupservice.h"
#include "operationreply.h"
#include "parametermodel.h"
#include "refusal.h"
#include "servocommands.h"
#include "servohealth.h"
#include "servolist.h"
#include "sessionthread.h"
#include "settingscheckservice.h"
#include "shareservice.h"
#include "telemetry.h"
#include "telemetryhub.h"

#include <QHash>
#include <QObject>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace feetech {

struct BusClientPrivate;

// Each operation it submits returns an OperationReply (nullptr, with *refusal, when refused), which
// finishes with the operation's result; submitted names every reply as it is made, for whoever
// reports all of them (the status bar). Refreshes in the background have none.
class BusClient : public QObject
{
    Q_OBJECT

public:
    explicit BusClient(const SessionTiming &timing = {}, QObject *parent = nullptr);
    ~BusClient() override;

    // The link's state, counters and packet log, on this thread.
    seriallink::LinkMirror *link() { return &m_link; }
    bool isScanning() const;
    bool isBusy() const;

    void connectTo(const QString &portName, qint32 baud = 1000000,
                   seriallink::EchoMode echo = seriallink::EchoMode::Auto);
    void disconnectFrom();

    // Forgets the servos found before, then looks for servos as `options` say. False and
    // *refusal, nothing changed, while the bus is shared (a scan changes the port's rate).
    bool scan(const ScanOptions &options, Refusal *refusal = nullptr);
    void cancelScan();

    // The servos found, each with its parameter model, in the order the tree shows them.
    ServoList *servos() const { return m_servos; }

    // Why changes cannot be made to servo `index` now (none when they can).
    Refusal writeBlocker(int index) const;

    OperationReply *readServo(int index);
    // Present values and other RAM registers, in the background; skipped while busy or while
    // the bus is shared with another program.
    void refreshRam(int index);
    // Writes the servo's edits (except ID and baud rate: see changeId / changeBaud) and reads
    // them back. Nullptr and *refusal when nothing was sent.
    OperationReply *apply(int index, Refusal *refusal = nullptr);
    // Everything pending: the register edits, then an ID edit through changeId, then a baud
    // edit through changeBaud, each only once the one before has succeeded.
    OperationReply *applyAll(int index, Refusal *refusal = nullptr);
    OperationReply *changeId(int index, int newId, Refusal *refusal = nullptr);
    OperationReply *changeBaud(int index, qint32 newBaud, Refusal *refusal = nullptr);

    // ---- live monitoring and control

    // Telemetry: one stream of what every subscriber asks for, and the newest samples.
    TelemetryHub *telemetry() const { return m_telemetry; }

    // Control writes: register values by key, in register units, written and read back (EEPROM
    // ones unlocked and locked again). Unlike apply() they do not wait for an idle bus and
    // leave the servo's pending edits alone; the model shows what the read-back says.
    // Nullptr and *refusal (BadValue, naming the register) when a value is unknown or out of
    // range.
    OperationReply *writeValues(int index, const QVector<model::WriteItem> &values,
                                Refusal *refusal = nullptr);
    // Torque enable 0 on every servo of the bus: a broadcast WRITE at each baud rate the scan
    // found servos at, ahead of anything queued (a running scan is cancelled), then a read-back
    // from each servo found. Emits allTorqueOffRequested at once.
    OperationReply *allTorqueOff();
    struct Goal
    {
        int index = 0;
        qint32 position = 0; // register units (steps)
    };
    // One SYNC WRITE of goal positions per baud rate, a reply each; none and *refusal when a
    // position is out of its servo's range or a servo is unknown (nothing sent).
    QVector<OperationReply *> moveAll(const QVector<Goal> &goals, Refusal *refusal = nullptr);

    // ---- the services' access: the session, and submitting operations to it

    // The session in its worker thread: connect to its signals (queued), never call it.
    Session *session() const { return m_worker.session(); }
    // Runs `work` in the session's thread, ahead of nothing: settings and cancels.
    void runInSession(const std::function<void(Session &)> &work) { m_worker.run(work); }
    enum class Work {
        Foreground, // the bus is busy until it ends
        Background, // a refresh: skipped when busy, no reply, its failure not reported
        Control, // a control write: reported, but it does not make the bus busy
        Emergency // All torque off: ahead of everything, it does not make the bus busy
    };
    // The operation `make` gives for servo `index` (as it is now), submitted.
    OperationReply *startOperation(Operation operation, int index, Refusal *refusal, Work kind,
                                   const std::function<BusOperation(const ServoInfo &)> &make);
    // Queues `operation` (busoperations.h) in the session under a new ticket, as work on the
    // servo at `id` and `baud`; its reply (none for a background one).
    OperationReply *submit(const BusOperation &operation, quint8 id, qint32 baud, Work kind);

    // The overload and thermal guard, on from the start.
    BusGuard *guard() const { return m_guard; }

    // Middle calibration, factory reset, reboot, clear status, lock EEPROM, frames by hand.
    ServoCommands *commands() const { return m_commands; }
    // Motor set-up: find the one servo on the bus, set it up, check a robot's joints.
    MotorSetupService *motorSetup() const { return m_motorSetup; }
    // The health check and its confirmed move test.
    HealthService *health() const { return m_health; }
    // The settings check and its fixes.
    SettingsCheckService *settingsCheck() const { return m_settingsCheck; }
    // Identifying a joint, and the servos held by what moves them meanwhile.
    IdentifyService *identify() const { return m_identify; }
    // The bus shared with another program.
    ShareService *share() const { return m_share; }

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void scanProgress(int done, int total, qint32 baud);
    void scanFinished(bool completed, const QString &message);
    // A reply was made for an operation just submitted (not for background refreshes).
    void submitted(feetech::OperationReply *reply);
    void busyChanged(bool busy);
    // Whatever moves servos (sweeps, step tests) stops on this.
    void allTorqueOffRequested();

private:
    void onMemoryRead(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                      ReadSource source, quint8 statusByte);
    void onOperationFinished(const OperationResult &result);
    void forgetWork(); // the link went down: nothing is running any more
    // The pending edits as planApply plans them; with `withAddress` the ID and baud too.
    OperationReply *startApply(int index, Refusal *refusal, bool withAddress);

    seriallink::SessionThread<Session> m_worker;
    seriallink::LinkMirror m_link;
    ServoList *m_servos = nullptr;
    std::unique_ptr<BusClientPrivate> d; // the operations on their way, the scan, the clock
    BusGuard *m_guard = nullptr;
    TelemetryHub *m_telemetry = nullptr;
    ServoCommands *m_commands = nullptr;
    MotorSetupService *m_motorSetup = nullptr;
    HealthService *m_health = nullptr;
    SettingsCheckService *m_settingsCheck = nullptr;
    IdentifyService *m_identify = nullptr;
    ShareService *m_share = nullptr;
};

// The goal positions servo `index` accepts (goalrange.h); nothing for an unknown servo or a
// table without goal_position.
std::optional<PositionRange> goalRange(const BusClient &client, int index);

} // namespace feetech
