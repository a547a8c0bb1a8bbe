// Feetech bus session: adaptive scan, identification, block reads, locked EEPROM writes, flows.
#include "feetech/feetechsession.h"

#include "feetech/feetechdescription.h"
#include "link/transport.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

constexpr int kIdentityAddress = 0;
constexpr int kIdentitySize = 9; // addresses 0-8: firmware, END, model, ID, baud, delay, level
constexpr quint8 kTorqueOff = 0;
constexpr std::size_t kLatencyWindow = 8;
constexpr quint8 kTorqueCalibrate = 128;

QString failureText(const seriallink::TransactionResult &result)
{
    switch (result.failure) {
    case seriallink::Failure::None:
        return {};
    case seriallink::Failure::Timeout:
        return Tr::tr("no reply after %n attempt(s)", nullptr, result.attempts);
    case seriallink::Failure::LinkDown:
        return Tr::tr("the port is closed");
    case seriallink::Failure::Cancelled:
        return Tr::tr("cancelled");
    }
    return {};
}

const Register *registerAt(const ServoInfo &servo, QStringView key)
{
    return servo.hasTable() ? servo.table().find(key) : nullptr;
}

// Runs asynchronous steps one after the other; the first failure ends the run.
class StepRunner : public std::enable_shared_from_this<StepRunner>
{
public:
    using Done = std::function<void(bool ok, const QString &message)>;
    using Step = std::function<void(Done next)>;

    StepRunner(std::vector<Step> steps, Done done)
        : m_steps(std::move(steps))
        , m_done(std::move(done))
    { }

    void run()
    {
        if (m_index == m_steps.size()) {
            finish(true, {});
            return;
        }
        auto self = shared_from_this();
        Step &step = m_steps[m_index++];
        step([self](bool ok, const QString &message) {
            if (!ok)
                self->finish(false, message);
            else
                self->run();
        });
    }

private:
    void finish(bool ok, const QString &message)
    {
        Done done = std::move(m_done);
        m_done = nullptr;
        if (done)
            done(ok, message);
    }

    std::vector<Step> m_steps;
    std::size_t m_index = 0;
    Done m_done;
};

} // namespace

quint16 ServoInfo::modelNumber() const
{
    return feetech::modelNumber(modelMajor, modelMinor,
                                byteOrderFlag ? ByteOrder::Big : ByteOrder::Little);
}

QString ServoInfo::firmware() const
{
    return QStringLiteral("%1.%2").arg(firmwareMajor).arg(firmwareMinor, 2, 10, QLatin1Char('0'));
}

const RegisterTable &ServoInfo::table() const
{
    return model.family ? RegisterTable::forFamily(*model.family) : RegisterTable::rawView();
}

std::optional<ServoInfo> servoInfoFromIdentity(quint8 id, qint32 baud, QByteArrayView bytes)
{
    if (bytes.size() < kIdentitySize)
        return std::nullopt;
    ServoInfo info;
    info.id = id;
    info.baud = baud;
    info.firmwareMajor = quint8(bytes[0]);
    info.firmwareMinor = quint8(bytes[1]);
    info.byteOrderFlag = quint8(bytes[2]);
    info.modelMajor = quint8(bytes[3]);
    info.modelMinor = quint8(bytes[4]);
    info.baudCode = quint8(bytes[6]);
    info.responseLevel = quint8(bytes[8]);
    info.model = ModelTable::builtIn().identify(info.modelMajor, info.modelMinor);
    // A servo whose END flag contradicts its family's byte order is not what the table
    // describes: it gets the raw view rather than a table decoded in the wrong order.
    if (info.model.family) {
        const ByteOrder expected = RegisterTable::forFamily(*info.model.family).byteOrder();
        const ByteOrder reported = info.byteOrderFlag ? ByteOrder::Big : ByteOrder::Little;
        if (info.byteOrderFlag > 1 || expected != reported)
            info.model.family.reset();
    }
    return info;
}

MiddleCalibration middleCalibration(const ServoInfo &servo)
{
    if (!servo.model.family)
        return MiddleCalibration::Unsupported;
    const int firmware = servo.firmwareMajor * 100 + servo.firmwareMinor;
    switch (*servo.model.family) {
    case Family::Scs:
        return MiddleCalibration::Unsupported;
    case Family::Sts:
        return firmware >= 310 ? MiddleCalibration::Instruction
                               : MiddleCalibration::TorqueEnable128;
    case Family::Hls:
        return MiddleCalibration::Instruction;
    case Family::Sms:
        return MiddleCalibration::TorqueEnable128;
    }
    return MiddleCalibration::Unsupported;
}

Session::Session(const SessionTiming &timing, QObject *parent)
    : QObject(parent)
    , m_timing(timing)
    , m_transport(new seriallink::SerialTransport(this))
    , m_engine(new seriallink::RequestEngine(*m_transport, m_format, describeFrame, this))
    , m_reopenTimer(new QTimer(this))
{
    qRegisterMetaType<feetech::ServoInfo>();
    qRegisterMetaType<feetech::ScanOptions>();
    qRegisterMetaType<feetech::ReadSource>();
    qRegisterMetaType<feetech::OperationResult>();
    m_engine->setTiming(m_timing.engine);
    connect(m_engine, &seriallink::RequestEngine::packetLogged, this, &Session::packetLogged);
    connect(m_engine, &seriallink::RequestEngine::countersChanged, this, &Session::countersChanged);
    // Queued: a port error can be raised inside a call the engine is making to the port.
    connect(m_transport, &seriallink::Transport::failed, this, &Session::onPortFailed,
            Qt::QueuedConnection);
    connect(m_reopenTimer, &QTimer::timeout, this, &Session::tryReopen);
}

Session::~Session()
{
    close();
}

const seriallink::LinkCounters &Session::counters() const
{
    return m_engine->counters();
}

std::optional<std::chrono::microseconds> Session::measuredLatency() const
{
    if (m_latencies.empty())
        return std::nullopt;
    // The median of the recent answers: one slow outlier (a busy OS, the first exchange on a
    // fresh port) must not slow a whole scan down.
    std::vector<std::chrono::microseconds> sorted(m_latencies.begin(), m_latencies.end());
    std::sort(sorted.begin(), sorted.end());
    return sorted.at((sorted.size() - 1) / 2);
}

std::chrono::microseconds Session::scanAllowance() const
{
    const auto latency = measuredLatency();
    if (!latency)
        return m_timing.initialScanAllowance;
    const auto scaled =
        std::chrono::microseconds(qint64(double(latency->count()) * m_timing.scanLatencyFactor));
    return std::clamp(scaled + kLongestReturnDelay, m_timing.minimumScanAllowance,
                      m_timing.maximumScanAllowance);
}

void Session::noteLatency(std::chrono::microseconds latency)
{
    m_latencies.push_back(latency);
    while (m_latencies.size() > kLatencyWindow)
        m_latencies.pop_front();
}

void Session::setStatus(seriallink::ConnectionState state, const QString &message)
{
    m_status.state = state;
    m_status.message = message;
    emit statusChanged(m_status);
}

void Session::open(const QString &portName, qint32 baud, seriallink::EchoMode echo)
{
    close();
    m_status.portName = portName;
    m_status.baud = baud;
    m_echo = echo;
    m_latencies.clear();
    setStatus(seriallink::ConnectionState::Connecting);
    QString error;
    if (!m_transport->open(portName, baud, &error)) {
        setStatus(seriallink::ConnectionState::Disconnected, error);
        return;
    }
    m_engine->resetCounters();
    m_engine->setEchoMode(echo);
    setStatus(seriallink::ConnectionState::Connected);
}

void Session::endAll(const QString &message, seriallink::Failure failure)
{
    ++m_generation;
    const bool wasScanning = m_scan.has_value();
    const bool wasRunning = m_running;
    const Operation running = m_currentOperation;
    std::deque<Queued> dropped;
    dropped.swap(m_queue);
    m_scan.reset();
    stopTelemetry();
    m_running = false;
    m_engine->cancelAll(failure);
    m_transport->close();
    // Whoever waits for an operation hears that it ended, queued ones included, so nothing
    // stays busy.
    if (wasScanning)
        emit scanFinished(false, message);
    else if (wasRunning)
        emit operationFinished({running, false, message, {}, {}});
    for (const Queued &operation : dropped) {
        if (operation.operation == Operation::Scan)
            emit scanFinished(false, message);
        else
            emit operationFinished({operation.operation, false, message, {}, {}});
    }
}

void Session::close()
{
    m_reopenTimer->stop();
    endAll(Tr::tr("Disconnected."), seriallink::Failure::Cancelled);
    if (m_status.state != seriallink::ConnectionState::Disconnected)
        setStatus(seriallink::ConnectionState::Disconnected);
}

void Session::onPortFailed(const QString &message, bool lost)
{
    // Queued: by now the user may have closed the port, or opened another one.
    if (!m_transport->isOpen() && m_status.state != seriallink::ConnectionState::Connected)
        return;
    endAll(message, seriallink::Failure::LinkDown);
    if (lost) {
        setStatus(seriallink::ConnectionState::Lost,
                  Tr::tr("%1 Reconnecting when it comes back.").arg(message));
        m_reopenTimer->start(m_timing.reconnectInterval);
    } else {
        setStatus(seriallink::ConnectionState::Disconnected, message);
    }
}

void Session::tryReopen()
{
    QString error;
    if (!m_transport->open(m_status.portName, m_status.baud, &error))
        return; // still gone; the timer tries again
    m_reopenTimer->stop();
    m_engine->resetEchoDetection();
    setStatus(seriallink::ConnectionState::Connected,
              Tr::tr("%1 is back. Scan again if servos were changed while it was away.")
                  .arg(m_status.portName));
}

// ---- operation queue

void Session::enqueue(Operation operation, std::function<void()> start)
{
    m_queue.push_back({operation, std::move(start)});
    if (!m_running)
        startNextOperation();
}

void Session::startNextOperation()
{
    if (m_running)
        return;
    // Telemetry and operations take turns: a running cycle ends first, and a cycle that is
    // due goes before the next operation, unless that is the torque-off emergency.
    if (m_telemetry && m_telemetry->inCycle)
        return;
    const bool emergency = !m_queue.empty() && m_queue.front().operation == Operation::TorqueOff;
    if (!emergency && startTelemetryCycleIfDue())
        return;
    startQueuedOperation();
}

void Session::startQueuedOperation()
{
    if (m_running || m_queue.empty())
        return;
    Queued next = std::move(m_queue.front());
    m_queue.pop_front();
    m_running = true;
    m_currentOperation = next.operation;
    if (!m_transport->isOpen()) {
        if (next.operation == Operation::Scan) {
            m_running = false;
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
    emit operationFinished(result);
    // Queued, so a slot reacting to the result sees the session idle before the next starts.
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::runSteps(std::vector<Step> steps, Done done)
{
    const quint64 generation = m_generation;
    auto runner = std::make_shared<StepRunner>(
        std::move(steps), [this, generation, done = std::move(done)](bool ok, const QString &m) {
            if (generation == m_generation) // not after a close or a lost port
                done(ok, m);
        });
    runner->run();
}

// ---- transactions and steps

void Session::exchange(const Exchange &request, ExchangeDone done)
{
    seriallink::Transaction transaction;
    transaction.request = request.request;
    transaction.priority = request.priority;
    transaction.replyTimeout = request.replyTimeout;
    transaction.retryCount = request.retryCount;
    transaction.silenceExpected = request.silenceExpected;
    if (request.listenOnly) {
        transaction.acceptsReply = [](const QByteArray &) {
            return false;
        };
        transaction.expectedReplySize = kMinimumPacketSize;
    } else if (request.replyId) {
        const QByteArray sent = request.request;
        const quint8 id = *request.replyId;
        const std::optional<quint8> alternate = request.alternateReplyId;
        const int size = request.replyDataSize;
        // Our own frame coming back (an echo the engine did not expect) is never the answer.
        const auto other = request.otherFrame;
        transaction.acceptsReply = [sent, id, alternate, size, other](const QByteArray &frame) {
            if (frame == sent)
                return false;
            const auto packet = decodePacket(frame);
            const bool answer = packet
                && (packet->id == id || (alternate && packet->id == *alternate))
                && packet->parameters.size() == size;
            if (packet && !answer && other)
                other(*packet);
            return answer;
        };
        transaction.expectedReplySize = kMinimumPacketSize + size;
    }
    const quint64 generation = m_generation;
    transaction.done = [this, generation,
                        done = std::move(done)](const seriallink::TransactionResult &result) {
        if (generation != m_generation)
            return;
        std::optional<Packet> packet;
        if (result.ok() && !result.reply.isEmpty())
            packet = decodePacket(result.reply);
        if (packet)
            noteLatency(result.latency);
        done(result, packet);
    };
    m_engine->submit(std::move(transaction));
}

Session::Step Session::stepSetBaud(qint32 baud)
{
    return [this, baud](Done next) {
        if (m_transport->baudRate() == baud) {
            next(true, {});
            return;
        }
        if (!m_transport->setBaudRate(baud)) {
            next(false, Tr::tr("The port cannot be set to %1.").arg(baudText(baud)));
            return;
        }
        m_status.baud = baud;
        next(true, {});
    };
}

Session::Step Session::stepWrite(quint8 id, int address, const QByteArray &bytes, bool expectReply,
                                 const QString &what)
{
    return stepInstruction(id, feetech::write(id, quint8(address), bytes), expectReply, what);
}

Session::Step Session::stepInstruction(quint8 id, const QByteArray &request, bool expectReply,
                                       const QString &what)
{
    return [this, id, request, expectReply, what](Done next) {
        Exchange ask;
        ask.request = request;
        if (expectReply)
            ask.replyId = id;
        exchange(ask,
                 [what, next](const seriallink::TransactionResult &result,
                              const std::optional<Packet> &) {
                     if (!result.ok())
                         next(false, Tr::tr("%1: %2").arg(what, failureText(result)));
                     else
                         next(true, {});
                 });
    };
}

Session::Step Session::stepLock(std::shared_ptr<ServoInfo> servo, bool locked)
{
    return [this, servo, locked](Done next) {
        const Register *lock = registerAt(*servo, u"lock");
        if (!lock) {
            next(false, Tr::tr("The servo's model has no known EEPROM lock register."));
            return;
        }
        const QString what = locked ? Tr::tr("Locking the EEPROM") : Tr::tr("Unlocking the EEPROM");
        stepWrite(servo->id, lock->address, QByteArray(1, char(locked ? 1 : 0)),
                  servo->repliesToWrites(), what)(next);
    };
}

Session::Step Session::stepRead(std::shared_ptr<ServoInfo> servo, int address, int size,
                                ReadSource source)
{
    return [this, servo, address, size, source](Done next) {
        Exchange ask;
        ask.request = feetech::read(servo->id, quint8(address), quint8(size));
        ask.replyId = servo->id;
        ask.replyDataSize = size;
        if (source == ReadSource::Refresh)
            ask.priority = seriallink::Transaction::Priority::Poll;
        exchange(
            ask,
            [this, servo, address, size, source, next](const seriallink::TransactionResult &result,
                                                       const std::optional<Packet> &reply) {
                if (!reply) {
                    next(false,
                         Tr::tr("Reading %1 bytes at address %2: %3")
                             .arg(size)
                             .arg(address)
                             .arg(failureText(result)));
                    return;
                }
                emit memoryRead(servo->id, servo->baud, address, reply->parameters, source,
                                reply->code);
                next(true, {});
            });
    };
}

Session::Step Session::stepIdentify(std::shared_ptr<ServoInfo> servo)
{
    return [this, servo](Done next) {
        Exchange ask;
        ask.request = feetech::read(servo->id, kIdentityAddress, kIdentitySize);
        ask.replyId = servo->id;
        ask.replyDataSize = kIdentitySize;
        exchange(ask,
                 [servo, next](const seriallink::TransactionResult &result,
                               const std::optional<Packet> &reply) {
                     const auto info = reply
                         ? servoInfoFromIdentity(servo->id, servo->baud, reply->parameters)
                         : std::nullopt;
                     if (!info) {
                         next(false,
                              Tr::tr("Reading the identity of servo %1: %2")
                                  .arg(servo->id)
                                  .arg(failureText(result)));
                         return;
                     }
                     *servo = *info;
                     next(true, {});
                 });
    };
}

Session::Step Session::stepPing(quint8 id, bool mustAnswer, int retries)
{
    return [this, id, mustAnswer, retries](Done next) {
        Exchange ask;
        ask.request = feetech::ping(id);
        ask.replyId = id;
        ask.retryCount = retries;
        exchange(ask,
                 [id, mustAnswer, next](const seriallink::TransactionResult &result,
                                        const std::optional<Packet> &reply) {
                     if (result.failure == seriallink::Failure::LinkDown
                         || result.failure == seriallink::Failure::Cancelled)
                         next(false, failureText(result));
                     else if (mustAnswer && !reply)
                         next(false, Tr::tr("Servo %1 does not answer.").arg(id));
                     else if (!mustAnswer && reply)
                         next(false, Tr::tr("ID %1 is already in use on this bus.").arg(id));
                     else
                         next(true, {});
                 });
    };
}

void Session::relock(std::vector<std::shared_ptr<ServoInfo>> places, std::function<void()> done)
{
    if (places.empty()) {
        done();
        return;
    }
    const std::shared_ptr<ServoInfo> place = places.front();
    places.erase(places.begin());
    // Best effort: a place where nothing answers is simply passed.
    runSteps({stepSetBaud(place->baud), stepLock(place, true)},
             [this, places, done](bool, const QString &) { relock(places, done); });
}

Session::Step Session::stepAddressWrite(quint8 id, int address, quint8 value,
                                        std::optional<quint8> alternateReplyId)
{
    return [this, id, address, value, alternateReplyId](Done next) {
        Exchange ask;
        ask.request = feetech::write(id, quint8(address), QByteArray(1, char(value)));
        ask.replyId = id;
        ask.alternateReplyId = alternateReplyId;
        ask.retryCount = 0; // a second write would go to an address that may have changed
        exchange(ask,
                 [next](const seriallink::TransactionResult &r, const std::optional<Packet> &) {
                     // No answer is not a failure: the servo may already listen elsewhere. Whether
                     // the write took is decided by finding it at the new address.
                     if (r.failure == seriallink::Failure::LinkDown
                         || r.failure == seriallink::Failure::Cancelled)
                         next(false, failureText(r));
                     else
                         next(true, {});
                 });
    };
}

Session::Step Session::markDone(std::shared_ptr<bool> flag)
{
    return [flag](Done next) {
        *flag = true;
        next(true, {});
    };
}

QString Session::servoName(const ServoInfo &servo) const
{
    return Tr::tr("servo %1 at %2").arg(servo.id).arg(baudText(servo.baud));
}

// ---- scan

void Session::scan(const ScanOptions &options)
{
    enqueue(Operation::Scan, [this, options] {
        ScanState state;
        state.options = options;
        state.options.firstId = std::clamp(options.firstId, 0, int(kMaxServoId));
        state.options.lastId = std::clamp(options.lastId, state.options.firstId, int(kMaxServoId));
        if (state.options.bauds.isEmpty())
            state.options.bauds = {m_transport->baudRate()};
        const int ids = state.options.lastId - state.options.firstId + 1;
        state.total = ids * int(state.options.bauds.size());
        m_scan = state;
        emit scanProgress(0, state.total, state.options.bauds.first());
        scanBaud(0);
    });
}

void Session::cancelScan()
{
    if (m_scan)
        m_scan->cancelled = true;
}

void Session::scanBaud(int baudIndex)
{
    if (!m_scan)
        return;
    if (m_scan->cancelled) {
        endScan(false, Tr::tr("Scan cancelled; %n servo(s) found before.", nullptr, m_scan->found));
        return;
    }
    if (baudIndex >= m_scan->options.bauds.size()) {
        endScan(true, Tr::tr("Scan complete: %n servo(s) found.", nullptr, m_scan->found));
        return;
    }
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    m_scan->baudIndex = baudIndex;
    m_scan->foundIds.clear(); // the same ID at another rate is another servo
    m_scan->recheck.clear();
    if (!feetech::baudCode(baud) && baud != m_transport->baudRate()) {
        endScan(false, Tr::tr("%1 is not a Feetech baud rate.").arg(baudText(baud)));
        return;
    }
    stepSetBaud(baud)([this, baudIndex, baud](bool ok, const QString &message) {
        if (!ok) {
            endScan(false, message);
            return;
        }
        probe(baudIndex, 0);
    });
}

void Session::probe(int baudIndex, int round)
{
    // Every servo at this rate answers a broadcast PING at once: the bytes collide, but that
    // any come at all says there is something to find, and when they come tells how quickly
    // this adapter answers. A second round gives a second measurement, so that one slow first
    // exchange does not set the pace.
    Exchange ask;
    ask.request = feetech::ping(kBroadcastId);
    ask.listenOnly = true;
    ask.silenceExpected = true;
    ask.replyTimeout = std::max(m_timing.probeAllowance, scanAllowance());
    ask.retryCount = 0;
    exchange(ask,
             [this, baudIndex, round](const seriallink::TransactionResult &result,
                                      const std::optional<Packet> &) {
                 if (!m_scan)
                     return;
                 if (result.failure == seriallink::Failure::LinkDown) {
                     endScan(false, failureText(result));
                     return;
                 }
                 if (result.bytesHeard > 0) {
                     noteLatency(result.latency);
                     if (round == 0)
                         probe(baudIndex, 1);
                     else
                         scanId(baudIndex, m_scan->options.firstId);
                     return;
                 }
                 if (round > 0 || !m_scan->options.skipSilentRates) {
                     scanId(baudIndex, m_scan->options.firstId); // heard once, or a thorough scan
                     return;
                 }
                 const int ids = m_scan->options.lastId - m_scan->options.firstId + 1;
                 m_scan->done += ids;
                 emit scanProgress(m_scan->done, m_scan->total,
                                   m_scan->options.bauds.at(baudIndex));
                 scanBaud(baudIndex + 1);
             });
}

void Session::scanId(int baudIndex, int id)
{
    if (!m_scan)
        return;
    if (m_scan->cancelled) {
        scanBaud(baudIndex);
        return;
    }
    if (id > m_scan->options.lastId) {
        recheck(baudIndex);
        return;
    }
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    scanPing(id, scanAllowance(), 0,
             [this, baudIndex, id, baud](const seriallink::TransactionResult &result,
                                         const std::optional<Packet> &reply) {
                 const auto advance = [this, baudIndex, id, baud] {
                     if (!m_scan)
                         return;
                     ++m_scan->done;
                     emit scanProgress(m_scan->done, m_scan->total, baud);
                     scanId(baudIndex, id + 1);
                 };
                 if (!reply) {
                     // Something came, but not a clean answer: worth a second, patient look.
                     if (result.bytesHeard > 0 && !m_scan->recheck.contains(id))
                         m_scan->recheck.append(id);
                     advance();
                     return;
                 }
                 identifyFound(quint8(id), baud, advance);
             });
}

void Session::scanPing(int id, std::optional<std::chrono::microseconds> timeout, int retries,
                       ExchangeDone then)
{
    Exchange ask;
    ask.request = feetech::ping(quint8(id));
    ask.replyId = quint8(id);
    ask.silenceExpected = true;
    ask.replyTimeout = timeout;
    ask.retryCount = retries;
    // A servo that answered after its wait ended shows up now, named: ask it again later.
    ask.otherFrame = [this, id](const Packet &packet) {
        if (m_scan && packet.id < id && !m_scan->foundIds.contains(packet.id)
            && !m_scan->recheck.contains(packet.id))
            m_scan->recheck.append(packet.id);
    };
    exchange(ask,
             [this, then](const seriallink::TransactionResult &result,
                          const std::optional<Packet> &reply) {
                 if (!m_scan)
                     return;
                 if (result.failure == seriallink::Failure::LinkDown)
                     endScan(false, failureText(result));
                 else
                     then(result, reply);
             });
}

void Session::recheck(int baudIndex)
{
    if (!m_scan)
        return;
    if (m_scan->recheck.isEmpty() || m_scan->cancelled) {
        m_scan->recheck.clear();
        scanBaud(m_scan->cancelled ? baudIndex : baudIndex + 1);
        return;
    }
    const int id = m_scan->recheck.takeFirst();
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    // The engine's own, generous reply timeout this time, and one retry.
    scanPing(id, std::nullopt, 1,
             [this, baudIndex, id, baud](const seriallink::TransactionResult &,
                                         const std::optional<Packet> &reply) {
                 if (!reply)
                     recheck(baudIndex);
                 else
                     identifyFound(quint8(id), baud, [this, baudIndex] { recheck(baudIndex); });
             });
}

void Session::identifyFound(quint8 id, qint32 baud, std::function<void()> then)
{
    auto servo = std::make_shared<ServoInfo>();
    servo->id = id;
    servo->baud = baud;
    stepIdentify(servo)([this, servo, then](bool ok, const QString &) {
        if (!m_scan)
            return;
        if (!ok) {
            // It answers PING but not READ: show it, with nothing guessed about it.
            servo->model.name = Tr::tr("unknown (identity unreadable)");
            servo->model.family.reset();
        }
        ++m_scan->found;
        m_scan->foundIds.append(servo->id);
        m_scan->recheck.removeAll(servo->id);
        emit servoFound(*servo);
        then();
    });
}

void Session::endScan(bool completed, const QString &message)
{
    m_scan.reset();
    m_running = false;
    emit scanFinished(completed, message);
    QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

// ---- single operations

void Session::ping(quint8 id, qint32 baud)
{
    enqueue(Operation::Ping, [this, id, baud] {
        stepSetBaud(baud)([this, id, baud](bool ok, const QString &message) {
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
            exchange(ask,
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

void Session::read(const ServoInfo &servo, const QVector<Block> &blocks, ReadSource source)
{
    enqueue(Operation::Read, [this, servo, blocks, source] {
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {stepSetBaud(servo.baud)};
        QVector<Block> toRead = blocks;
        if (toRead.isEmpty())
            toRead = servo.hasTable() ? servo.table().blocks()
                                      : QVector<Block> {{0, RegisterTable::kRawViewSize}};
        for (const Block &block : std::as_const(toRead))
            steps.push_back(stepRead(target, block.address, block.size, source));
        runSteps(std::move(steps), [this, servo](bool ok, const QString &message) {
            finishOperation({Operation::Read,
                             ok,
                             ok ? Tr::tr("Read %1.").arg(servoName(servo)) : message,
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
        const Register *id = registerAt(servo, u"id");
        const Register *baud = registerAt(servo, u"baud_rate");
        if (!servo.hasTable()) {
            finishOperation({Operation::Write,
                             false,
                             Tr::tr("Servo %1 is of an unknown model; its memory is shown "
                                    "read-only and nothing is written to it.")
                                 .arg(servo.id),
                             servo,
                             {}});
            return;
        }
        for (const RegisterWrite &item : writes) {
            const int end = item.address + int(item.bytes.size());
            for (const Register *guarded : {id, baud}) {
                if (guarded && item.address < guarded->end() && guarded->address < end) {
                    finishOperation({Operation::Write,
                                     false,
                                     Tr::tr("The ID and the baud rate change how the servo is "
                                            "reached; use Change ID or Change baud rate."),
                                     servo,
                                     {}});
                    return;
                }
            }
        }
        const Register *lockRegister = registerAt(servo, u"lock");
        const Register *torque = registerAt(servo, u"torque_enable");
        for (const RegisterWrite &item : writes) {
            const bool opensLock = lockRegister && item.address == lockRegister->address;
            const bool calibrates = torque && item.address == torque->address
                && !item.bytes.isEmpty() && quint8(item.bytes.at(0)) == kTorqueCalibrate;
            if (opensLock || calibrates) {
                finishOperation({Operation::Write,
                                 false,
                                 opensLock ? Tr::tr("The EEPROM lock is opened and closed by "
                                                    "ServoBench around each EEPROM write; it "
                                                    "is not written by hand.")
                                           : Tr::tr("Torque enable 128 recalibrates the middle; "
                                                    "use Calibrate middle."),
                                 servo,
                                 {}});
                return;
            }
        }
        auto target = std::make_shared<ServoInfo>(servo);
        const bool eeprom = std::any_of(writes.begin(), writes.end(),
                                        [](const RegisterWrite &w) { return w.eeprom; });
        const int total = int(writes.size()) * 2 + (eeprom ? 2 : 0);
        auto done = std::make_shared<int>(0);
        const auto counted = [this, done, total](Step step) -> Step {
            return [this, done, total, step = std::move(step)](Done next) {
                step([this, done, total, next](bool ok, const QString &message) {
                    emit progress(++*done, total);
                    next(ok, message);
                });
            };
        };
        std::vector<Step> steps {stepSetBaud(servo.baud)};
        if (eeprom)
            steps.push_back(counted(stepLock(target, false)));
        for (const RegisterWrite &item : writes)
            steps.push_back(
                counted(stepWrite(servo.id, item.address, item.bytes, servo.repliesToWrites(),
                                  Tr::tr("Writing address %1").arg(item.address))));
        if (eeprom)
            steps.push_back(counted(stepLock(target, true)));
        for (const RegisterWrite &item : writes)
            steps.push_back(counted(
                stepRead(target, item.address, int(item.bytes.size()), ReadSource::ReadBack)));
        emit progress(0, total);
        runSteps(std::move(steps), [this, servo, target, eeprom](bool ok, const QString &message) {
            if (ok || !eeprom) {
                finishOperation({Operation::Write,
                                 ok,
                                 ok ? Tr::tr("Written and read back.") : message,
                                 servo,
                                 {}});
                return;
            }
            // Never leave the EEPROM open: lock it again, whatever failed.
            runSteps({stepLock(target, true)}, [this, servo, message](bool, const QString &) {
                finishOperation({Operation::Write, false, message, servo, {}});
            });
        });
    });
}

void Session::changeId(const ServoInfo &servo, int newId, const QVector<int> &idsInUse)
{
    enqueue(Operation::ChangeId, [this, servo, newId, idsInUse] {
        OperationResult result {Operation::ChangeId, false, {}, servo, {}};
        const Register *idRegister = registerAt(servo, u"id");
        if (!idRegister) {
            result.message =
                Tr::tr("Servo %1 is of an unknown model; its ID is not changed.").arg(servo.id);
        } else if (newId < 0 || newId > kMaxServoId) {
            result.message = Tr::tr("ID %1 is out of range (0 to %2).").arg(newId).arg(kMaxServoId);
        } else if (newId == servo.id) {
            result.message = Tr::tr("The servo already has ID %1.").arg(newId);
        } else if (idsInUse.contains(newId)) {
            result.message =
                Tr::tr("ID %1 is already in use on this bus; nothing was written.").arg(newId);
        }
        if (!result.message.isEmpty()) {
            finishOperation(result);
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        auto moved = std::make_shared<ServoInfo>(servo);
        moved->id = quint8(newId);
        const quint8 oldId = servo.id;
        auto unlocked = std::make_shared<bool>(false);
        // From the moment the unlock is sent the EEPROM may be open, even if its reply is lost.
        std::vector<Step> steps {stepSetBaud(servo.baud), stepPing(quint8(newId), false, 1),
                                 markDone(unlocked), stepLock(target, false)};
        // The reply may come from the old ID or the new one (spec §13), or not at all.
        steps.push_back(stepAddressWrite(oldId, idRegister->address, quint8(newId), quint8(newId)));
        steps.push_back(stepLock(moved, true));
        steps.push_back(stepIdentify(moved));
        runSteps(std::move(steps),
                 [this, result, moved, target, newId, unlocked](bool ok,
                                                                const QString &message) mutable {
                     if (ok) {
                         result.ok = true;
                         result.servo = *moved;
                         result.message =
                             Tr::tr("Servo %1 now answers as ID %2.").arg(target->id).arg(newId);
                         finishOperation(result);
                         return;
                     }
                     result.message = message;
                     if (!*unlocked) { // refused before anything was written
                         finishOperation(result);
                         return;
                     }
                     // Wherever it is now, its EEPROM is locked again: at the new ID (ignored
                     // when nothing answers there), then at the old one.
                     relock({moved}, [this, result, target]() mutable {
                         runSteps({stepPing(target->id, true, 1), stepLock(target, true)},
                                  [this, result](bool stillThere, const QString &) mutable {
                                      if (stillThere)
                                          result.message +=
                                              u' ' + Tr::tr("The servo still has its old ID.");
                                      finishOperation(result);
                                  });
                     });
                 });
    });
}

void Session::changeBaud(const ServoInfo &servo, qint32 newBaud)
{
    enqueue(Operation::ChangeBaud, [this, servo, newBaud] {
        OperationResult result {Operation::ChangeBaud, false, {}, servo, {}};
        const Register *baudRegister = registerAt(servo, u"baud_rate");
        const std::optional<int> code = feetech::baudCode(newBaud);
        if (!baudRegister)
            result.message = Tr::tr("Servo %1 is of an unknown model; its baud rate is not "
                                    "changed.")
                                 .arg(servo.id);
        else if (!code || *code > baudRegister->maximum)
            result.message =
                Tr::tr("%1 is not a baud rate this servo supports.").arg(baudText(newBaud));
        else if (newBaud == servo.baud)
            result.message = Tr::tr("The servo already runs at %1.").arg(baudText(newBaud));
        if (!result.message.isEmpty()) {
            finishOperation(result);
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        auto moved = std::make_shared<ServoInfo>(servo);
        moved->baud = newBaud;
        auto unlocked = std::make_shared<bool>(false);
        // No servo may already answer with this ID at the new rate: both would then answer
        // every request there.
        std::vector<Step> steps {stepSetBaud(newBaud), stepPing(servo.id, false, 1),
                                 stepSetBaud(servo.baud), markDone(unlocked),
                                 stepLock(target, false)};
        // The answer may already come at the new rate and be lost.
        steps.push_back(stepAddressWrite(servo.id, baudRegister->address, quint8(*code), {}));
        steps.push_back(stepSetBaud(newBaud));
        steps.push_back(stepLock(moved, true));
        steps.push_back(stepIdentify(moved));
        steps.push_back([moved, code](Done next) {
            if (moved->baudCode != *code)
                next(false,
                     Tr::tr("The servo reports baud code %1 instead of %2.")
                         .arg(moved->baudCode)
                         .arg(*code));
            else
                next(true, {});
        });
        runSteps(std::move(steps),
                 [this, result, moved, target, newBaud, unlocked](bool ok,
                                                                  const QString &message) mutable {
                     if (ok) {
                         result.ok = true;
                         result.servo = *moved;
                         result.message = Tr::tr("Servo %1 now runs at %2 and answers there.")
                                              .arg(moved->id)
                                              .arg(baudText(newBaud));
                         finishOperation(result);
                         return;
                     }
                     result.message = message;
                     if (!*unlocked) {
                         finishOperation(result);
                         return;
                     }
                     // Lock it at the new rate in case it got there, then follow it back: maybe it
                     // never took the new rate.
                     relock({moved}, [this, result, target]() mutable {
                         runSteps({stepSetBaud(target->baud), stepPing(target->id, true, 1),
                                   stepLock(target, true)},
                                  [this, result, target](bool stillThere, const QString &) mutable {
                                      result.message += u' '
                                          + (stillThere
                                                 ? Tr::tr("It still answers at %1.")
                                                       .arg(baudText(target->baud))
                                                 : Tr::tr("It answers at neither rate; scan all "
                                                          "baud rates to find it."));
                                      finishOperation(result);
                                  });
                     });
                 });
    });
}

void Session::calibrateMiddle(const ServoInfo &servo)
{
    enqueue(Operation::CalibrateMiddle, [this, servo] {
        const MiddleCalibration method = middleCalibration(servo);
        const Register *offset = registerAt(servo, u"position_offset");
        const Register *torque = registerAt(servo, u"torque_enable");
        if (method == MiddleCalibration::Unsupported || !offset || !torque) {
            finishOperation({Operation::CalibrateMiddle,
                             false,
                             Tr::tr("Middle calibration is not available on this servo "
                                    "(SCS servos have no offset register)."),
                             servo,
                             {}});
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {stepSetBaud(servo.baud), stepLock(target, false)};
        if (method == MiddleCalibration::Instruction)
            steps.push_back(stepInstruction(servo.id, feetech::calibrate(servo.id),
                                            servo.repliesToWrites(), Tr::tr("Middle calibration")));
        else
            steps.push_back(stepWrite(servo.id, torque->address,
                                      QByteArray(1, char(kTorqueCalibrate)),
                                      servo.repliesToWrites(), Tr::tr("Middle calibration")));
        steps.push_back(stepLock(target, true));
        steps.push_back(stepRead(target, offset->address, offset->size, ReadSource::ReadBack));
        runSteps(std::move(steps), [this, servo, target](bool ok, const QString &message) {
            const OperationResult result {Operation::CalibrateMiddle,
                                          ok,
                                          ok ? Tr::tr("The present position is now the middle.")
                                             : message,
                                          servo,
                                          {}};
            if (ok)
                finishOperation(result);
            else
                relock({target}, [this, result] { finishOperation(result); });
        });
    });
}

void Session::factoryReset(const ServoInfo &servo)
{
    enqueue(Operation::FactoryReset, [this, servo] {
        if (!servo.hasTable()) {
            finishOperation(
                {Operation::FactoryReset,
                 false,
                 Tr::tr("Servo %1 is of an unknown model; it is not reset.").arg(servo.id),
                 servo,
                 {}});
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {stepSetBaud(servo.baud), stepLock(target, false),
                                 stepInstruction(servo.id, feetech::recovery(servo.id),
                                                 servo.repliesToWrites(), Tr::tr("Factory reset"))};
        // Factory values include the baud rate: look for the servo at every rate, its old one
        // first.
        steps.push_back([this, target](Done next) {
            QVector<qint32> rates {target->baud};
            for (const qint32 rate : baudRates()) {
                if (rate != target->baud)
                    rates.append(rate);
            }
            searchBauds(target, rates, next);
        });
        steps.push_back(stepIdentify(target));
        steps.push_back(stepLock(target, true));
        runSteps(std::move(steps), [this, target](bool ok, const QString &message) {
            const OperationResult result {
                Operation::FactoryReset,
                ok,
                ok ? Tr::tr("Factory values restored; servo %1 answers at %2.")
                         .arg(target->id)
                         .arg(baudText(target->baud))
                   : message,
                *target,
                {}};
            if (ok)
                finishOperation(result);
            else
                relock({target}, [this, result] { finishOperation(result); });
        });
    });
}

void Session::searchBauds(std::shared_ptr<ServoInfo> servo, QVector<qint32> rates, Done done)
{
    if (rates.isEmpty()) {
        done(false,
             Tr::tr("Servo %1 answers at no baud rate; scan the bus to find it.").arg(servo->id));
        return;
    }
    const qint32 rate = rates.takeFirst();
    runSteps({stepSetBaud(rate), stepPing(servo->id, true, 1)},
             [this, servo, rates, rate, done](bool found, const QString &) {
                 if (found) {
                     servo->baud = rate;
                     done(true, {});
                 } else {
                     searchBauds(servo, rates, done);
                 }
             });
}

void Session::reboot(const ServoInfo &servo)
{
    enqueue(Operation::Reboot, [this, servo] {
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {stepSetBaud(servo.baud)};
        if (const Register *torque = registerAt(servo, u"torque_enable"))
            steps.push_back(stepWrite(servo.id, torque->address, QByteArray(1, char(kTorqueOff)),
                                      servo.repliesToWrites(), Tr::tr("Torque off")));
        steps.push_back(
            stepInstruction(servo.id, feetech::reboot(servo.id), false, Tr::tr("Reboot")));
        auto clock = std::make_shared<QElapsedTimer>();
        steps.push_back([clock](Done next) {
            clock->start();
            next(true, {});
        });
        runSteps(std::move(steps), [this, servo, clock](bool ok, const QString &message) {
            if (!ok) {
                finishOperation({Operation::Reboot, false, message, servo, {}});
                return;
            }
            waitForReboot(servo, clock);
        });
    });
}

void Session::waitForReboot(const ServoInfo &servo, std::shared_ptr<QElapsedTimer> clock)
{
    const quint64 generation = m_generation;
    QTimer::singleShot(m_timing.rebootPollInterval, this, [this, servo, clock, generation] {
        if (generation != m_generation)
            return;
        runSteps({stepPing(servo.id, true, 0)}, [this, servo, clock](bool back, const QString &) {
            if (back) {
                finishOperation({Operation::Reboot,
                                 true,
                                 Tr::tr("Servo %1 restarted and answers again after %2 ms.")
                                     .arg(servo.id)
                                     .arg(clock->elapsed()),
                                 servo,
                                 {}});
            } else if (clock->elapsed() >= m_timing.rebootGiveUp.count()) {
                finishOperation({Operation::Reboot,
                                 false,
                                 Tr::tr("Servo %1 has not answered within %2 ms of the restart.")
                                     .arg(servo.id)
                                     .arg(clock->elapsed()),
                                 servo,
                                 {}});
            } else {
                waitForReboot(servo, clock);
            }
        });
    });
}

void Session::clearStatus(const ServoInfo &servo)
{
    enqueue(Operation::ClearStatus, [this, servo] {
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {stepSetBaud(servo.baud),
                                 stepInstruction(servo.id, feetech::reset(servo.id),
                                                 servo.repliesToWrites(),
                                                 Tr::tr("Clearing the status"))};
        if (const Register *status = registerAt(servo, u"status"))
            steps.push_back(stepRead(target, status->address, status->size, ReadSource::ReadBack));
        runSteps(std::move(steps), [this, servo](bool ok, const QString &message) {
            finishOperation({Operation::ClearStatus,
                             ok,
                             ok ? Tr::tr("Status of servo %1 cleared.").arg(servo.id) : message,
                             servo,
                             {}});
        });
    });
}

} // namespace feetech
