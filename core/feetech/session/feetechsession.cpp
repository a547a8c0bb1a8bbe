// Feetech bus session: the link, the operation queue, the turns operations and telemetry take,
// and All torque off ahead of everything.
#include "feetechsession.h"

#include "feetechdescription.h"
#include "linksession.h"

#include <QCoreApplication>
#include <QTimer>

#include <algorithm>
#include <memory>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

} // namespace

namespace feetech {

Session::Session(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
    , m_timing(timing)
    , m_link(new seriallink::LinkSession(m_format, describeFrame, this))
    , m_bus(new BusExchange(*m_link, m_timing, this))
    , m_scan(new BusScan(*m_bus, this))
    , m_flows(new GuidedFlows(*m_bus, this))
    , m_telemetry(new TelemetryCycle(*m_bus, this))
    , m_apply(new ApplyFlow(*m_bus, *m_flows, this))
    , m_motorSetup(new MotorSetup(*m_bus, *m_flows, *m_apply, this))
    , m_identify(new JointIdentify(*m_bus, this))
    , m_health(new HealthCheck(*m_bus, this))
    , m_moveTest(new HealthMoveTest(*m_bus, this))
    , m_guard(new GuardKeeper(*m_bus, this))
    , m_context(*this)
{
    qRegisterMetaType<feetech::ApplyPlan>();
    qRegisterMetaType<feetech::HealthReading>();
    qRegisterMetaType<feetech::MoveTestResult>();
    qRegisterMetaType<feetech::ServoInfo>();
    qRegisterMetaType<feetech::ScanOptions>();
    qRegisterMetaType<feetech::ReadSource>();
    qRegisterMetaType<feetech::OperationResult>();
    qRegisterMetaType<feetech::OperationProgress>();
    qRegisterMetaType<feetech::MotorTarget>();
    qRegisterMetaType<feetech::MotorSetupResult>();
    qRegisterMetaType<QVector<feetech::JointCheck>>();
    m_link->engine().setTiming(m_timing.engine);
    m_link->setReconnectInterval(m_timing.reconnectInterval);
    m_link->setLinkDownHook(
        [this](const QString &message, seriallink::Failure) { onLinkDown(message); });
    m_link->setReconnectedHook([this] {
        m_link->setState(seriallink::ConnectionState::Connected,
                         Tr::tr("%1 is back. Scan again if servos were changed while it was away.")
                             .arg(m_link->status().portName));
    });
    connect(m_link, &seriallink::LinkSession::statusChanged, this, &Session::statusChanged);
    connect(m_link, &seriallink::LinkSession::packetLogged, this, &Session::packetLogged);
    connect(m_link, &seriallink::LinkSession::countersChanged, this, &Session::countersChanged);
    connect(m_bus, &BusExchange::memoryRead, this, &Session::memoryRead);
    connect(m_scan, &BusScan::progress, this, &Session::scanProgress);
    connect(m_scan, &BusScan::servoFound, this, &Session::servoFound);
    connect(m_scan, &BusScan::finished, this, &Session::onScanFinished);
    connect(m_telemetry, &TelemetryCycle::telemetry, this, &Session::telemetry);
    // An apply's writes; the motor set-up that applies settings reports its own steps.
    connect(m_apply, &ApplyFlow::progress, this, [this](int done, int total) {
        if (m_current.operation.kind == Operation::Write)
            emit operationProgress({m_current.operation.ticket, done, total, {}, {}});
    });
    connect(m_telemetry, &TelemetryCycle::statsChanged, this, &Session::telemetryStats);
    connect(m_motorSetup, &MotorSetup::progress, this,
            [this](int step, int steps, const QString &text) {
                emit operationProgress({m_current.operation.ticket, step, steps, text, {}});
            });
    connect(m_scan, &BusScan::servoFound, m_guard, &GuardKeeper::noteServo);
    connect(m_telemetry, &TelemetryCycle::telemetry, m_guard,
            [this](const QVector<FeedbackSample> &samples, quint64) { m_guard->observe(samples); });
    connect(m_guard, &GuardKeeper::guardEvent, this, &Session::guardEvent);
    m_guard->setRunUrgent([this](std::function<void(std::function<void()>)> work) {
        runGuardAction(std::move(work));
    });
    m_guard->setActed([this](const ServoInfo &servo) {
        // An identify would go on wiggling the servo the guard just stopped: it ends and
        // puts back what it changed. A move test ends and leaves it as the guard did.
        if (m_identifying)
            m_identify->cancel();
        m_moveTest->stopForGuard(servo.id, servo.baud);
    });
    m_telemetry->setBusBusy([this] { return m_running || m_guard->cycle().inCycle(); });
    m_telemetry->setCycleEnded([this] { onCycleEnded(); });
    m_guard->cycle().setBusBusy([this] { return m_running || m_telemetry->inCycle(); });
    m_guard->cycle().setCycleEnded([this] { onCycleEnded(); });
}

Session::~Session()
{
    close();
}

const seriallink::ConnectionStatus &Session::status() const
{
    return m_link->status();
}

const seriallink::LinkCounters &Session::counters() const
{
    return m_link->counters();
}

std::optional<std::chrono::microseconds> Session::measuredLatency() const
{
    return m_bus->measuredLatency();
}

std::chrono::microseconds Session::scanAllowance() const
{
    return m_bus->scanAllowance();
}

bool Session::isStreaming() const
{
    return m_telemetry->isStreaming();
}

void Session::open(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    m_bus->forgetLatencies();
    if (m_link->open(portName, baud, echo))
        m_link->setState(seriallink::ConnectionState::Connected);
}

void Session::close()
{
    m_link->close();
}

void Session::onLinkDown(const QString &message)
{
    const bool wasScanning = m_scan->isRunning();
    const bool wasRunning = m_running;
    const BusOperation running = m_current.operation;
    // All torque off may have run during the pause: the paused operation ends too.
    const bool wasPaused = m_paused;
    const BusOperation paused = m_pausedOperation.operation;
    m_paused = false;
    m_identifying = false;
    ++m_pauseGeneration;
    std::deque<Queued> dropped;
    dropped.swap(m_queue);
    m_scan->abandon();
    stopTelemetry();
    m_guard->noteLinkDown();
    m_running = false;
    // Whoever waits for an operation hears that it ended, queued ones included, so nothing
    // stays busy.
    const auto failed = [&message](const BusOperation &operation) {
        OperationResult result {operation.kind, false, message, {}, {}};
        result.ticket = operation.ticket;
        result.linkLost = true;
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
        m_scan->cancel(); // nothing may hold torque off back for seconds
        ++m_torqueOffEpoch; // what was asked for before must not power the servos again
        m_guard->noteAllTorqueOff();
    }
    if (operation.submitted)
        operation.submitted(m_context);
    Queued queued {operation, m_torqueOffEpoch};
    if (operation.priority == BusOperation::Priority::Emergency)
        m_queue.push_front(std::move(queued)); // ahead of everything waiting
    else
        m_queue.push_back(std::move(queued));
    if (!m_running)
        startNextOperation();
}

void Session::cancel(Operation kind)
{
    switch (kind) {
    case Operation::Scan:
        m_scan->cancel();
        break;
    case Operation::Identify:
        m_identify->cancel();
        break;
    case Operation::FindMotor:
    case Operation::SetUpMotor:
    case Operation::CheckJoints:
        m_motorSetup->cancel();
        break;
    case Operation::HealthCheck:
        m_health->cancel();
        break;
    default:
        break; // the others are short: they run to their end
    }
}

std::deque<Session::Queued>::iterator Session::afterTorqueOff()
{
    auto at = m_queue.begin();
    while (at != m_queue.end() && at->operation.kind == Operation::TorqueOff)
        ++at;
    return at;
}

Session::Queued Session::continuation(Operation kind, std::function<void()> resume) const
{
    Queued next = m_current;
    next.operation.kind = kind;
    next.operation.priority = BusOperation::Priority::Normal;
    next.operation.powersServos = false; // checked once, when it first started
    next.operation.submitted = nullptr;
    next.operation.start = [resume = std::move(resume)](OperationContext &) {
        resume();
    };
    return next;
}

void Session::startNextOperation()
{
    if (m_running)
        return;
    // Telemetry and operations take turns: a running cycle ends first, and a cycle that is
    // due goes before the next operation, unless that is the torque-off emergency.
    if (inCycle())
        return;
    const bool emergency = !m_queue.empty()
        && (m_queue.front().operation.kind == Operation::TorqueOff
            || m_queue.front().operation.kind == Operation::Guard);
    if (!emergency && startCycleIfDue())
        return;
    startQueuedOperation();
}

bool Session::inCycle() const
{
    return m_telemetry->inCycle() || m_guard->cycle().inCycle();
}

bool Session::startCycleIfDue()
{
    return m_telemetry->startIfDue() || m_guard->cycle().startIfDue();
}

void Session::onCycleEnded()
{
    if (!m_queue.empty() && !m_running)
        startQueuedOperation();
    if (!m_running && !inCycle())
        startCycleIfDue();
}

void Session::startQueuedOperation()
{
    if (m_running || m_queue.empty())
        return;
    if (m_paused && m_queue.front().operation.kind != Operation::TorqueOff
        && m_queue.front().operation.kind != Operation::Guard)
        return; // the paused operation goes on first
    m_current = std::move(m_queue.front());
    m_queue.pop_front();
    m_running = true;
    const std::function<void(OperationContext &)> start = std::move(m_current.operation.start);
    m_current.operation.start = nullptr;
    const Operation kind = m_current.operation.kind;
    if (!m_link->isOpen()) {
        if (kind == Operation::Scan || kind == Operation::Guard) {
            m_running = false;
            if (kind == Operation::Scan)
                emit scanFinished(false, Tr::tr("Not connected."));
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        } else {
            finishOperation({kind, false, Tr::tr("Not connected."), {}, {}});
        }
        return;
    }
    if (m_current.operation.powersServos && m_current.epoch != m_torqueOffEpoch) {
        finishOperation({kind,
                         false,
                         Tr::tr("Not sent: all torque off was asked for after this write."),
                         {},
                         {}});
        return;
    }
    if (kind == Operation::Identify)
        m_identifying = true;
    start(m_context);
}

void Session::finishOperation(const OperationResult &result)
{
    m_running = false;
    if (m_current.operation.kind == Operation::Identify)
        m_identifying = false;
    OperationResult reported = result;
    reported.ticket = m_current.operation.ticket;
    emit operationFinished(reported);
    // Queued, so a slot reacting to the result sees the session idle before the next starts.
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::continueLater(Operation next, std::function<void()> resume)
{
    // The running operation pauses here: it goes on as the next one, behind an emergency
    // stop asked for meanwhile (All torque off never waits for a whole apply chain).
    m_running = false;
    m_queue.insert(afterTorqueOff(), continuation(next, std::move(resume)));
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::pauseFor(std::chrono::milliseconds delay,
                       std::function<void(bool torqueOffMeanwhile)> resume)
{
    m_running = false;
    m_paused = true;
    const quint64 epoch = m_current.epoch;
    m_pausedOperation = continuation(m_current.operation.kind,
                                     [this, epoch, resume] { resume(epoch != m_torqueOffEpoch); });
    const quint64 generation = ++m_pauseGeneration;
    QTimer::singleShot(delay, this, [this, generation] {
        if (!m_paused || generation != m_pauseGeneration)
            return;
        m_paused = false;
        // Not continueLater: All torque off may be running right now, and goes on.
        m_queue.insert(afterTorqueOff(), m_pausedOperation);
        if (!m_running)
            startNextOperation();
    });
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::onScanFinished(bool completed, const QString &message)
{
    m_running = false;
    emit scanFinished(completed, message);
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::startTelemetry(const TelemetryOptions &options)
{
    m_telemetry->start(options);
    m_guard->noteStream(options);
}

void Session::stopTelemetry()
{
    m_telemetry->stop();
    m_guard->noteStream({});
}

void Session::setGuardSettings(const GuardSettings &settings)
{
    m_guard->setSettings(settings);
}

void Session::runGuardAction(std::function<void(std::function<void()> finished)> work)
{
    BusOperation action;
    action.kind = Operation::Guard;
    action.start = [this, work = std::move(work)](OperationContext &) {
        work([this] {
            m_running = false;
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        });
    };
    // Behind All torque off only: a servo pushing against a block must not wait for an apply.
    m_queue.insert(afterTorqueOff(), {action, m_torqueOffEpoch});
    if (!m_running)
        startNextOperation();
}

} // namespace feetech
