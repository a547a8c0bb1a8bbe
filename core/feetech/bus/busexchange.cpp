// Feetech bus steps: exchanges with a decoded answer, locked writes, reads, pings, relocking.
#include "busexchange.h"

#include "feetechsessiontr.h"
#include "feetechvalue.h"
#include "servoparameters.h"

#include "linksession.h"
#include "transport.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QPointer>

#include <algorithm>

namespace feetech {

namespace {

constexpr std::size_t kLatencyWindow = 8;
// Blocks at most this far apart are read in one READ: at any rate, 16 unused bytes take less
// wire time than a second READ (14 bytes of request and reply framing) and its turnaround.
constexpr int kLongestGapReadThrough = 16;
// The most data one status packet carries (the SDKs' 250-byte packets).
constexpr int kLongestRead = kMaxPacketSize - kMinimumPacketSize;

// The blocks in groups that one READ each covers.
QVector<QVector<Block>> readGroups(const QVector<Block> &blocks)
{
    QVector<QVector<Block>> groups;
    for (const Block &block : blocks) {
        if (!groups.isEmpty()) {
            QVector<Block> &group = groups.last();
            const int groupEnd = group.last().address + group.last().size;
            const int gap = block.address - groupEnd;
            if (gap >= 0 && gap <= kLongestGapReadThrough
                && block.address + block.size - group.first().address <= kLongestRead) {
                group.append(block);
                continue;
            }
        }
        groups.append({block});
    }
    return groups;
}

qint64 servoKey(const ServoInfo &servo)
{
    return qint64(servo.baud) * 256 + servo.id;
}

Exchange readRequest(const ServoInfo &servo, int address, int size, ReadSource source)
{
    Exchange ask;
    ask.request = feetech::read(servo.id, quint8(address), quint8(size));
    ask.replyId = servo.id;
    ask.replyDataSize = size;
    if (source == ReadSource::Refresh)
        ask.priority = seriallink::Transaction::Priority::Poll;
    return ask;
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

QString failureText(const seriallink::TransactionResult &result)
{
    switch (result.failure) {
    case seriallink::Failure::None:
        return {};
    case seriallink::Failure::Timeout:
        return FeetechSessionTr::tr("no reply after %n attempt(s)", nullptr, result.attempts);
    case seriallink::Failure::LinkDown:
        return FeetechSessionTr::tr("the port is closed");
    case seriallink::Failure::Cancelled:
        return FeetechSessionTr::tr("cancelled");
    }
    return {};
}

OperationFailure failureKind(const seriallink::TransactionResult &result)
{
    switch (result.failure) {
    case seriallink::Failure::None:
        return OperationFailure::None;
    case seriallink::Failure::Timeout:
        return OperationFailure::NoAnswer;
    case seriallink::Failure::LinkDown:
        return OperationFailure::LinkLost;
    case seriallink::Failure::Cancelled:
        return OperationFailure::Stopped;
    }
    return OperationFailure::None;
}

static QString readFailure(int address, int size, const seriallink::TransactionResult &result)
{
    return FeetechSessionTr::tr("Reading %1 bytes at address %2: %3")
        .arg(size)
        .arg(address)
        .arg(failureText(result));
}

const Register *registerAt(const ServoInfo &servo, QStringView key)
{
    return servo.hasTable() ? servo.table().find(key) : nullptr;
}

QString servoName(const ServoInfo &servo)
{
    return FeetechSessionTr::tr("servo %1 at %2").arg(servo.id).arg(baudText(servo.baud));
}

BusExchange::BusExchange(seriallink::LinkSession &link, const SessionTiming &timing,
                         QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_timing(timing)
{ }

std::optional<std::chrono::microseconds> BusExchange::measuredLatency() const
{
    if (m_latencies.empty())
        return std::nullopt;
    // The median of the recent answers: one slow outlier (a busy OS, the first exchange on a
    // fresh port) must not slow a whole scan down.
    std::vector<std::chrono::microseconds> sorted(m_latencies.begin(), m_latencies.end());
    std::sort(sorted.begin(), sorted.end());
    return sorted.at((sorted.size() - 1) / 2);
}

std::chrono::microseconds BusExchange::scanAllowance() const
{
    const auto latency = measuredLatency();
    if (!latency)
        return m_timing.initialScanAllowance;
    const auto scaled =
        std::chrono::microseconds(qint64(double(latency->count()) * m_timing.scanLatencyFactor));
    return std::clamp(scaled + kLongestReturnDelay, m_timing.minimumScanAllowance,
                      m_timing.maximumScanAllowance);
}

void BusExchange::noteLatency(std::chrono::microseconds latency)
{
    m_latencies.push_back(latency);
    while (m_latencies.size() > kLatencyWindow)
        m_latencies.pop_front();
}

void BusExchange::runSteps(std::vector<Step> steps, StepDone done)
{
    for (Step &step : steps)
        step = [this, step = std::move(step)](StepDone next) {
            m_stepFailure = OperationFailure::None;
            step(std::move(next));
        };
    const quint64 generation = m_link.generation();
    auto runner = std::make_shared<StepRunner>(
        std::move(steps), [this, generation, done = std::move(done)](bool ok, const QString &m) {
            if (generation == m_link.generation()) // not after a close or a lost port
                done(ok, m);
        });
    runner->run();
}

void BusExchange::fail(const StepDone &next, OperationFailure kind, const QString &message)
{
    m_stepFailure = kind;
    next(false, message);
}

void BusExchange::exchange(const Exchange &request, ExchangeDone done)
{
    seriallink::Transaction transaction;
    transaction.request = request.request;
    transaction.priority = request.priority;
    transaction.replyTimeout = request.replyTimeout;
    transaction.retryCount = request.retryCount;
    transaction.afterFirstByte = request.afterFirstByte;
    transaction.silenceExpected = request.silenceExpected;
    transaction.collisionsExpected = request.silenceExpected; // scans, probes: servos at once
    if (request.listenOnly) {
        transaction.acceptsReply = [](const QByteArray &) {
            return false;
        };
        transaction.expectedReplySize = kMinimumPacketSize;
    }
    // The frame the engine accepts is decoded here, once, and that packet is what `done` gets.
    auto accepted = std::make_shared<std::optional<Packet>>();
    if (!request.listenOnly && request.replyId) {
        const QByteArray &sent = request.request;
        const quint8 id = *request.replyId;
        const std::optional<quint8> alternate = request.alternateReplyId;
        const int size = request.replyDataSize;
        // An answer whose error byte equals the instruction has the request's very bytes when
        // neither carries data: a PING, RESET, REBOOT or calibration answered with those error
        // bits (a PING with the voltage bit: FF FF id 02 01 ..). The engine accounts for the
        // echo and hands such a frame here only when it is no echo. (A READ of two bytes whose
        // data happen to equal its address and length could too; taking its echo for an answer
        // would be worse than missing that one.)
        const auto asStatus = decodePacket(sent);
        transaction.answerMayEqualRequest = asStatus && asStatus->parameters.isEmpty() && size == 0
            && (asStatus->id == id || (alternate && asStatus->id == *alternate));
        const auto other = request.otherFrame;
        transaction.acceptsReply = [id, alternate, size, other, accepted](const QByteArray &frame) {
            auto packet = decodePacket(frame);
            const bool answer = packet
                && (packet->id == id || (alternate && packet->id == *alternate))
                && packet->parameters.size() == size;
            if (packet && !answer && other)
                other(*packet);
            if (answer)
                *accepted = std::move(packet);
            return answer;
        };
        transaction.expectedReplySize = kMinimumPacketSize + size;
        // An answer that comes after the wait is counted late, and tells how slow the line is.
        transaction.lateAnswer = [this, alive = QPointer<BusExchange>(this),
                                  link = m_link.generation(), id, alternate,
                                  size](const QByteArray &frame, std::chrono::microseconds after) {
            if (!alive || link != m_link.generation())
                return false;
            const auto packet = decodePacket(frame);
            if (!packet || packet->parameters.size() != size
                || !(packet->id == id || (alternate && packet->id == *alternate)))
                return false;
            noteLatency(after);
            return true;
        };
    }
    const quint64 generation = m_link.generation();
    // The engine may end the transaction after this object is gone (a link destroyed last).
    transaction.done = [this, alive = QPointer<BusExchange>(this), generation, accepted, request,
                        done = std::move(done)](const seriallink::TransactionResult &result) {
        if (!alive || generation != m_link.generation())
            return;
        if (result.failure == seriallink::Failure::Timeout && result.onlyOwnFrame
            && request.replyId) {
            settleOwnFrame(request, result, done);
            return;
        }
        std::optional<Packet> packet;
        if (result.ok() && !result.reply.isEmpty())
            packet = std::move(*accepted);
        if (packet)
            noteLatency(result.latency);
        done(result, packet);
    };
    m_link.engine().submit(std::move(transaction));
}

void BusExchange::settleOwnFrame(const Exchange &request,
                                 const seriallink::TransactionResult &result, ExchangeDone done)
{
    // Nothing came but the request's own bytes, and whether the adapter echoes is not known
    // yet: the echo, or the answer of a servo whose error bits equal the instruction (a PING
    // with the voltage bit). A READ of one byte, whose answer cannot equal it, tells: answered
    // with no echo before it, the servo is there and those bytes were its answer.
    Exchange decide;
    decide.request = feetech::read(*request.replyId, 0, 1);
    decide.replyId = request.replyId;
    decide.replyDataSize = 1;
    decide.priority = request.priority;
    decide.silenceExpected = request.silenceExpected;
    decide.retryCount = 0;
    exchange(decide,
             [this, request, result, done = std::move(done)](
                 const seriallink::TransactionResult &decided, const std::optional<Packet> &reply) {
                 if (decided.failure == seriallink::Failure::LinkDown
                     || decided.failure == seriallink::Failure::Cancelled) {
                     done(decided, std::nullopt);
                     return;
                 }
                 // Answered, the servo is there; the READ also showed whether the adapter echoes.
                 // Only where it does not were those bytes the servo's answer.
                 if (!reply || m_link.engine().echoExpected()) {
                     done(result, std::nullopt);
                     return;
                 }
                 seriallink::TransactionResult answered = result;
                 answered.failure = seriallink::Failure::None;
                 answered.reply = request.request;
                 answered.onlyOwnFrame = false;
                 answered.latency = decided.latency;
                 done(answered, decodePacket(request.request));
             });
}

Step BusExchange::setBaud(qint32 baud)
{
    return [this, baud](StepDone next) {
        if (!m_link.setBaudRate(baud)) {
            fail(next, OperationFailure::PortSetting,
                 FeetechSessionTr::tr("The port cannot be set to %1.").arg(baudText(baud)));
            return;
        }
        next(true, {});
    };
}

Step BusExchange::write(quint8 id, int address, const QByteArray &bytes, bool expectReply,
                        const QString &what)
{
    return instruction(id, feetech::write(id, quint8(address), bytes), expectReply, what);
}

Step BusExchange::instruction(quint8 id, const QByteArray &request, bool expectReply,
                              const QString &what)
{
    return [this, id, request, expectReply, what](StepDone next) {
        Exchange ask;
        ask.request = request;
        if (expectReply)
            ask.replyId = id;
        exchange(ask,
                 [this, what, next](const seriallink::TransactionResult &result,
                                    const std::optional<Packet> &) {
                     if (!result.ok())
                         fail(next, failureKind(result),
                              FeetechSessionTr::tr("%1: %2").arg(what, failureText(result)));
                     else
                         next(true, {});
                 });
    };
}

std::vector<Step>
BusExchange::readValues(std::shared_ptr<ServoInfo> servo, const QStringList &keys,
                        std::function<void(const QString &key, qint32 value)> seen)
{
    std::vector<Step> steps;
    const RegisterTable &table = servo->table();
    for (const QString &key : keys) {
        const Register *reg = table.find(key);
        if (!reg)
            continue;
        const ValueFormat format = table.format(*reg);
        steps.push_back(read(servo, reg->address, reg->size, ReadSource::ReadBack,
                             [seen, key, format](const QByteArray &bytes) {
                                 seen(key, decodeValue(bytes, format));
                             }));
    }
    return steps;
}

Step BusExchange::writeValue(std::shared_ptr<ServoInfo> servo, const QString &key, qint32 value,
                             std::function<void()> sending)
{
    QString error;
    const auto writes = encodeWrites(servo->table(), {{key, value}}, &error);
    if (!writes || writes->size() != 1)
        return [this, error](StepDone next) {
            fail(next, OperationFailure::InvalidRequest, error);
        };
    const RegisterWrite registerWrite = writes->first();
    return [this, servo, registerWrite, key, sending](StepDone next) {
        sending();
        write(servo->id, registerWrite.address, registerWrite.bytes, servo->repliesToWrites(),
              FeetechSessionTr::tr("Writing %1").arg(key))(next);
    };
}

Step BusExchange::lock(std::shared_ptr<ServoInfo> servo, bool locked)
{
    return [this, servo, locked](StepDone next) {
        const Register *lock = registerAt(*servo, u"lock");
        if (!lock) {
            fail(next, OperationFailure::Unsupported,
                 FeetechSessionTr::tr("The servo's model has no known EEPROM lock register."));
            return;
        }
        const QString what = locked ? FeetechSessionTr::tr("Locking the EEPROM")
                                    : FeetechSessionTr::tr("Unlocking the EEPROM");
        write(servo->id, lock->address, QByteArray(1, char(locked ? 1 : 0)),
              servo->repliesToWrites(), what)(next);
    };
}

Step BusExchange::read(std::shared_ptr<ServoInfo> servo, int address, int size, ReadSource source,
                       std::function<void(const QByteArray &bytes)> seen)
{
    return [this, servo, address, size, source, seen](StepDone next) {
        exchange(readRequest(*servo, address, size, source),
                 [this, servo, address, size, source, seen,
                  next](const seriallink::TransactionResult &result,
                        const std::optional<Packet> &reply) {
                     if (!reply) {
                         fail(next, failureKind(result), readFailure(address, size, result));
                         return;
                     }
                     emit memoryRead(servo->id, servo->baud, address, reply->parameters, source,
                                     reply->code);
                     if (seen)
                         seen(reply->parameters);
                     next(true, {});
                 });
    };
}

Step BusExchange::readBlocks(std::shared_ptr<ServoInfo> servo, QVector<Block> blocks,
                             ReadSource source)
{
    return [this, servo, blocks, source](StepDone next) {
        std::vector<Step> steps;
        if (m_refuseLongReads.contains(servoKey(*servo))) {
            for (const Block &block : blocks)
                steps.push_back(read(servo, block.address, block.size, source));
        } else {
            for (const QVector<Block> &group : readGroups(blocks))
                steps.push_back(readSpan(servo, group, source));
        }
        runSteps(std::move(steps), std::move(next));
    };
}

Step BusExchange::readSpan(std::shared_ptr<ServoInfo> servo, QVector<Block> blocks,
                           ReadSource source)
{
    if (blocks.size() == 1)
        return read(servo, blocks.first().address, blocks.first().size, source);
    return [this, servo, blocks, source](StepDone next) {
        const int address = blocks.first().address;
        const int size = blocks.last().address + blocks.last().size - address;
        exchange(
            readRequest(*servo, address, size, source),
            [this, servo, blocks, source, address, size, next](
                const seriallink::TransactionResult &result, const std::optional<Packet> &reply) {
                if (reply) {
                    for (const Block &block : blocks)
                        emit memoryRead(servo->id, servo->baud, block.address,
                                        reply->parameters.mid(block.address - address, block.size),
                                        source, reply->code);
                    next(true, {});
                    return;
                }
                if (result.failure != seriallink::Failure::Timeout) {
                    fail(next, failureKind(result), readFailure(address, size, result));
                    return;
                }
                // Firmware that answers short READs only: remembered once the blocks
                // alone are answered (a servo that answers nothing proves nothing).
                std::vector<Step> steps;
                for (const Block &block : blocks)
                    steps.push_back(read(servo, block.address, block.size, source));
                const qint64 key = servoKey(*servo);
                runSteps(std::move(steps), [this, key, next](bool ok, const QString &message) {
                    if (ok)
                        m_refuseLongReads.insert(key);
                    next(ok, message);
                });
            });
    };
}

Step BusExchange::identify(std::shared_ptr<ServoInfo> servo)
{
    return [this, servo](StepDone next) {
        Exchange ask;
        ask.request = feetech::read(servo->id, kIdentityAddress, kIdentitySize);
        ask.replyId = servo->id;
        ask.replyDataSize = kIdentitySize;
        exchange(ask,
                 [this, servo, next](const seriallink::TransactionResult &result,
                                     const std::optional<Packet> &reply) {
                     const auto info = reply
                         ? servoInfoFromIdentity(servo->id, servo->baud, reply->parameters)
                         : std::nullopt;
                     if (!info) {
                         fail(next, reply ? OperationFailure::BadReply : failureKind(result),
                              FeetechSessionTr::tr("Reading the identity of servo %1: %2")
                                  .arg(servo->id)
                                  .arg(failureText(result)));
                         return;
                     }
                     *servo = *info;
                     next(true, {});
                 });
    };
}

Step BusExchange::ping(quint8 id, bool mustAnswer, int retries)
{
    return [this, id, mustAnswer, retries](StepDone next) {
        Exchange ask;
        ask.request = feetech::ping(id);
        ask.replyId = id;
        ask.retryCount = retries;
        // Asking whether an ID is free hopes for silence: none is a link error.
        ask.silenceExpected = !mustAnswer;
        exchange(ask,
                 [this, id, mustAnswer, next](const seriallink::TransactionResult &result,
                                              const std::optional<Packet> &reply) {
                     if (result.failure == seriallink::Failure::LinkDown
                         || result.failure == seriallink::Failure::Cancelled)
                         fail(next, failureKind(result), failureText(result));
                     else if (mustAnswer && !reply)
                         fail(next, OperationFailure::NoAnswer,
                              FeetechSessionTr::tr("Servo %1 does not answer.").arg(id));
                     else if (!mustAnswer && reply)
                         fail(next, OperationFailure::IdInUse,
                              FeetechSessionTr::tr("ID %1 is already in use on this bus.").arg(id));
                     else
                         next(true, {});
                 });
    };
}

void BusExchange::relock(std::vector<std::shared_ptr<ServoInfo>> places, std::function<void()> done)
{
    if (places.empty()) {
        done();
        return;
    }
    const std::shared_ptr<ServoInfo> place = places.front();
    places.erase(places.begin());
    // Best effort: a place where nothing answers is simply passed.
    runSteps({setBaud(place->baud), lock(place, true)},
             [this, places, done](bool, const QString &) { relock(places, done); });
}

Step BusExchange::addressWrite(quint8 id, int address, quint8 value,
                               std::optional<quint8> alternateReplyId)
{
    return [this, id, address, value, alternateReplyId](StepDone next) {
        Exchange ask;
        ask.request = feetech::write(id, quint8(address), QByteArray(1, char(value)));
        ask.replyId = id;
        ask.alternateReplyId = alternateReplyId;
        ask.retryCount = 0; // a second write would go to an address that may have changed
        exchange(
            ask,
            [this, next](const seriallink::TransactionResult &r, const std::optional<Packet> &) {
                // No answer is not a failure: the servo may already listen elsewhere. Whether
                // the write took is decided by finding it at the new address.
                if (r.failure == seriallink::Failure::LinkDown
                    || r.failure == seriallink::Failure::Cancelled)
                    fail(next, failureKind(r), failureText(r));
                else
                    next(true, {});
            });
    };
}

Step BusExchange::markDone(std::shared_ptr<bool> flag)
{
    return [flag](StepDone next) {
        *flag = true;
        next(true, {});
    };
}

Step BusExchange::tolerant(Step step)
{
    return [step = std::move(step)](StepDone next) {
        step([next](bool, const QString &) { next(true, {}); });
    };
}

void BusExchange::searchBauds(std::shared_ptr<ServoInfo> servo, QVector<qint32> rates,
                              StepDone done)
{
    if (rates.isEmpty()) {
        fail(done, OperationFailure::NoAnswer,
             FeetechSessionTr::tr("Servo %1 answers at no baud rate; scan the bus to find it.")
                 .arg(servo->id));
        return;
    }
    const qint32 rate = rates.takeFirst();
    runSteps({setBaud(rate), ping(servo->id, true, 1)},
             [this, servo, rates, rate, done](bool found, const QString &) {
                 if (found) {
                     servo->baud = rate;
                     done(true, {});
                 } else {
                     searchBauds(servo, rates, done);
                 }
             });
}

void BusExchange::logNote(const QString &note, bool error)
{
    m_link.logNote(note, error);
}

} // namespace feetech
