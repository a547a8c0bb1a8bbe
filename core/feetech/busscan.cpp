// Feetech bus scan: probe each rate, PING each ID with an adaptive wait, re-ask late answers.
#include "feetech/busscan.h"

#include "link/linksession.h"
#include "link/transport.h"

#include <QCoreApplication>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

} // namespace

BusScan::BusScan(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

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
        end(false, Tr::tr("Scan cancelled; %n servo(s) found before.", nullptr, m_scan->found));
        return;
    }
    if (baudIndex >= m_scan->options.bauds.size()) {
        end(true, Tr::tr("Scan complete: %n servo(s) found.", nullptr, m_scan->found));
        return;
    }
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    m_scan->foundIds.clear(); // the same ID at another rate is another servo
    m_scan->recheck.clear();
    if (!feetech::baudCode(baud) && baud != m_bus.link().transport().baudRate()) {
        end(false, Tr::tr("%1 is not a Feetech baud rate.").arg(baudText(baud)));
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
    Exchange ask;
    ask.request = feetech::ping(kBroadcastId);
    ask.listenOnly = true;
    ask.silenceExpected = true;
    ask.replyTimeout = std::max(m_bus.timing().probeAllowance, m_bus.scanAllowance());
    ask.retryCount = 0;
    m_bus.exchange(
        ask,
        [this, baudIndex, round](const seriallink::TransactionResult &result,
                                 const std::optional<Packet> &) {
            if (!m_scan)
                return;
            if (result.failure == seriallink::Failure::LinkDown) {
                end(false, failureText(result));
                return;
            }
            if (result.bytesHeard > 0) {
                m_bus.noteLatency(result.latency);
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
            emit progress(m_scan->done, m_scan->total, m_scan->options.bauds.at(baudIndex));
            scanBaud(baudIndex + 1);
        });
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
        recheck(baudIndex);
        return;
    }
    const qint32 baud = m_scan->options.bauds.at(baudIndex);
    // A late answer is caught while the next PING waits; the last ID of a rate has no next
    // PING, so it gets the patience of a recheck (the engine's own reply timeout).
    const bool lastOfRate = id == m_scan->options.lastId;
    scanPing(id, lastOfRate ? std::nullopt : std::make_optional(m_bus.scanAllowance()), 0,
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
                     // Something came, but not a clean answer: worth a second, patient look.
                     if (result.bytesHeard > 0 && !m_scan->recheck.contains(id))
                         m_scan->recheck.append(id);
                     advance();
                     return;
                 }
                 identifyFound(quint8(id), baud, advance);
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
    ask.retryCount = retries;
    // A servo that answered after its wait ended shows up now, named: ask it again later.
    ask.otherFrame = [this, id](const Packet &packet) {
        if (m_scan && packet.id < id && !m_scan->foundIds.contains(packet.id)
            && !m_scan->recheck.contains(packet.id))
            m_scan->recheck.append(packet.id);
    };
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

void BusScan::identifyFound(quint8 id, qint32 baud, std::function<void()> then)
{
    auto servo = std::make_shared<ServoInfo>();
    servo->id = id;
    servo->baud = baud;
    m_bus.identify(servo)([this, servo, then](bool ok, const QString &) {
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

void BusScan::end(bool completed, const QString &message)
{
    m_scan.reset();
    emit finished(completed, message);
}

} // namespace feetech
