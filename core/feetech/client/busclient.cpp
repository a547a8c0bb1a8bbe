// Feetech bus client: the link, the servos found and their models, and the operations on them,
// submitted to the session in its worker thread.
#include "busclient.h"

#include "busclient_p.h"

#include "busoperations.h"
#include "linksession.h"
#include "modeltable.h"
#include "registerkeys.h"
#include "registertable.h"
#include "servoparameters.h"

#include <QHash>

#include <algorithm>

namespace feetech {

BusClient::BusClient(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
    , m_worker(QStringLiteral("feetech-link"), timing)
    , m_servos(new ServoList(this))
    , d(std::make_unique<BusClientPrivate>())
{
    d->clock.start();
    Session *session = m_worker.session();
    // First, so the client has settled before the main window hears of a change.
    connect(&m_link, &seriallink::LinkMirror::statusChanged, this, [this](const auto &status) {
        if (status.state == seriallink::ConnectionState::Disconnected
            || status.state == seriallink::ConnectionState::Lost)
            forgetWork(); // a backstop: the session reports what it dropped
        emit statusChanged(status);
    });
    m_link.follow(&session->link());
    connect(session, &Session::scanProgress, this, &BusClient::scanProgress);
    connect(session, &Session::servoFound, m_servos, &ServoList::add);
    connect(session, &Session::scanFinished, this, [this](bool completed, const QString &m) {
        d->scanning = false;
        emit busyChanged(isBusy());
        emit scanFinished(completed, m);
    });
    connect(session, &Session::memoryRead, this, &BusClient::onMemoryRead);
    connect(session, &Session::statusSeen, this, [this](quint8 id, qint32 baud, quint8 status) {
        const int index = m_servos->indexOf({id, baud});
        if (index < 0)
            return;
        m_servos->entry(index).statusByte = status;
        m_servos->noteUpdated(index);
    });
    connect(session, &Session::operationProgress, this, [this](const OperationProgress &progress) {
        const auto pending = d->pending.find(progress.ticket);
        if (pending != d->pending.end() && pending->second.reply)
            pending->second.reply->reportProgress(progress);
    });
    connect(session, &Session::operationFinished, this, &BusClient::onOperationFinished);
    m_guard = new BusGuard(this);
    m_telemetry = new TelemetryHub(this);
    m_commands = new ServoCommands(this);
    m_motorSetup = new MotorSetupService(this);
    m_health = new HealthService(this);
    m_settingsCheck = new SettingsCheckService(this);
    m_identify = new IdentifyService(this);
    m_share = new ShareService(this);
}

BusClient::~BusClient() = default;

bool BusClient::isScanning() const
{
    return d->scanning;
}

bool BusClient::isBusy() const
{
    return d->scanning || std::any_of(d->pending.begin(), d->pending.end(), [](const auto &entry) {
               return entry.second.kind == Work::Foreground && !entry.second.dropped;
           });
}

void BusClient::connectTo(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    m_servos->clear();
    m_worker.run([portName, baud, echo](Session &s) { s.open(portName, baud, echo); });
}

void BusClient::disconnectFrom()
{
    m_worker.run([](Session &s) { s.close(); });
}

bool BusClient::scan(const ScanOptions &options, Refusal *refusal)
{
    if (refused(m_share->isActive() ? Refusal(Refusal::Code::BusShared) : Refusal(), refusal))
        return false;
    if (d->scanning)
        return true;
    m_servos->clear();
    d->scanning = true;
    emit busyChanged(true);
    m_worker.run([options](Session &s) { s.submit(operations::scan(options)); });
    return true;
}

void BusClient::cancelScan()
{
    // Not queued behind the scan: the flag must be seen while it runs.
    Session *session = m_worker.session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancel(Operation::Scan); }, Qt::QueuedConnection);
}

Refusal BusClient::writeBlocker(int index) const
{
    if (!m_link.isConnected())
        return Refusal(Refusal::Code::NotConnected);
    if (index < 0 || index >= m_servos->count())
        return Refusal(Refusal::Code::NoServo);
    // What stays true first: a shared ID or an unknown model is no reason to wait.
    if (m_servos->at(index).info.sharedId)
        return Refusal::sharedId(m_servos->at(index).info.id);
    if (!m_servos->at(index).info.hasTable())
        return Refusal(Refusal::Code::UnknownModel);
    if (isBusy())
        return Refusal(Refusal::Code::Busy);
    return {};
}

void BusClient::onMemoryRead(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                             ReadSource source, quint8 statusByte)
{
    const int index = m_servos->indexOf({id, baud});
    if (index < 0)
        return;
    Servo &entry = m_servos->entry(index);
    entry.statusByte = statusByte;
    const qint64 now = d->clock.elapsed() + 1; // 0 means "never read"
    for (const DecodedRegister &item : decodeRegisters(entry.info.table(), address, bytes)) {
        // A background refresh may have been read before the write went out: only the
        // read-back settles what is being written.
        if (source == ReadSource::Refresh
            && entry.parameters->state(item.reg->key) == model::State::Writing)
            continue;
        entry.parameters->setDeviceValue(item.reg->key, item.value, now);
    }
    m_servos->noteUpdated(index);
}

void BusClient::onOperationFinished(const OperationResult &result)
{
    if (result.operation == Operation::Scan)
        return; // a scan ends through scanFinished
    if (result.operation == Operation::Guard)
        return; // the guard's own: reported as a guardEvent
    const auto pending = d->pending.find(result.ticket);
    if (pending == d->pending.end())
        return; // not one of ours
    const BusClientPrivate::Pending target = pending->second;
    // A step of an apply chain: the operation goes on, with the servo where it left it.
    if (result.final) {
        d->pending.erase(pending);
    } else {
        pending->second.id = result.servo.id;
        pending->second.baud = result.servo.baud;
    }
    const int index = m_servos->indexOf({target.id, target.baud});
    if (index >= 0) {
        Servo &entry = m_servos->entry(index);
        model::ParameterModel &parameters = *entry.parameters;
        if (result.operation == Operation::Read && result.ok && target.kind != Work::Background)
            entry.read = true;
        // A control write never marks anything Writing: its failure leaves an apply alone.
        if (result.operation == Operation::Write && !result.ok && target.kind != Work::Control) {
            // What was on its way and never came back verified keeps its edit: Unknown when it
            // went out (it may have landed), Failed when it never did.
            for (const model::Definition &definition : parameters.definitions()) {
                if (parameters.state(definition.key) != model::State::Writing)
                    continue;
                if (result.writesSent)
                    parameters.markUnknown(definition.key);
                else
                    parameters.markFailed(definition.key);
            }
        }
        const bool moved = result.servo.id != entry.info.id || result.servo.baud != entry.info.baud;
        if (result.ok && moved
            && (result.operation == Operation::ChangeId || result.operation == Operation::ChangeBaud
                || result.operation == Operation::FactoryReset)) {
            m_servos->move(index, result.servo);
        }
        if (result.ok && result.operation == Operation::ChangeId)
            parameters.revert(QStringLiteral("id"));
        if (result.ok && result.operation == Operation::ChangeBaud)
            parameters.revert(QStringLiteral("baud_rate"));
        const bool flow = result.operation == Operation::ChangeId
            || result.operation == Operation::ChangeBaud
            || result.operation == Operation::FactoryReset
            || result.operation == Operation::CalibrateMiddle;
        if (result.ok && result.operation == Operation::FactoryReset)
            parameters.revertAll(); // the flow changed the servo under every edit
        if (result.ok && result.operation == Operation::CalibrateMiddle) {
            parameters.revert(QStringLiteral("position_offset"));
            parameters.revert(QStringLiteral("torque_enable"));
        }
        if (result.ok && flow && result.final) // what the flow changed shows
            readServo(m_servos->indexOf(entry.info.address()));
    }
    if (target.kind == Work::Foreground && !target.dropped)
        emit busyChanged(isBusy());
    // A failed refresh has no reply: the next one retries it.
    if (target.reply) {
        target.reply->finishStep(result);
        if (result.final)
            target.reply->deleteLater();
    }
}

void BusClient::forgetWork()
{
    const bool wasBusy = isBusy();
    // Their replies finish when the session reports what it dropped.
    for (auto &entry : d->pending)
        entry.second.dropped = true;
    d->scanning = false;
    // The link went down with writes on their way: whether they landed is not known.
    for (int i = 0; i < m_servos->count(); ++i) {
        model::ParameterModel &parameters = *m_servos->at(i).parameters;
        for (const model::Definition &definition : parameters.definitions()) {
            if (parameters.state(definition.key) == model::State::Writing)
                parameters.markUnknown(definition.key);
        }
    }
    if (wasBusy)
        emit busyChanged(false);
}

OperationReply *BusClient::applyAll(int index, Refusal *refusal)
{
    return startApply(index, refusal, true);
}

OperationReply *BusClient::apply(int index, Refusal *refusal)
{
    return startApply(index, refusal, false);
}

OperationReply *BusClient::startApply(int index, Refusal *refusal, bool withAddress)
{
    if (refused(writeBlocker(index), refusal))
        return nullptr;
    model::ParameterModel &parameters = *m_servos->parameters(index);
    ApplyRefusal why;
    // Without the address, the ID and baud rate edits stay pending for their own flows.
    const auto plan = planApply(m_servos->at(index).info, parameters, m_servos->idsInUse(),
                                withAddress ? ApplyScope::Everything : ApplyScope::Registers, &why);
    if (!plan) {
        switch (why.code()) {
        case ApplyRefusal::Code::None: // planApply says why whenever it makes no plan
        case ApplyRefusal::Code::NothingToWrite:
            refused(Refusal(Refusal::Code::NothingToWrite), refusal);
            break;
        case ApplyRefusal::Code::IdInUse:
            refused(Refusal::idInUse(why.newId()), refusal);
            break;
        case ApplyRefusal::Code::BadValue:
            refused(Refusal::badValue(why.detail()), refusal);
            break;
        }
        return nullptr;
    }
    // Exactly the planned registers are Writing; an ID or baud edit stays an edit until its
    // flow has moved the servo.
    parameters.takeWritePlan({QStringLiteral("id"), QStringLiteral("baud_rate")});
    return startOperation(
        Operation::Write, index, refusal, Work::Foreground,
        [plan = *plan](const ServoInfo &info) { return operations::apply(info, plan); });
}

OperationReply *
BusClient::startOperation(Operation operation, int index, Refusal *refusal, Work kind,
                          const std::function<BusOperation(const ServoInfo &)> &make)
{
    if (index < 0 || index >= m_servos->count()) {
        refused(Refusal(Refusal::Code::NoServo), refusal);
        return nullptr;
    }
    if (!m_link.isConnected()) {
        refused(Refusal(Refusal::Code::NotConnected), refusal);
        return nullptr;
    }
    const ServoInfo info = m_servos->at(index).info;
    const BusOperation made = make(info);
    Q_ASSERT(made.kind == operation);
    return submit(made, info.id, info.baud, kind);
}

OperationReply *BusClient::submit(const BusOperation &operation, quint8 id, qint32 baud, Work kind)
{
    const quint64 ticket = ++d->lastTicket;
    const bool wasBusy = isBusy();
    OperationReply *reply = kind == Work::Background
        ? nullptr
        : new OperationReply(operation.kind, id, baud, kind == Work::Control, this);
    d->pending[ticket] = {id, baud, kind, reply, false};
    if (kind == Work::Foreground && !wasBusy)
        emit busyChanged(true);
    if (reply)
        emit submitted(reply);
    BusOperation submitted = operation;
    submitted.ticket = ticket;
    m_worker.run([submitted](Session &s) { s.submit(submitted); });
    return reply;
}

OperationReply *BusClient::readServo(int index)
{
    return startOperation(
        Operation::Read, index, nullptr, Work::Foreground,
        [](const ServoInfo &info) { return operations::read(info, {}, ReadSource::Read); });
}

void BusClient::refreshRam(int index)
{
    if (isBusy() || d->hasLivePending() || index < 0 || index >= m_servos->count())
        return; // the next refresh will come; real work goes first
    if (m_share->isActive())
        return; // a shared bus carries the other program's reads, not ours
    const ServoInfo &info = m_servos->at(index).info;
    if (!info.hasTable())
        return;
    const QVector<Block> ram = info.table().ramBlocks();
    startOperation(Operation::Read, index, nullptr, Work::Background,
                   [ram](const ServoInfo &target) {
                       return operations::read(target, ram, ReadSource::Refresh);
                   });
}

OperationReply *BusClient::changeId(int index, int newId, Refusal *refusal)
{
    if (refused(writeBlocker(index), refusal))
        return nullptr;
    const QVector<int> inUse = m_servos->idsInUse();
    if (inUse.contains(newId) && newId != m_servos->at(index).info.id) {
        refused(Refusal::idInUse(newId), refusal);
        return nullptr;
    }
    return startOperation(
        Operation::ChangeId, index, refusal, Work::Foreground,
        [newId, inUse](const ServoInfo &info) { return operations::changeId(info, newId, inUse); });
}

OperationReply *BusClient::changeBaud(int index, qint32 newBaud, Refusal *refusal)
{
    if (refused(writeBlocker(index), refusal))
        return nullptr;
    if (refused(m_share->isActive() ? Refusal(Refusal::Code::BusShared) : Refusal(), refusal))
        return nullptr;
    return startOperation(
        Operation::ChangeBaud, index, refusal, Work::Foreground,
        [newBaud](const ServoInfo &info) { return operations::changeBaud(info, newBaud); });
}

// ---- live monitoring and control

OperationReply *BusClient::writeValues(int index, const QVector<model::WriteItem> &values,
                                       Refusal *refusal)
{
    if (!m_link.isConnected() || index < 0 || index >= m_servos->count()
        || !m_servos->at(index).info.hasTable() || m_servos->at(index).info.sharedId) {
        // The same reasons as for any write, except a busy bus: control writes queue up.
        const Refusal blocker = writeBlocker(index);
        refused(blocker ? blocker : Refusal(Refusal::Code::NoServo), refusal);
        return nullptr;
    }
    if (values.isEmpty()) {
        refused(Refusal(Refusal::Code::NothingToWrite), refusal);
        return nullptr;
    }
    QString why;
    const auto writes = encodeWrites(m_servos->at(index).info.table(), values, &why);
    if (!writes) {
        refused(Refusal::badValue(why), refusal);
        return nullptr;
    }
    const QVector<RegisterWrite> items = *writes;
    return startOperation(
        Operation::Write, index, refusal, Work::Control,
        [items](const ServoInfo &info) { return operations::write(info, items); });
}

OperationReply *BusClient::allTorqueOff()
{
    emit allTorqueOffRequested();
    QVector<qint32> bauds;
    QVector<ServoInfo> servos;
    for (int i = 0; i < m_servos->count(); ++i) {
        if (!bauds.contains(m_servos->at(i).info.baud))
            bauds.append(m_servos->at(i).info.baud);
        servos.append(m_servos->at(i).info);
    }
    if (bauds.isEmpty() && m_link.status().baud > 0)
        bauds.append(m_link.status().baud); // nothing scanned yet: the rate the port is at
    // A shared bus stays at the rate the other program set: torque off goes at that one only.
    if (m_share->state() == ShareService::State::Sharing && m_share->portBaud() > 0)
        bauds = {m_share->portBaud()};
    return submit(operations::torqueOffAll(bauds, servos), 0, 0, Work::Emergency);
}

QVector<OperationReply *> BusClient::moveAll(const QVector<Goal> &goals, Refusal *refusal)
{
    const auto refuse = [refusal](const Refusal &why) {
        refused(why, refusal);
        return QVector<OperationReply *>();
    };
    if (!m_link.isConnected())
        return refuse(Refusal(Refusal::Code::NotConnected));
    if (goals.isEmpty())
        return refuse(Refusal(Refusal::Code::NothingToMove));
    // One SYNC WRITE per baud rate, servos in the order given.
    QVector<qint32> bauds;
    QHash<qint32, QVector<SyncWriteEntry>> entries;
    for (const Goal &goal : goals) {
        if (goal.index < 0 || goal.index >= m_servos->count())
            return refuse(Refusal(Refusal::Code::NoServo));
        const ServoInfo &info = m_servos->at(goal.index).info;
        if (!info.hasTable())
            return refuse(Refusal::unknownModel(info.id));
        QString why;
        const auto encoded =
            encodeWrites(info.table(), {{QStringLiteral("goal_position"), goal.position}}, &why);
        if (!encoded || encoded->size() != 1)
            return refuse(Refusal::badValue(info.id, why));
        if (!bauds.contains(info.baud))
            bauds.append(info.baud);
        entries[info.baud].append({info.id, encoded->first().bytes});
    }
    const Register *goal =
        m_servos->at(goals.first().index).info.table().find(QStringLiteral("goal_position"));
    const int address = goal ? goal->address : 42;
    QVector<OperationReply *> replies;
    for (const qint32 baud : std::as_const(bauds)) {
        const QVector<SyncWriteEntry> group = entries.value(baud);
        replies.append(
            submit(operations::syncWrite(baud, address, int(group.first().data.size()), group), 0,
                   baud, Work::Control));
    }
    return replies;
}

std::optional<PositionRange> goalRange(const BusClient &client, int index)
{
    if (index < 0 || index >= client.servos()->count()
        || !client.servos()->at(index).info.hasTable())
        return std::nullopt;
    const model::ParameterModel *parameters = client.servos()->parameters(index);
    return goalRange(client.servos()->at(index).info.table(),
                     parameters->deviceValue(registerkeys::kMinAngleLimit),
                     parameters->deviceValue(registerkeys::kMaxAngleLimit));
}

} // namespace feetech
