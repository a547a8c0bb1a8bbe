// The request engine both servo families share: one transaction in flight, commands before
// polls, timeouts from the moment the frame has left, bounded retries, echo suppression.
#pragma once

#include "link/linktypes.h"
#include "link/precisetimer.h"
#include "link/streamframer.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <QVector>

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace seriallink {

class Transport;

// Single-wire adapters send every byte back. Auto decides from the first answer.
enum class EchoMode { Auto, On, Off };

struct EngineTiming
{
    // Time allowed after the request (and any echo and the reply) has crossed the wire.
    std::chrono::milliseconds replyTimeout {25};
    int retryCount = 2;
    // Extra time a request that expects no reply is given to leave the adapter.
    std::chrono::milliseconds writeSettle {1};
    // After a timeout, hold the next request back for one reply timeout so a late reply lands
    // while nothing waits. PTK needs this (its replies name no query); Feetech replies carry
    // the servo's ID, so a late one is recognised and discarded without the wait.
    bool settleAfterTimeout = true;
    // A frame complete sooner after the request than the request and the frame take to cross
    // the wire answers an earlier request (late): it is discarded. Off only for a test
    // transport that answers instantly.
    bool discardImpossiblyEarlyAnswers = true;
};

enum class Failure { None, Timeout, LinkDown, Cancelled };

struct TransactionResult
{
    Failure failure = Failure::None;
    QByteArray reply;
    int attempts = 0;
    // From the moment the request had left the program to the accepted reply, minus the wire
    // time of the echo and reply: what the adapter, the servo and the OS added.
    // Measured on the first byte that was not an echo, so a garbled answer (two servos at
    // once) still tells how quickly the line answers.
    std::chrono::microseconds latency {0};
    int bytesHeard = 0; // bytes other than the echo that arrived for this request
    // Requests answered by several frames (SYNC READ): every accepted frame, in order of arrival,
    // also those that came before a timeout.
    QVector<QByteArray> frames;
    bool ok() const { return failure == Failure::None; }
};

struct Transaction
{
    enum class Priority { Command, Poll };

    QByteArray request;
    Priority priority = Priority::Command;
    // Whether a received frame is this request's answer; no function: nothing is expected back.
    std::function<bool(const QByteArray &frame)> acceptsReply;
    // For a request several servos answer in turn (SYNC READ), instead of acceptsReply: says of
    // each frame whether it is not an answer, one of the answers, or the last one needed. The
    // transaction ends on the last one, or at the timeout with the answers that came.
    enum class Answer { NotMine, More, Complete };
    std::function<Answer(const QByteArray &frame)> collectsReplies;
    int expectedReplySize = 0; // for the wire-time part of the timeout (all answers together)
    // Overrides of the engine's timing for this transaction (a scan waits less than a write).
    std::optional<std::chrono::microseconds> replyTimeout;
    std::optional<int> retryCount;
    // Set by a scan: replyTimeout is then the whole wait for the first byte of an answer, from
    // the request leaving (the caller has counted the wire time in), and once a byte has come
    // the answer gets this long from that byte to complete, however short the first wait was.
    std::optional<std::chrono::microseconds> afterFirstByte;
    // A scan asks where most IDs are empty and several servos may answer at once: its
    // timeouts and garbled answers say nothing about the link, so the counters skip them.
    bool silenceExpected = false;
    // Frames that went well are counted but not put in the packet log (a telemetry stream of
    // hundreds of frames a second would bury everything else); failures are always logged.
    bool logFailuresOnly = false;
    bool expectsReply() const { return bool(acceptsReply) || bool(collectsReplies); }
    std::function<void(const TransactionResult &)> done;
};

// Lives in the link's worker thread with its transport; everything is driven by signals and
// timers, nothing blocks.
class RequestEngine : public QObject
{
    Q_OBJECT

public:
    // Describes a frame for the packet log; `request` is what was sent last (PTK replies carry
    // no command and mean something only next to their query).
    using Describer = std::function<QString(const QByteArray &frame, const QByteArray &request)>;

    RequestEngine(Transport &transport, const FrameFormat &format, Describer describer,
                  QObject *parent = nullptr);
    ~RequestEngine() override;

    void setTiming(const EngineTiming &timing) { m_timing = timing; }
    const EngineTiming &timing() const { return m_timing; }
    void setEchoMode(EchoMode mode);
    EchoMode echoMode() const { return m_echoMode; }
    bool echoDetected() const { return m_echoSeen == Decision::Yes; }

    void submit(Transaction transaction);
    // Ends every queued transaction (and the one in flight) with `failure`.
    void cancelAll(Failure failure = Failure::Cancelled);
    // Ends queued polls only: a write sequence is about to start.
    void cancelPolls();
    bool isIdle() const { return m_state == State::Idle && m_commands.empty() && m_polls.empty(); }
    int queuedCount() const { return int(m_commands.size() + m_polls.size()); }

    const LinkCounters &counters() const { return m_counters; }
    void resetCounters() { m_counters = {}; }
    // Forget what auto echo detection decided (a new port or adapter).
    void resetEchoDetection() { m_echoSeen = Decision::Unknown; }

signals:
    void packetLogged(const seriallink::PacketLogEntry &entry);
    void countersChanged(const seriallink::LinkCounters &counters);

private:
    // Settling: after a timeout, waiting out a reply that may still arrive late.
    enum class State { Idle, Settling, Sending, AwaitingReply };
    enum class Decision { Unknown, Yes, No };

    void scheduleNext();
    void startNext();
    void send();
    void onBytesWritten(qint64 count);
    void onReceived(const QByteArray &bytes);
    void onTimeout(quint64 generation);
    void finish(Failure failure, const QByteArray &reply = {});
    void log(Direction direction, const QByteArray &bytes, const QString &error = {},
             const QString &note = {});
    void publishCounters();
    void heard(int bytes);
    void armAfterFirstByte();
    bool echoExpected() const;
    std::chrono::microseconds wireTime(int bytes) const;
    // Whether a frame of this size, complete now, came too soon to answer the request in flight.
    bool cameTooSoon(int frameBytes) const;
    std::chrono::microseconds replyTimeout() const;
    int retryCount() const;

    Transport &m_transport;
    StreamFramer m_framer;
    Describer m_describer;
    EngineTiming m_timing;
    EchoMode m_echoMode = EchoMode::Auto;
    LinkCounters m_counters;
    Decision m_echoSeen = Decision::Unknown;

    std::deque<Transaction> m_commands;
    std::deque<Transaction> m_polls;
    std::unique_ptr<Transaction> m_current;
    State m_state = State::Idle;
    int m_attempts = 0;
    qint64 m_writtenBytes = 0;
    qint64 m_sentAtUs = 0; // when the request was handed to the port
    qint64 m_writtenAtUs = 0; // when the whole request had left
    qint64 m_firstHeardUs = -1; // when the first byte other than the echo came
    int m_bytesHeard = 0;
    int m_rawSinceSend = 0; // bytes of any kind since the request went out
    std::chrono::microseconds m_replyWireTime {0};
    bool m_echoConsumed = false;
    bool m_sawFrame = false;
    bool m_firstByteDeadline = false; // afterFirstByte: the wait now runs from the first byte
    QVector<QByteArray> m_collected; // answers so far of a request several servos answer
    QElapsedTimer m_clock;
    qint64 m_quietUntilMs = 0; // no request goes out before this: a late reply may be on its way
    quint64 m_generation = 0; // stale timer firings carry an old generation and are ignored
    bool m_nextScheduled = false;
    bool m_countersDirty = false;
    QTimer *m_countersTimer = nullptr; // a child, so it follows the engine to its thread
    PreciseTimer *m_replyTimer = nullptr; // a child too; a scan waits less than a millisecond
};

} // namespace seriallink
