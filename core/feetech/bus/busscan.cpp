// Feetech bus scan: probe each rate, PING each ID with an adaptive wait, re-ask late answers.
#include "busscan.h"

#include "feetechsessiontr.h"
#include "linksession.h"
#include "porttransport.h"
#include "sharedidcheck.h"

#include <QCoreApplication>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

// After the first byte of the broadcast probe's answers: every servo at the rate answers
// within its return delay, so the rest of the collided bytes are in well before this.
constexpr std::chrono::microseconds kProbeSettle {2000};
// How much longer than an opening probe the closing broadcast may wait for its answers.
constexpr int kClosingPatience = 10;
// How much longer than an opening probe a second look at a rate that seemed silent waits:
// a busy machine (or adapter) can hold one answer back past the first probe's wait.
constexpr int kSecondLookPatience = 2;
// How often one ID may be asked again at one rate: a loaded machine may make a servo late
// more than once, but a servo that is always too late must not keep the scan going.
constexpr int kMostRechecks = 4;

} // namespace

BusScan::BusScan(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{
    m_clock.start();
    // Every byte the link hears during a scan passes through the packet log: answers, frames
    // no exchange was waiting for (a late answer during another servo's identity READ), and
    // input that came while nothing waited (a late answer between two PINGs).
    connect(&m_bus.link(), &seriallink::LinkSession::packetLogged, this,
            [this](const seriallink::PacketLogEntry &entry) {
                if (!m_scan || entry.bytes.isEmpty())
                    return;
                if (entry.direction == seriallink::Direction::Stray)
                    onStrayBytes(entry.bytes);
                else if (entry.direction == seriallink::Direction::In)
                    onFrameHeard(entry.bytes);
            });
}

std::chrono::microseconds BusScan::pingWait(qint32 baud, bool patient) const
{
    const bool echo = m_bus.link().engine().echoDetected();
    const ScanPace none; // measures nothing: its wait is the whole allowance
    return (m_scan && !patient ? m_scan->pace : none).pingWait(baud, echo, m_bus.scanAllowance());
}

std::chrono::microseconds BusScan::lateWindow() const
{
    // Bytes that name no one may be the late answer of any ID whose wait ended this long ago:
    // what a scan waited per ID before it measured its link, so that an answer that wait
    // would have caught is never lost to the shorter one, even garbled.
    const qint32 baud = m_bus.link().transport().baudRate();
    return ScanPace::pingWireTime(baud, true) + std::max(m_bus.scanAllowance(), pingWait(baud));
}

void BusScan::answeredLate(quint8 id)
{
    // The answer of the ID being asked is no late one, and a higher ID was not asked yet.
    if (m_scan && int(id) != m_scan->asking && int(id) <= m_scan->sweptUpTo)
        askAgain(id);
}

void BusScan::heardUnnamed()
{
    if (!m_scan)
        return;
    const qint64 since = m_clock.nsecsElapsed() / 1000 - lateWindow().count();
    for (const auto &[id, endedUs] : m_scan->silent) {
        if (endedUs >= since)
            askAgain(id);
    }
}

void BusScan::askAgain(int id)
{
    if (m_scan->foundIds.contains(id) || m_scan->recheck.contains(id))
        return;
    int &times = m_scan->timesRechecked[id];
    if (times >= kMostRechecks)
        return;
    ++times;
    m_scan->recheck.append(id);
}

void BusScan::onFrameHeard(const QByteArray &frame)
{
    const auto packet = decodePacket(frame);
    // A PING's own bytes may be its echo come late while the engine cannot tell; once it can,
    // it logs echoes as such, and a frame with those bytes is a servo's answer with the
    // voltage bit.
    if (packet && (frame != feetech::ping(packet->id) || m_bus.link().engine().echoDecided()))
        answeredLate(packet->id);
    else if (!packet && !m_scan->probing)
        heardUnnamed();
}

void BusScan::onStrayBytes(const QByteArray &bytes)
{
    // Each delivery on its own: the start of a frame left over from noise must not swallow
    // the late answer that comes next. A frame split across two is unnamed bytes.
    m_strays.discardPending();
    m_strays.append(bytes);
    while (auto item = m_strays.next())
        onFrameHeard(item->bytes);
    if (m_strays.pendingBytes() > 0 && !m_scan->probing)
        heardUnnamed();
}

void BusScan::start(const ScanOptions &options)
{
    State state;
    state.options = options;
    state.options.firstId = std::clamp(options.firstId, 0, int(kMaxServoId));
    state.options.lastId = std::clamp(options.lastId, state.options.firstId, int(kMaxServoId));
    if (state.options.bauds.isEmpty())
        state.options.bauds = {m_bus.link().transport().baudRate()};
    const int ids = state.options.lastId - state.options.firstId + 1;
    state.total = ids * int(state.options.bauds.size());
    m_scan = state;
    emit progress(0, state.total, state.options.bauds.first());
    scanBaud(0);
}

void BusScan::cancel()
{
    if (m_scan)
        m_scan->cancelled = true;
}

void BusScan::scanBaud(int baudIndex)
{
    if (!m_scan)
        return;
    if (m_scan->cancelled) {
        end(false,
            FeetechSessionTr::tr("Scan cancelled; %n servo(s) found before.", nullptr,
                                 m_scan->found));
        return;
    }
    if (baudIndex >= m_scan->options.bauds.size()) {
        if (m_scan->found == 0 && !m_scan->secondLook && !m_scan->silentRates.isEmpty()) {
            lookAgainAtSilentRates();
            return;
        }
        end(true,
            FeetechSessionTr::tr("Scan complete: %n servo(s) found.", nullptr, m_scan->found));
        return;
    }
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    m_scan->foundIds.clear(); // the same ID at another rate is another servo
    m_scan->recheck.clear();
    m_scan->silent.clear();
    m_scan->timesRechecked.clear();
    m_scan->asking = -1;
    m_scan->sweptUpTo = -1;
    m_scan->answeredAtRate = false;
    m_strays.discardPending();
    if (!feetech::baudCode(baud) && baud != m_bus.link().transport().baudRate()) {
        end(false, FeetechSessionTr::tr("%1 is not a Feetech baud rate.").arg(baudText(baud)));
        return;
    }
    m_bus.setBaud(baud)([this, baudIndex, baud](bool ok, const QString &message) {
        if (!ok) {
            end(false, message);
            return;
        }
        probe(baudIndex, 0);
    });
}

void BusScan::probe(int baudIndex, int round)
{
    // Every servo at this rate answers a broadcast PING at once: the bytes collide, but that
    // any come at all says there is something to find, and when they come tells how quickly
    // this adapter answers. A second round gives a second measurement, so that one slow first
    // exchange does not set the pace.
    const auto allowance = std::max(m_bus.timing().probeAllowance, m_bus.scanAllowance());
    broadcastPing(
        m_scan->secondLook ? allowance * kSecondLookPatience : allowance,
        [this, baudIndex, round](const seriallink::TransactionResult &result) {
            if (result.bytesHeard > 0) {
                m_scan->answeredAtRate = true;
                m_bus.noteLatency(result.latency);
                m_scan->pace.noteAnswer(result.latency, m_scan->options.bauds.at(baudIndex));
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
            // Only a Feetech rate can be set again: a port's own other rate is left as it was.
            const qint32 baud = m_scan->options.bauds.at(baudIndex);
            if (!m_scan->secondLook && feetech::baudCode(baud))
                m_scan->silentRates.append(baud);
            emit progress(m_scan->done, m_scan->total, m_scan->options.bauds.at(baudIndex));
            scanBaud(baudIndex + 1);
        });
}

void BusScan::lookAgainAtSilentRates()
{
    // Nobody answered anywhere: before saying so, each rate whose broadcast PING went
    // unanswered gets one more, longer one. It costs a moment only when the scan found nobody,
    // and a servo whose first answer a busy machine held back is not reported missing.
    m_scan->secondLook = true;
    m_scan->options.bauds = m_scan->silentRates;
    const int ids = m_scan->options.lastId - m_scan->options.firstId + 1;
    m_scan->total += ids * int(m_scan->silentRates.size());
    m_scan->silentRates.clear();
    scanBaud(0);
}

void BusScan::broadcastPing(std::chrono::microseconds wait,
                            std::function<void(const seriallink::TransactionResult &)> then)
{
    Exchange ask;
    ask.request = feetech::ping(kBroadcastId);
    ask.listenOnly = true;
    ask.silenceExpected = true;
    ask.replyTimeout = wait;
    // Once the answers begin, the broadcast has what it came for: it ends when they are in.
    ask.afterFirstByte = kProbeSettle;
    ask.retryCount = 0;
    // Its answers collide: bytes that name no one are no late answer of a silent ID.
    m_scan->probing = true;
    m_bus.exchange(
        ask,
        [this, then](const seriallink::TransactionResult &result, const std::optional<Packet> &) {
            if (!m_scan)
                return;
            m_scan->probing = false;
            if (result.failure == seriallink::Failure::LinkDown)
                end(false, failureText(result));
            else
                then(result);
        });
}

void BusScan::closeSweep(int baudIndex)
{
    // The servos answer in the order they were asked: once the answers to a broadcast PING
    // sent after the last ID are in, every late answer of the sweep is in too, heard and
    // named. On a busy machine that is what bounds a late answer, not a fixed wait. It costs
    // one answer time, unless every servo went away meanwhile. The last ID's answer is a late
    // one now too.
    m_scan->asking = -1;
    broadcastPing(m_bus.timing().probeAllowance * kClosingPatience,
                  [this, baudIndex](const seriallink::TransactionResult &) { recheck(baudIndex); });
}

void BusScan::scanId(int baudIndex, int id)
{
    if (!m_scan)
        return;
    if (m_scan->cancelled) {
        scanBaud(baudIndex);
        return;
    }
    if (id > m_scan->options.lastId) {
        if (m_scan->answeredAtRate)
            closeSweep(baudIndex);
        else
            recheck(baudIndex);
        return;
    }
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    m_scan->asking = id;
    m_scan->sweptUpTo = id;
    // A late answer is caught while a later PING waits (or between two), by its ID, and the
    // broadcast that closes the sweep waits for the last ones. Where nothing answered that
    // broadcast (a thorough scan), the last ID gets the patience of a recheck instead. Where
    // something did, the last ID still waits the whole allowance: a late answer of its own
    // would collide with the broadcast's answers and name no one.
    const bool lastId = id == m_scan->options.lastId;
    const auto wait = !lastId    ? std::make_optional(pingWait(baud))
        : m_scan->answeredAtRate ? std::make_optional(pingWait(baud, true))
                                 : std::nullopt;
    scanPing(id, wait, 0,
             [this, baudIndex, id, baud](const seriallink::TransactionResult &result,
                                         const std::optional<Packet> &reply) {
                 const auto advance = [this, baudIndex, id, baud] {
                     if (!m_scan)
                         return;
                     ++m_scan->done;
                     emit progress(m_scan->done, m_scan->total, baud);
                     scanId(baudIndex, id + 1);
                 };
                 if (!reply) {
                     if (result.bytesHeard > 0) {
                         // Something came, but not a clean answer: this ID or one just before
                         // it (answering late) is worth a second, patient look.
                         heardUnnamed();
                         askAgain(id);
                     }
                     const qint64 nowUs = m_clock.nsecsElapsed() / 1000;
                     m_scan->silent.emplace_back(id, nowUs);
                     while (m_scan->silent.front().second < nowUs - lateWindow().count())
                         m_scan->silent.pop_front();
                     advance();
                     return;
                 }
                 m_scan->pace.noteAnswer(result.latency, baud);
                 identifyFound(quint8(id), baud, quint8(reply->code), advance);
             });
}

void BusScan::scanPing(int id, std::optional<std::chrono::microseconds> timeout, int retries,
                       ExchangeDone then)
{
    Exchange ask;
    ask.request = feetech::ping(quint8(id));
    ask.replyId = quint8(id);
    ask.silenceExpected = true;
    ask.replyTimeout = timeout;
    // A short sweep wait is for the first byte only: an answer that has begun gets its time.
    if (timeout)
        ask.afterFirstByte = m_bus.timing().engine.replyTimeout;
    ask.retryCount = retries;
    m_bus.exchange(ask,
                   [this, then](const seriallink::TransactionResult &result,
                                const std::optional<Packet> &reply) {
                       if (!m_scan)
                           return;
                       if (result.failure == seriallink::Failure::LinkDown)
                           end(false, failureText(result));
                       else
                           then(result, reply);
                   });
}

void BusScan::recheck(int baudIndex)
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
    m_scan->asking = id;
    // The engine's own, generous reply timeout this time, and one retry.
    scanPing(id, std::nullopt, 1,
             [this, baudIndex, id, baud](const seriallink::TransactionResult &,
                                         const std::optional<Packet> &reply) {
                 if (!reply)
                     recheck(baudIndex);
                 else
                     identifyFound(quint8(id), baud, quint8(reply->code),
                                   [this, baudIndex] { recheck(baudIndex); });
             });
}

void BusScan::identifyFound(quint8 id, qint32 baud, quint8 statusBits, std::function<void()> then)
{
    auto servo = std::make_shared<ServoInfo>();
    servo->id = id;
    servo->baud = baud;
    m_bus.identify(servo)([this, servo, statusBits, then](bool ok, const QString &) {
        if (!m_scan)
            return;
        // identify() fills the ServoInfo anew from addresses 0-8: the PING's error bits go back.
        servo->statusBits = statusBits;
        if (!ok) {
            // It answers PING but not READ: show it, with nothing guessed about it.
            servo->model.name = FeetechSessionTr::tr("unknown (identity unreadable)");
            servo->model.family.reset();
            reportFound(*servo);
            then();
            return;
        }
        checkShared(servo, then);
    });
}

void BusScan::checkShared(std::shared_ptr<ServoInfo> servo, std::function<void()> then)
{
    // Two servos at one ID answer PING and identity alike; their feedback tells them apart.
    checkSharedId(
        m_bus, *servo, true,
        [this, servo, then](SharedIdVerdict verdict, const seriallink::TransactionResult &result) {
            if (!m_scan)
                return;
            if (verdict == SharedIdVerdict::Failed
                && result.failure == seriallink::Failure::LinkDown) {
                end(false, failureText(result));
                return;
            }
            servo->sharedId = verdict == SharedIdVerdict::Shared;
            reportFound(*servo);
            then();
        });
}

void BusScan::reportFound(const ServoInfo &servo)
{
    ++m_scan->found;
    m_scan->foundIds.append(servo.id);
    m_scan->recheck.removeAll(servo.id);
    emit servoFound(servo);
}

void BusScan::end(bool completed, const QString &message)
{
    m_scan.reset();
    emit finished(completed, message);
}

} // namespace feetech
