// Feetech bus session: the link, the operation queue, the turns operations and telemetry take,
// and All torque off ahead of everything.
#include "feetechsession.h"

#include "feetechsession_p.h"

#include "feetechdescription.h"
#include "feetechsessiontr.h"
#include "linksession.h"
#include "porttransport.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QTimer>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

using Queued = SessionPrivate::Queued;

// Where a READ's address and a status frame's data begin: after header, ID, length and the
// instruction or error byte.
constexpr int kShareDataFrom = 5;

// Where a paused or continued operation goes back in: behind any All torque off.
std::deque<Queued>::iterator afterTorqueOff(std::deque<Queued> &queue)
{
    auto at = queue.begin();
    while (at != queue.end() && at->operation.kind == Operation::TorqueOff)
        ++at;
    return at;
}

// A continuation of the running operation `current`: its ticket and torque-off count, and kind
// `kind` (an apply chain goes on as its ID or baud change).
Queued continuation(const Queued &current, Operation kind, std::function<void()> resume)
{
    Queued next = current;
    next.operation.kind = kind;
    next.operation.priority = BusOperation::Priority::Normal;
    next.operation.powersServos = false; // checked once, when it first started
    next.operation.submitted = nullptr;
    next.operation.start = [resume = std::move(resume)](OperationContext &) {
        resume();
    };
    return next;
}

} // namespace

Session::Session(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
    , d(std::make_unique<SessionPrivate>())
    , m_context(*this)
{
    d->timing = timing;
    d->link = new seriallink::LinkSession(d->format, describeFrame, this);
    d->bus = new BusExchange(*d->link, d->timing, this);
    d->scan = new BusScan(*d->bus, this);
    d->flows = new GuidedFlows(*d->bus, this);
    d->telemetry = new TelemetryCycle(*d->bus, this);
    d->apply = new ApplyFlow(*d->bus, *d->flows, this);
    d->motorSetup = new MotorSetup(*d->bus, *d->flows, *d->apply, this);
    d->identify = new JointIdentify(*d->bus, this);
    d->replay = new MotionReplay(*d->bus, this);
    d->health = new HealthCheck(*d->bus, this);
    d->moveTest = new HealthMoveTest(*d->bus, this);
    d->guard = new GuardKeeper(*d->bus, this);
    d->share = new share::BusShare(*d->link, this);
    qRegisterMetaType<feetech::ApplyPlan>();
    qRegisterMetaType<feetech::HealthReading>();
    qRegisterMetaType<feetech::MoveTestResult>();
    qRegisterMetaType<feetech::ReplayPosition>();
    qRegisterMetaType<feetech::ServoInfo>();
    qRegisterMetaType<feetech::ScanOptions>();
    qRegisterMetaType<feetech::ReadSource>();
    qRegisterMetaType<feetech::OperationResult>();
    qRegisterMetaType<feetech::OperationProgress>();
    qRegisterMetaType<feetech::MotorTarget>();
    qRegisterMetaType<feetech::MotorSetupResult>();
    qRegisterMetaType<QVector<feetech::JointCheck>>();
    d->link->engine().setTiming(d->timing.engine);
    d->link->setReconnectInterval(d->timing.reconnectInterval);
    d->link->setLinkDownHook(
        [this](const QString &message, seriallink::Failure) { onLinkDown(message); });
    d->link->setReconnectedHook([this] {
        d->link->setState(
            seriallink::ConnectionState::Connected,
            FeetechSessionTr::tr("%1 is back. Scan again if servos were changed while it was away.")
                .arg(d->link->status().portName));
    });
    connect(d->link, &seriallink::LinkSession::statusChanged, this, &Session::statusChanged);
    connect(d->link, &seriallink::LinkSession::packetLogged, this, &Session::packetLogged);
    connect(d->link, &seriallink::LinkSession::countersChanged, this, &Session::countersChanged);
    connect(d->bus, &BusExchange::memoryRead, this, &Session::memoryRead);
    connect(d->scan, &BusScan::progress, this, &Session::scanProgress);
    connect(d->scan, &BusScan::servoFound, this, &Session::servoFound);
    connect(d->scan, &BusScan::finished, this, &Session::onScanFinished);
    connect(d->telemetry, &TelemetryCycle::telemetry, this, &Session::telemetry);
    // An apply's writes; the motor set-up that applies settings reports its own steps.
    connect(d->apply, &ApplyFlow::progress, this, [this](int done, int total) {
        if (d->current.operation.kind == Operation::Write)
            emit operationProgress({d->current.operation.ticket, done, total, {}, {}});
    });
    connect(d->telemetry, &TelemetryCycle::statsChanged, this, &Session::telemetryStats);
    connect(d->motorSetup, &MotorSetup::progress, this,
            [this](int step, int steps, const QString &text) {
                emit operationProgress({d->current.operation.ticket, step, steps, text, {}});
            });
    connect(d->scan, &BusScan::servoFound, d->guard, &GuardKeeper::noteServo);
    connect(
        d->telemetry, &TelemetryCycle::telemetry, d->guard,
        [this](const QVector<FeedbackSample> &samples, quint64) { d->guard->observe(samples); });
    connect(d->guard, &GuardKeeper::guardEvent, this, &Session::guardEvent);
    d->guard->setRunUrgent([this](std::function<void(std::function<void()>)> work) {
        runGuardAction(std::move(work));
    });
    d->guard->setActed([this](const ServoInfo &servo) {
        // An identify would go on wiggling the servo the guard just stopped: it ends and
        // puts back what it changed. A move test ends and leaves it as the guard did.
        if (d->identifying)
            d->identify->cancel();
        // A replay would drive it again with its next goal: it stops, holding where it stands.
        d->replay->cancel();
        d->moveTest->stopForGuard(servo.id, servo.baud);
    });
    // While the bus is shared neither adds traffic: the program's own reads are the telemetry.
    d->telemetry->setBusBusy(
        [this] { return d->running || d->guard->cycle().inCycle() || d->share->isSharing(); });
    d->telemetry->setCycleEnded([this] { onCycleEnded(); });
    d->guard->cycle().setBusBusy(
        [this] { return d->running || d->telemetry->inCycle() || d->share->isSharing(); });
    d->guard->cycle().setCycleEnded([this] { onCycleEnded(); });
    connectShare();
}

void Session::connectShare()
{
    // The other program's frames go into the packet log; ServoBench's own requests through the
    // share are logged by the engine as always.
    connect(d->share, &share::BusShare::framePassed, this,
            [this](const share::RecordedFrame &frame) {
                if (frame.direction != share::FrameDirection::FromProgram
                    && frame.direction != share::FrameDirection::ToProgram)
                    return;
                d->link->logEntry(d->shareLog.entry(frame, QDateTime::currentMSecsSinceEpoch()));
            });
    // What the program reads of a servo's memory is what the servo holds: the parameter models
    // show it as a background refresh would, with no read of ours.
    connect(d->share, &share::BusShare::transactionEnded, this,
            [this](const share::SharedTransaction &transaction) {
                const quint8 code = transaction.instruction();
                if (transaction.own
                    || (code != quint8(Instruction::Read) && code != quint8(Instruction::SyncRead))
                    || transaction.request.size() <= kShareDataFrom)
                    return;
                const int address = quint8(transaction.request.at(kShareDataFrom));
                const qint32 baud = d->link->transport().baudRate();
                for (const QByteArray &reply : transaction.replies) {
                    if (reply.size() <= kShareDataFrom + 1)
                        continue;
                    emit memoryRead(quint8(reply.at(2)), baud, address,
                                    reply.mid(kShareDataFrom, reply.size() - kShareDataFrom - 1),
                                    ReadSource::Refresh, quint8(reply.at(4)));
                }
            });
    connect(d->share, &share::BusShare::alertRaised, this, [this](const share::ShareAlert &alert) {
        d->link->logNote(
            FeetechSessionTr::tr("Shared bus alert at ID %1: %2").arg(alert.id).arg(alert.message),
            true);
    });
    connect(d->share, &share::BusShare::noted, this, [this](const QString &text) {
        d->link->logNote(FeetechSessionTr::tr("Shared bus: %1").arg(text));
    });
    connect(d->share, &share::BusShare::sharingChanged, this, [this](bool sharing) {
        if (sharing) {
            d->shareLog = {};
            return;
        }
        // The bus is ServoBench's again: the streams and the guard's reads go on.
        QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        QMetaObject::invokeMethod(
            this,
            [this] {
                if (!d->running && !inCycle())
                    startCycleIfDue();
            },
            Qt::QueuedConnection);
    });
}

Session::~Session()
{
    close();
    // The parts go while the state they report into is still there, the last made first.
    delete d->share;
    delete d->guard;
    delete d->moveTest;
    delete d->health;
    delete d->replay;
    delete d->identify;
    delete d->motorSetup;
    delete d->apply;
    delete d->telemetry;
    delete d->flows;
    delete d->scan;
    delete d->bus;
    delete d->link;
}

seriallink::LinkSession &Session::link()
{
    return *d->link;
}

share::BusShare &Session::share()
{
    return *d->share;
}

bool Session::changesPortRate(Operation kind)
{
    switch (kind) {
    case Operation::Scan:
    case Operation::ChangeBaud:
    case Operation::FindMotor:
    case Operation::SetUpMotor:
    case Operation::FactoryReset:
        return true;
    default:
        return false;
    }
}

bool Session::isBusy() const
{
    return d->running || d->paused || !d->queue.empty();
}

const GuardSettings &Session::guardSettings() const
{
    return d->guard->settings();
}

const seriallink::ConnectionStatus &Session::status() const
{
    return d->link->status();
}

const seriallink::LinkCounters &Session::counters() const
{
    return d->link->counters();
}

std::optional<std::chrono::microseconds> Session::measuredLatency() const
{
    return d->bus->measuredLatency();
}

std::chrono::microseconds Session::scanAllowance() const
{
    return d->bus->scanAllowance();
}

bool Session::isStreaming() const
{
    return d->telemetry->isStreaming();
}

void Session::open(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    d->share->stop(); // shared at the port being left: the other program's port goes with it
    d->bus->forgetLatencies();
    if (d->link->open(portName, baud, echo))
        d->link->setState(seriallink::ConnectionState::Connected);
}

void Session::close()
{
    d->share->stop(); // the other program's port goes with the bus
    d->link->close();
}

void Session::onLinkDown(const QString &message)
{
    const bool wasScanning = d->scan->isRunning();
    const bool wasRunning = d->running;
    const BusOperation running = d->current.operation;
    // All torque off may have run during the pause: the paused operation ends too.
    const bool wasPaused = d->paused;
    const BusOperation paused = d->pausedOperation.operation;
    d->paused = false;
    d->identifying = false;
    ++d->pauseGeneration;
    std::deque<Queued> dropped;
    dropped.swap(d->queue);
    d->scan->abandon();
    stopTelemetry();
    d->guard->noteLinkDown();
    d->running = false;
    // Whoever waits for an operation hears that it ended, queued ones included, so nothing
    // stays busy.
    const auto failed = [&message](const BusOperation &operation) {
        OperationResult result {operation.kind, false, message, {}, {}};
        result.ticket = operation.ticket;
        result.failure = OperationFailure::LinkLost;
        return result;
    };
    if (wasScanning)
        emit scanFinished(false, message);
    else if (wasRunning && running.kind != Operation::Guard)
        emit operationFinished(failed(running));
    if (wasPaused)
        emit operationFinished(failed(paused));
    for (const Queued &queued : dropped) {
        if (queued.operation.kind == Operation::Scan)
            emit scanFinished(false, message);
        else if (queued.operation.kind != Operation::Guard)
            emit operationFinished(failed(queued.operation));
    }
}

// ---- operation queue

void Session::submit(const BusOperation &operation)
{
    if (operation.priority == BusOperation::Priority::Emergency) {
        d->scan->cancel(); // nothing may hold torque off back for seconds
        ++d->torqueOffEpoch; // what was asked for before must not power the servos again
        d->guard->noteAllTorqueOff();
    }
    if (operation.submitted)
        operation.submitted(m_context);
    Queued queued {operation, d->torqueOffEpoch};
    if (operation.priority == BusOperation::Priority::Emergency)
        d->queue.push_front(std::move(queued)); // ahead of everything waiting
    else
        d->queue.push_back(std::move(queued));
    if (!d->running)
        startNextOperation();
}

void Session::cancel(Operation kind)
{
    switch (kind) {
    case Operation::Scan:
        d->scan->cancel();
        break;
    case Operation::Identify:
        d->identify->cancel();
        break;
    case Operation::FindMotor:
    case Operation::SetUpMotor:
    case Operation::CheckJoints:
        d->motorSetup->cancel();
        break;
    case Operation::HealthCheck:
        d->health->cancel();
        break;
    case Operation::Replay:
        d->replay->cancel();
        break;
    default:
        break; // the others are short: they run to their end
    }
}

void Session::startNextOperation()
{
    if (d->running)
        return;
    // Telemetry and operations take turns: a running cycle ends first, and a cycle that is
    // due goes before the next operation, unless that is the torque-off emergency.
    if (inCycle())
        return;
    const bool emergency = !d->queue.empty()
        && (d->queue.front().operation.kind == Operation::TorqueOff
            || d->queue.front().operation.kind == Operation::Guard);
    if (!emergency && startCycleIfDue())
        return;
    startQueuedOperation();
}

bool Session::inCycle() const
{
    return d->telemetry->inCycle() || d->guard->cycle().inCycle();
}

bool Session::startCycleIfDue()
{
    return d->telemetry->startIfDue() || d->guard->cycle().startIfDue();
}

void Session::onCycleEnded()
{
    if (!d->queue.empty() && !d->running)
        startQueuedOperation();
    if (!d->running && !inCycle())
        startCycleIfDue();
}

void Session::startQueuedOperation()
{
    if (d->running || d->queue.empty())
        return;
    if (d->paused && d->queue.front().operation.kind != Operation::TorqueOff
        && d->queue.front().operation.kind != Operation::Guard)
        return; // the paused operation goes on first
    d->current = std::move(d->queue.front());
    d->queue.pop_front();
    d->running = true;
    const std::function<void(OperationContext &)> start = std::move(d->current.operation.start);
    d->current.operation.start = nullptr;
    const Operation kind = d->current.operation.kind;
    if (!d->link->isOpen()) {
        if (kind == Operation::Scan || kind == Operation::Guard) {
            d->running = false;
            if (kind == Operation::Scan)
                emit scanFinished(false, FeetechSessionTr::tr("Not connected."));
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        } else {
            OperationResult result {kind, false, FeetechSessionTr::tr("Not connected."), {}, {}};
            result.failure = OperationFailure::NotConnected;
            finishOperation(result);
        }
        return;
    }
    if (d->share->isSharing() && changesPortRate(kind)) {
        const QString why =
            FeetechSessionTr::tr("Not while the bus is shared with another program: this would "
                                 "change the port's rate under it. Stop sharing first.");
        if (kind == Operation::Scan) {
            onScanFinished(false, why);
            return;
        }
        OperationResult result {kind, false, why, {}, {}};
        result.failure = OperationFailure::BusShared;
        finishOperation(result);
        return;
    }
    if (d->current.operation.powersServos && d->current.epoch != d->torqueOffEpoch) {
        OperationResult result {
            kind,
            false,
            FeetechSessionTr::tr("Not sent: all torque off was asked for after this write."),
            {},
            {}};
        result.failure = OperationFailure::AfterTorqueOff;
        finishOperation(result);
        return;
    }
    if (kind == Operation::Identify)
        d->identifying = true;
    start(m_context);
}

void Session::finishOperation(const OperationResult &result)
{
    d->running = false;
    if (d->current.operation.kind == Operation::Identify)
        d->identifying = false;
    OperationResult reported = result;
    reported.ticket = d->current.operation.ticket;
    emit operationFinished(reported);
    // Queued, so a slot reacting to the result sees the session idle before the next starts.
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::continueLater(Operation next, std::function<void()> resume)
{
    // The running operation pauses here: it goes on as the next one, behind an emergency
    // stop asked for meanwhile (All torque off never waits for a whole apply chain).
    d->running = false;
    d->queue.insert(afterTorqueOff(d->queue), continuation(d->current, next, std::move(resume)));
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::pauseFor(std::chrono::milliseconds delay,
                       std::function<void(bool torqueOffMeanwhile)> resume)
{
    d->running = false;
    d->paused = true;
    const quint64 epoch = d->current.epoch;
    d->pausedOperation = continuation(d->current, d->current.operation.kind, [this, epoch, resume] {
        resume(epoch != d->torqueOffEpoch);
    });
    const quint64 generation = ++d->pauseGeneration;
    QTimer::singleShot(delay, this, [this, generation] {
        if (!d->paused || generation != d->pauseGeneration)
            return;
        d->paused = false;
        // Not continueLater: All torque off may be running right now, and goes on.
        d->queue.insert(afterTorqueOff(d->queue), d->pausedOperation);
        if (!d->running)
            startNextOperation();
    });
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::onScanFinished(bool completed, const QString &message)
{
    d->running = false;
    emit scanFinished(completed, message);
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::startTelemetry(const TelemetryOptions &options)
{
    d->telemetry->start(options);
    d->guard->noteStream(options);
}

void Session::stopTelemetry()
{
    d->telemetry->stop();
    d->guard->noteStream({});
}

void Session::setGuardSettings(const GuardSettings &settings)
{
    d->guard->setSettings(settings);
}

void Session::runGuardAction(std::function<void(std::function<void()> finished)> work)
{
    BusOperation action;
    action.kind = Operation::Guard;
    action.start = [this, work = std::move(work)](OperationContext &) {
        work([this] {
            d->running = false;
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        });
    };
    // Behind All torque off only: a servo pushing against a block must not wait for an apply.
    d->queue.insert(afterTorqueOff(d->queue), {action, d->torqueOffEpoch});
    if (!d->running)
        startNextOperation();
}

} // namespace feetech
