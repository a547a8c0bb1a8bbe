// Feetech bus session: the link, the operation queue, and each operation handed to its part.
#include "feetechsession.h"

#include "feetechdescription.h"
#include "linksession.h"
#include "overloadrecovery.h"
#include "sharedidcheck.h"
#include "transport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>
#include <memory>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

// A hand-built frame whose answers cannot be named in advance (broadcast, SYNC READ) is listened
// to this long; what comes back shows in the packet log.
constexpr std::chrono::milliseconds kListenWindow {150};

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
{
    qRegisterMetaType<feetech::ApplyPlan>();
    qRegisterMetaType<feetech::HealthReading>();
    qRegisterMetaType<feetech::MoveTestResult>();
    qRegisterMetaType<feetech::ServoInfo>();
    qRegisterMetaType<feetech::ScanOptions>();
    qRegisterMetaType<feetech::ReadSource>();
    qRegisterMetaType<feetech::OperationResult>();
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
    connect(m_apply, &ApplyFlow::progress, this, &Session::progress);
    connect(m_telemetry, &TelemetryCycle::statsChanged, this, &Session::telemetryStats);
    connect(m_motorSetup, &MotorSetup::progress, this, &Session::motorSetupProgress);
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
    const Operation running = m_currentOperation;
    const quint64 runningTicket = m_currentTicket;
    // All torque off may have run during the pause: the paused operation ends too.
    const bool wasPaused = m_paused;
    const Operation paused = m_pausedOperation;
    const quint64 pausedTicket = m_pausedTicket;
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
    const auto failed = [&message](Operation operation, quint64 ticket) {
        OperationResult result {operation, false, message, {}, {}};
        result.ticket = ticket;
        result.linkLost = true;
        return result;
    };
    if (wasScanning)
        emit scanFinished(false, message);
    else if (wasRunning && running != Operation::Guard)
        emit operationFinished(failed(running, runningTicket));
    if (wasPaused)
        emit operationFinished(failed(paused, pausedTicket));
    for (const Queued &operation : dropped) {
        if (operation.operation == Operation::Scan)
            emit scanFinished(false, message);
        else if (operation.operation != Operation::Guard)
            emit operationFinished(failed(operation.operation, operation.ticket));
    }
}

// ---- operation queue

Session::Queued Session::newOperation(Operation operation, std::function<void()> start)
{
    Queued queued {operation, std::move(start), m_nextTicket};
    m_nextTicket = 0;
    return queued;
}

std::deque<Session::Queued>::iterator Session::afterTorqueOff()
{
    auto at = m_queue.begin();
    while (at != m_queue.end() && at->operation == Operation::TorqueOff)
        ++at;
    return at;
}

void Session::enqueue(Operation operation, std::function<void()> start)
{
    m_queue.push_back(newOperation(operation, std::move(start)));
    if (!m_running)
        startNextOperation();
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
        && (m_queue.front().operation == Operation::TorqueOff
            || m_queue.front().operation == Operation::Guard);
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
    if (m_paused && m_queue.front().operation != Operation::TorqueOff
        && m_queue.front().operation != Operation::Guard)
        return; // the paused operation goes on first
    Queued next = std::move(m_queue.front());
    m_queue.pop_front();
    m_running = true;
    m_currentOperation = next.operation;
    m_currentTicket = next.ticket;
    if (!m_link->isOpen()) {
        if (next.operation == Operation::Scan || next.operation == Operation::Guard) {
            m_running = false;
            if (next.operation == Operation::Scan)
                emit scanFinished(false, Tr::tr("Not connected."));
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        } else {
            finishOperation({next.operation, false, Tr::tr("Not connected."), {}, {}});
        }
        return;
    }
    next.start();
}

void Session::finishOperation(const OperationResult &result)
{
    m_running = false;
    OperationResult reported = result;
    reported.ticket = m_currentTicket;
    emit operationFinished(reported);
    // Queued, so a slot reacting to the result sees the session idle before the next starts.
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::continueLater(Operation next, std::function<void()> resume)
{
    // The running operation pauses here: it goes on as the next one, behind an emergency
    // stop asked for meanwhile (All torque off never waits for a whole apply chain).
    m_running = false;
    m_queue.insert(afterTorqueOff(), {next, std::move(resume), m_currentTicket});
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::pauseFor(Operation operation, std::chrono::milliseconds delay,
                       std::function<void()> resume)
{
    m_running = false;
    m_paused = true;
    m_pausedOperation = operation;
    m_pausedTicket = m_currentTicket;
    const quint64 generation = ++m_pauseGeneration;
    QTimer::singleShot(delay, this, [this, generation, operation, resume = std::move(resume)] {
        if (!m_paused || generation != m_pauseGeneration)
            return;
        m_paused = false;
        // Not continueLater: All torque off may be running right now, and goes on.
        m_queue.insert(afterTorqueOff(), {operation, resume, m_pausedTicket});
        if (!m_running)
            startNextOperation();
    });
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

GuidedFlows::Finish Session::finisher()
{
    return [this](const OperationResult &result) {
        finishOperation(result);
    };
}

void Session::onScanFinished(bool completed, const QString &message)
{
    m_running = false;
    emit scanFinished(completed, message);
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

// ---- operations

void Session::scan(const ScanOptions &options)
{
    enqueue(Operation::Scan, [this, options] { m_scan->start(options); });
}

void Session::cancelScan()
{
    m_scan->cancel();
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

void Session::changeId(const ServoInfo &servo, int newId, const QVector<int> &idsInUse)
{
    enqueue(Operation::ChangeId, [this, servo, newId, idsInUse] {
        m_flows->changeId(servo, newId, idsInUse, finisher());
    });
}

void Session::changeBaud(const ServoInfo &servo, qint32 newBaud)
{
    enqueue(Operation::ChangeBaud,
            [this, servo, newBaud] { m_flows->changeBaud(servo, newBaud, finisher()); });
}

void Session::calibrateMiddle(const ServoInfo &servo)
{
    enqueue(Operation::CalibrateMiddle,
            [this, servo] { m_flows->calibrateMiddle(servo, finisher()); });
}

void Session::factoryReset(const ServoInfo &servo)
{
    enqueue(Operation::FactoryReset, [this, servo] { m_flows->factoryReset(servo, finisher()); });
}

void Session::reboot(const ServoInfo &servo)
{
    enqueue(Operation::Reboot, [this, servo] { m_flows->reboot(servo, finisher()); });
}

void Session::ping(quint8 id, qint32 baud)
{
    enqueue(Operation::Ping, [this, id, baud] {
        m_bus->setBaud(baud)([this, id, baud](bool ok, const QString &message) {
            OperationResult result {Operation::Ping, false, message, {}, {}};
            result.servo.id = id;
            result.servo.baud = baud;
            if (!ok) {
                finishOperation(result);
                return;
            }
            Exchange ask;
            ask.request = feetech::ping(id);
            ask.replyId = id;
            m_bus->exchange(
                ask,
                [this, result](const seriallink::TransactionResult &answer,
                               const std::optional<Packet> &reply) mutable {
                    result.ok = reply.has_value();
                    result.latency = answer.latency;
                    result.message = reply ? Tr::tr("Servo %1 answers.").arg(result.servo.id)
                                           : Tr::tr("Servo %1 does not answer: %2")
                                                 .arg(result.servo.id)
                                                 .arg(failureText(answer));
                    if (reply)
                        emit statusSeen(result.servo.id, result.servo.baud, reply->code);
                    finishOperation(result);
                });
        });
    });
}

void Session::checkSharedId(const ServoInfo &servo)
{
    enqueue(Operation::CheckSharedId, [this, servo] {
        m_bus->setBaud(servo.baud)([this, servo](bool ok, const QString &message) {
            if (!ok) {
                finishOperation({Operation::CheckSharedId, false, message, servo, {}});
                return;
            }
            feetech::checkSharedId(
                *m_bus, servo, false,
                [this, servo](SharedIdVerdict verdict, const seriallink::TransactionResult &last) {
                    OperationResult result {Operation::CheckSharedId, true, {}, servo, {}};
                    result.servo.sharedId = verdict == SharedIdVerdict::Shared;
                    if (result.servo.sharedId)
                        result.message = sharedIdRefusal(servo.id);
                    if (verdict == SharedIdVerdict::Failed || verdict == SharedIdVerdict::Silent) {
                        result.ok = false;
                        result.message = verdict == SharedIdVerdict::Failed
                            ? failureText(last)
                            : Tr::tr("%1 stopped answering: check the power and the cable, "
                                     "then look again.")
                                  .arg(servoName(servo));
                    }
                    finishOperation(result);
                });
        });
    });
}

void Session::read(const ServoInfo &servo, const QVector<Block> &blocks, ReadSource source)
{
    m_guard->noteServo(servo);
    enqueue(Operation::Read, [this, servo, blocks, source] {
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {m_bus->setBaud(servo.baud)};
        QVector<Block> toRead = blocks;
        if (toRead.isEmpty())
            toRead = servo.hasTable() ? servo.table().blocks()
                                      : QVector<Block> {{0, RegisterTable::kRawViewSize}};
        steps.push_back(m_bus->readBlocks(target, toRead, source));
        m_bus->runSteps(std::move(steps), [this, servo](bool ok, const QString &message) {
            finishOperation({Operation::Read,
                             ok,
                             ok ? Tr::tr("Read %1.").arg(feetech::servoName(servo)) : message,
                             servo,
                             {}});
        });
    });
}

void Session::write(const ServoInfo &servo, const QVector<RegisterWrite> &writes)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::Write, [this, servo, writes, epoch] {
        if (refusedAfterTorqueOff(Operation::Write, epoch))
            return;
        m_guard->noteWrites(servo, writes);
        m_apply->write(servo, writes, finisher());
    });
}

void Session::apply(const ServoInfo &servo, const ApplyPlan &plan)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::Write, [this, servo, plan, epoch] {
        if (refusedAfterTorqueOff(Operation::Write, epoch))
            return;
        m_guard->noteWrites(servo, plan.writes);
        // Each step's result is reported as it comes; the last one ends the operation.
        m_apply->apply(
            servo, plan,
            [this](const OperationResult &step) {
                OperationResult reported = step;
                reported.ticket = m_currentTicket;
                emit operationFinished(reported);
            },
            finisher(),
            [this](Operation next, std::function<void()> resume) {
                continueLater(next, std::move(resume));
            });
    });
}

void Session::clearStatus(const ServoInfo &servo)
{
    enqueue(Operation::ClearStatus, [this, servo] {
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {m_bus->setBaud(servo.baud),
                                 m_bus->instruction(servo.id, feetech::reset(servo.id),
                                                    servo.repliesToWrites(),
                                                    Tr::tr("Clearing the status"))};
        if (const Register *status = registerAt(servo, u"status"))
            steps.push_back(
                m_bus->read(target, status->address, status->size, ReadSource::ReadBack));
        m_bus->runSteps(std::move(steps), [this, servo](bool ok, const QString &message) {
            finishOperation({Operation::ClearStatus,
                             ok,
                             ok ? Tr::tr("Status of servo %1 cleared.").arg(servo.id) : message,
                             servo,
                             {}});
        });
    });
}

bool Session::refusedAfterTorqueOff(Operation operation, quint64 epoch)
{
    if (epoch == m_torqueOffEpoch)
        return false;
    finishOperation({operation,
                     false,
                     Tr::tr("Not sent: all torque off was asked for after this write."),
                     {},
                     {}});
    return true;
}

namespace {

// The torque-enable register and its "off" value, as the tables of the servos at `baud` give
// them; the STS table's where none is known (a broadcast also reaches servos not scanned).
QVector<std::pair<int, qint32>> torqueOffWrites(const QVector<ServoInfo> &servos, qint32 baud)
{
    QVector<std::pair<int, qint32>> writes;
    const auto add = [&writes](const RegisterTable &table) {
        const Register *torque = table.find(u"torque_enable");
        const auto off = table.torqueValue(TorqueMode::Off);
        if (torque && off && !writes.contains(std::pair(torque->address, *off)))
            writes.append({torque->address, *off});
    };
    for (const ServoInfo &servo : servos) {
        if (servo.baud == baud && servo.hasTable())
            add(servo.table());
    }
    if (writes.isEmpty())
        add(RegisterTable::forFamily(Family::Sts));
    return writes;
}

} // namespace

Step Session::confirmTorqueOff(const ServoInfo &servo, std::shared_ptr<int> confirmed)
{
    return [this, servo, confirmed](StepDone next) {
        const Register *torque = registerAt(servo, u"torque_enable");
        const auto off =
            servo.hasTable() ? servo.table().torqueValue(TorqueMode::Off) : std::nullopt;
        if (!torque || !off) {
            next(false,
                 Tr::tr("%1 is of an unknown model; its torque was not read back.")
                     .arg(feetech::servoName(servo)));
            return;
        }
        Exchange ask;
        ask.request = feetech::read(servo.id, quint8(torque->address), 1);
        ask.replyId = servo.id;
        ask.replyDataSize = 1;
        const int address = torque->address;
        const qint32 offValue = *off;
        m_bus->exchange(
            ask,
            [this, servo, confirmed, next, address, offValue](const seriallink::TransactionResult &,
                                                              const std::optional<Packet> &reply) {
                if (!reply) {
                    next(false,
                         Tr::tr("%1 did not confirm (no reply).").arg(feetech::servoName(servo)));
                    return;
                }
                emit memoryRead(servo.id, servo.baud, address, reply->parameters,
                                ReadSource::ReadBack, reply->code);
                if (quint8(reply->parameters.at(0)) != offValue) {
                    next(false, Tr::tr("%1 still has torque on.").arg(feetech::servoName(servo)));
                    return;
                }
                ++*confirmed;
                next(true, {});
            });
    };
}

void Session::torqueOffAll(const QVector<qint32> &bauds, const QVector<ServoInfo> &servos)
{
    m_scan->cancel(); // nothing may hold torque off back for seconds
    ++m_torqueOffEpoch; // writes asked for before this must not power the servos again
    m_guard->noteAllTorqueOff();
    const auto start = [this, bauds, servos] {
        // Every step goes on whatever failed before it: one silent servo or an odd rate must
        // not keep the others powered.
        auto problems = std::make_shared<QStringList>();
        auto confirmed = std::make_shared<int>(0);
        const auto tolerant = [problems](Step step) -> Step {
            return [problems, step = std::move(step)](StepDone next) {
                step([problems, next](bool ok, const QString &message) {
                    if (!ok)
                        problems->append(message);
                    next(true, {});
                });
            };
        };
        std::vector<Step> steps;
        for (const qint32 baud : bauds) {
            steps.push_back(tolerant(m_bus->setBaud(baud)));
            for (const auto &[address, value] : torqueOffWrites(servos, baud))
                steps.push_back(
                    tolerant(m_bus->write(kBroadcastId, address, QByteArray(1, char(value)), false,
                                          Tr::tr("Torque off at %1").arg(baudText(baud)))));
            for (const ServoInfo &servo : servos) {
                if (servo.baud == baud)
                    steps.push_back(tolerant(confirmTorqueOff(servo, confirmed)));
            }
        }
        m_bus->runSteps(
            std::move(steps), [this, problems, confirmed, servos](bool, const QString &) {
                const QString message = problems->isEmpty()
                    ? Tr::tr("Torque off: sent to the whole bus; %n servo(s) confirmed it.",
                             nullptr, *confirmed)
                    : Tr::tr("Torque off was sent to the whole bus, but: %1")
                          .arg(problems->join(QLatin1Char(' ')));
                finishOperation({Operation::TorqueOff, problems->isEmpty(), message, {}, {}});
            });
    };
    // Ahead of everything waiting: this is the emergency stop.
    m_queue.push_front(newOperation(Operation::TorqueOff, start));
    if (!m_running)
        startNextOperation();
}

void Session::syncWrite(qint32 baud, int address, int length,
                        const QVector<SyncWriteEntry> &entries)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::SyncWrite, [this, baud, address, length, entries, epoch] {
        if (refusedAfterTorqueOff(Operation::SyncWrite, epoch))
            return;
        m_guard->noteSyncWrite(baud, address, entries);
        const auto frame = feetech::syncWrite(quint8(address), quint8(length), entries);
        if (!frame) {
            finishOperation({Operation::SyncWrite,
                             false,
                             Tr::tr("The SYNC WRITE does not fit in one packet."),
                             {},
                             {}});
            return;
        }
        std::vector<Step> steps {
            m_bus->setBaud(baud),
            m_bus->instruction(kBroadcastId, *frame, false,
                               Tr::tr("SYNC WRITE at %1").arg(baudText(baud)))};
        m_bus->runSteps(std::move(steps), [this, entries](bool ok, const QString &message) {
            finishOperation(
                {Operation::SyncWrite,
                 ok,
                 ok ? Tr::tr("Sent to %n servo(s) in one SYNC WRITE.", nullptr, int(entries.size()))
                    : message,
                 {},
                 {}});
        });
    });
}

void Session::setGuardSettings(const GuardSettings &settings)
{
    m_guard->setSettings(settings);
}

void Session::runGuardAction(std::function<void(std::function<void()> finished)> work)
{
    const auto start = [this, work = std::move(work)] {
        work([this] {
            m_running = false;
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        });
    };
    // Behind All torque off only: a servo pushing against a block must not wait for an apply.
    m_queue.insert(afterTorqueOff(), {Operation::Guard, start, 0});
    if (!m_running)
        startNextOperation();
}

void Session::recoverOverload(const ServoInfo &servo, bool checkOnly)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::RecoverOverload, [this, servo, checkOnly, epoch] {
        if (!checkOnly && refusedAfterTorqueOff(Operation::RecoverOverload, epoch))
            return;
        auto target = std::make_shared<ServoInfo>(servo);
        auto latched = std::make_shared<std::optional<bool>>();
        m_bus->runSteps(
            {m_bus->setBaud(servo.baud),
             feetech::recoverOverload(*m_bus, target, checkOnly, latched)},
            [this, servo, checkOnly, latched](bool ok, const QString &message) {
                OperationResult result {Operation::RecoverOverload, ok, message, servo, {}};
                result.stillLatched = ok && latched->value_or(false);
                if (result.stillLatched) {
                    result.ok = false;
                    result.message = powerCycleSteps(servo).join(QLatin1Char('\n'));
                } else if (ok) {
                    result.message = checkOnly
                        ? Tr::tr("Servo ID %1: the overload bit is clear; switch its torque on "
                                 "when you are ready.")
                              .arg(servo.id)
                        : Tr::tr("Servo ID %1 recovered: the overload bit is clear and it holds "
                                 "where it stands with torque on.")
                              .arg(servo.id);
                    if (!checkOnly) {
                        const Register *torque = registerAt(servo, u"torque_enable");
                        const auto on = servo.table().torqueValue(TorqueMode::On);
                        if (torque && on)
                            m_guard->noteWrites(servo,
                                                {{torque->address, QByteArray(1, char(*on))}});
                    }
                }
                m_bus->logNote(result.message, !result.ok);
                finishOperation(result);
            });
    });
}
void Session::checkHealth(const QVector<ServoInfo> &servos, int reads)
{
    m_health->clearCancel();
    enqueue(Operation::HealthCheck, [this, servos, reads] { checkNextServo(servos, 0, reads); });
}

void Session::checkNextServo(QVector<ServoInfo> servos, int done, int reads)
{
    const int total = int(servos.size());
    if (done >= total || m_health->isCancelled()) {
        const bool stopped = done < total;
        finishOperation({Operation::HealthCheck,
                         !stopped,
                         stopped ? Tr::tr("The health check was stopped after %1 of %n servo(s).",
                                          nullptr, total)
                                       .arg(done)
                                 : Tr::tr("%n servo(s) checked.", nullptr, total),
                         {},
                         {}});
        return;
    }
    m_health->read(servos.at(done), reads, [this, servos, done, reads](const HealthReading &r) {
        if (!m_link->isOpen())
            return; // onLinkDown has ended the check
        emit healthRead(r);
        emit progress(done + 1, int(servos.size()));
        // Between two servos the bus is free: All torque off never waits for a whole check.
        continueLater(Operation::HealthCheck,
                      [this, servos, done, reads] { checkNextServo(servos, done + 1, reads); });
    });
}

void Session::cancelHealthCheck()
{
    m_health->cancel();
}

void Session::moveTest(const ServoInfo &servo)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::MoveTest, [this, servo, epoch] {
        if (refusedAfterTorqueOff(Operation::MoveTest, epoch))
            return;
        m_guard->noteDriven(servo); // the guard watches the move as it does any other
        m_moveTest->run(
            servo,
            [this, epoch](std::chrono::milliseconds delay,
                          std::function<void(bool torqueOff)> resume) {
                pauseFor(Operation::MoveTest, delay,
                         [this, epoch, resume] { resume(epoch != m_torqueOffEpoch); });
            },
            [this, servo](const MoveTestResult &result) {
                emit moveTested(result);
                finishOperation({Operation::MoveTest, result.ok, result.message, servo, {}});
            });
    });
}
void Session::lockEeprom(const ServoInfo &servo)
{
    enqueue(Operation::LockEeprom, [this, servo] {
        const Register *lock = registerAt(servo, u"lock");
        if (!lock) {
            finishOperation({Operation::LockEeprom,
                             false,
                             Tr::tr("The servo's model has no known EEPROM lock register."),
                             servo,
                             {}});
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        // What the servo says after the write, not that the write was answered, is the result.
        auto readBack = std::make_shared<std::optional<int>>();
        std::vector<Step> steps {m_bus->setBaud(servo.baud), m_bus->lock(target, true),
                                 m_bus->read(target, lock->address, lock->size,
                                             ReadSource::ReadBack,
                                             [readBack](const QByteArray &bytes) {
                                                 if (!bytes.isEmpty())
                                                     *readBack = quint8(bytes.at(0));
                                             })};
        m_bus->runSteps(std::move(steps), [this, servo, readBack](bool ok, const QString &message) {
            const bool locked = ok && readBack->has_value() && **readBack != 0;
            QString text = message;
            if (locked)
                text = Tr::tr("Servo %1's EEPROM is locked (read back).").arg(servo.id);
            else if (ok)
                text = Tr::tr("Servo %1 still reads back unlocked after the lock was written.")
                           .arg(servo.id);
            finishOperation({Operation::LockEeprom, locked, text, servo, {}});
        });
    });
}
void Session::sendPacket(const QByteArray &frame, qint32 baud, std::optional<quint8> replyId,
                         int replyDataSize)
{
    // Like any write: one asked for before All torque off must not power the servos again.
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::SendPacket, [this, frame, baud, replyId, replyDataSize, epoch] {
        if (refusedAfterTorqueOff(Operation::SendPacket, epoch))
            return;
        m_bus->setBaud(
            baud)([this, frame, baud, replyId, replyDataSize](bool ok, const QString &message) {
            OperationResult result {Operation::SendPacket, false, message, {}, {}};
            result.servo.baud = baud;
            if (!ok) {
                finishOperation(result);
                return;
            }
            Exchange ask;
            ask.request = frame;
            ask.retryCount = 0; // sent once, as the user built it
            if (replyId) {
                ask.replyId = replyId;
                ask.replyDataSize = replyDataSize;
                result.servo.id = *replyId;
            } else {
                ask.listenOnly = true;
                ask.silenceExpected = true;
                ask.replyTimeout = kListenWindow;
            }
            m_bus->exchange(ask,
                            [this, result, replyId](const seriallink::TransactionResult &answer,
                                                    const std::optional<Packet> &reply) mutable {
                                result.latency = answer.latency;
                                if (answer.failure == seriallink::Failure::LinkDown) {
                                    result.message = failureText(answer);
                                } else if (!replyId) {
                                    result.ok = true;
                                    result.message = Tr::tr("Sent; its answers, if any, are in "
                                                            "the packet log.");
                                } else {
                                    result.ok = reply.has_value();
                                    result.message = reply
                                        ? Tr::tr("Servo %1 answered.").arg(*replyId)
                                        : Tr::tr("Sent; servo %1 did not answer: %2")
                                              .arg(*replyId)
                                              .arg(failureText(answer));
                                }
                                finishOperation(result);
                            });
        });
    });
}
// ---- identify

void Session::identifyJoint(const ServoInfo &servo)
{
    const quint64 epoch = m_torqueOffEpoch;
    m_identify->clearCancel();
    enqueue(Operation::Identify, [this, servo, epoch] {
        if (refusedAfterTorqueOff(Operation::Identify, epoch))
            return;
        m_guard->noteDriven(servo);
        m_identifying = true;
        m_identify->run(
            servo,
            [this](const OperationResult &result) {
                m_identifying = false;
                finishOperation(result);
            },
            [this, epoch](std::chrono::milliseconds delay,
                          std::function<void(bool torqueOff)> resume) {
                pauseFor(Operation::Identify, delay,
                         [this, epoch, resume] { resume(epoch != m_torqueOffEpoch); });
            });
    });
}

// ---- motor set-up

void Session::findMotor(const MotorTarget &target)
{
    m_motorSetup->clearCancel();
    enqueue(Operation::FindMotor, [this, target] {
        m_motorSetup->find(target, [this](const MotorSearch &search) {
            MotorSetupResult result;
            result.ok = search.foundOne();
            result.search = search;
            result.stopped = search.stopped;
            result.from = result.to = search.servo;
            result.message = search.message;
            emit motorSetupFinished(result);
            finishOperation({Operation::FindMotor, result.ok, result.message, search.servo, {}});
        });
    });
}

void Session::setUpMotor(const MotorTarget &target)
{
    m_motorSetup->clearCancel();
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::SetUpMotor, [this, target, epoch] {
        if (refusedAfterTorqueOff(Operation::SetUpMotor, epoch))
            return;
        m_motorSetup->setUp(target, [this](const MotorSetupResult &result) {
            emit motorSetupFinished(result);
            finishOperation({Operation::SetUpMotor, result.ok, result.message, result.to, {}});
        });
    });
}

void Session::checkJoints(qint32 baud, const QVector<JointCheck> &joints)
{
    m_motorSetup->clearCancel();
    enqueue(Operation::CheckJoints, [this, baud, joints] {
        m_motorSetup->check(baud, joints, [this](const QVector<JointCheck> &checked) {
            emit jointsChecked(checked);
            const auto done = std::count_if(checked.begin(), checked.end(),
                                            [](const JointCheck &joint) { return joint.done(); });
            finishOperation(
                {Operation::CheckJoints,
                 true,
                 Tr::tr("%1 of %n joint(s) already set up.", nullptr, int(checked.size()))
                     .arg(done),
                 {},
                 {}});
        });
    });
}

void Session::cancelMotorSetup()
{
    m_motorSetup->cancel();
}

void Session::cancelIdentify()
{
    m_identify->cancel();
}

} // namespace feetech
