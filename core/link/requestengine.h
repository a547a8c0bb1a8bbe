// The request engine both servo families share: one transaction in flight, commands before
// polls, timeouts from the moment the frame has left, bounded retries, echo suppression.
#pragma once

#include "lateanswers.h"
#include "linktypes.h"
#include "precisetimer.h"
#include "streamframer.h"

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
    // Time allowed after the request (and any echo and the reply) has crossed the wire. More
    // when the link's answers have taken longer (a USB adapter's latency timer): half as much
    // again as the slow end of the recent answers, and a margin.
    std::chrono::milliseconds replyTimeout {25};
    int retryCount = 2;
    // Extra time a request that expects no reply is given to leave the adapter.
    std::chrono::milliseconds writeSettle {1};
    // After a timeout, hold the next request back for one reply timeout so a late reply lands
    // while nothing waits. PTK needs this (its replies name no query); Feetech replies carry
    // the servo's ID, so a late one is recognised and discarded without the wait.
    bool settleAfterTimeout = true;
    // A frame complete sooner after the request than the request and the frame take to cross
    // the wire, while an earlier request is still owed an answer, is that late answer: it is
    // discarded. While nothing is owed it is the answer, however soon (a virtual port, an
    // emulator, a USB CDC device that ignores the rate answer at once). Off: never discarded.
    bool discardImpossiblyEarlyAnswers = true;
};

enum class Failure { None, Timeout, LinkDown, Cancelled };

// The 95th percentile of some measured times, none of none: the slow end, which a wait that
// must not end before an answer follows (not the median).
std::optional<std::chrono::microseconds>
slowEnd(const std::deque<std::chrono::microseconds> &times);

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
    // From the moment the request had left to the last accepted answer being complete, minus the
    // wire time of the echo and of the bytes heard: what an answer needs beyond the wire time.
    // Zero when nothing was accepted.
    std::chrono::microseconds completedAfter {0};
    int bytesHeard = 0; // bytes other than the echo that arrived for this request
    // Nothing came but a frame equal to the request, taken for the echo while auto detection
    // had not decided whether the adapter echoes: it may have been the answer (see
    // Transaction::answerMayEqualRequest). A request whose answer cannot equal it decides.
    bool onlyOwnFrame = false;
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
    // The answer may have the request's very bytes (a Feetech PING answered with error bit 0):
    // while auto echo detection is undecided, a frame equal to the request is then no proof of
    // an echo, and the next frame decides.
    bool answerMayEqualRequest = false;
    // Overrides of the engine's timing for this transaction (a scan waits less than a write).
    std::optional<std::chrono::microseconds> replyTimeout;
    std::optional<int> retryCount;
    // Set by a scan: replyTimeout is then the whole wait for the first byte of an answer, from
    // the request leaving (the caller has counted the wire time in), and once a byte has come
    // the answer gets this long from that byte to complete, however short the first wait was.
    std::optional<std::chrono::microseconds> afterFirstByte;
    // A scan asks where most IDs are empty and several servos may answer at once, a flow asks
    // whether an ID is free: their timeouts (and retries) and garbled answers say nothing about
    // the link, so the counters skip them and the log shows them as notes.
    bool silenceExpected = false;
    // Several servos may answer at once (a scan's broadcast, a sweep): garbled answers are what
    // it looks for, logged as notes, not errors.
    bool collisionsExpected = false;
    // Frames that went well are counted but not put in the packet log (a telemetry stream of
    // hundreds of frames a second would bury everything else); failures are always logged.
    bool logFailuresOnly = false;
    // After the transaction has ended without all its answers (a timeout, or a SYNC READ some
    // servos did not answer in time), the engine offers it every frame no request accounts for,
    // for a while: true when the frame is a late answer to it (counted late, not an error).
    // `after`: how long after the request left the frame was complete, beyond the wire time of
    // the request, its echo and the answer it expected. Must not touch the engine.
    std::function<bool(const QByteArray &frame, std::chrono::microseconds after)> lateAnswer;
    bool expectsReply() const { return bool(acceptsReply) || bool(collectsReplies); }
    std::function<void(const TransactionResult &)> done;
    // Submitted from the `done` of the transaction before (a stream's next read), it leaves at
    // once, before that `done` returns: what `done` does after submitting it (decoding the
    // answers) overlaps its time on the wire instead of delaying it.
    bool leavesAtOnce = false;
};

// Lives in the link's worker thread with its transport; everything is driven by signals and
// timers, nothing blocks.
class RequestEngine : public QObject
{
    Q_OBJECT

public:
    // Describes a frame for the packet log; `request` is what was sent last when the frame is
    // its answer, empty otherwise (PTK replies carry no command and mean something only next
    // to their query).
    using Describer = std::function<QString(const QByteArray &frame, const QByteArray &request)>;

    RequestEngine(Transport &transport, const FrameFormat &format, Describer describer,
                  QObject *parent = nullptr);
    ~RequestEngine() override;

    // Talks through `transport` from now on (a shared bus puts its gate between the engine and
    // the port); what was queued or in flight ends Cancelled.
    void setTransport(Transport &transport);
    Transport &transport() const { return *m_transport; }

    void setTiming(const EngineTiming &timing) { m_timing = timing; }
    const EngineTiming &timing() const { return m_timing; }
    void setEchoMode(EchoMode mode);
    EchoMode echoMode() const { return m_echoMode; }
    bool echoDetected() const { return m_echoSeen == Decision::Yes; }
    // Whether a frame equal to the request may be its echo (on, or auto and not known off).
    bool echoExpected() const;
    // Whether the engine knows if the adapter echoes (on, off, or auto and decided): then it
    // tells each echo from an answer with the same bytes, and logs the echo as such.
    bool echoDecided() const
    {
        return m_echoMode != EchoMode::Auto || m_echoSeen != Decision::Unknown;
    }

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

    void connectTransport();
    void scheduleNext();
    void startNext();
    // Where an answer, a write or a time-out ends a transaction, the next one starts at once, in
    // the same pass: a stream's next request leaves without a trip through the event loop.
    struct HandlingEvent;
    void send();
    void onBytesWritten(qint64 count);
    void onReceived(const QByteArray &bytes);
    void onTimeout(quint64 generation);
    // Offers the frame to the transactions that ended lately without all their answers; true
    // when one took it as its late answer (it is then counted and logged as late).
    bool takeLateAnswer(const QByteArray &frame);
    // Bytes heard while no request waits: late answers are taken out, the rest is stray.
    void onInputBetweenRequests(const QByteArray &bytes, const QString &why);
    void finish(Failure failure, const QByteArray &reply = {});
    void log(Direction direction, const QByteArray &bytes, const QString &error = {},
             const QString &note = {});
    void publishCounters();
    void heard(int bytes);
    void armAfterFirstByte();
    bool echoKnown() const; // the adapter echoes, for certain
    std::chrono::microseconds wireTime(int bytes) const;
    // Whether a frame of this size, complete now, came too soon to answer the request in flight.
    bool cameTooSoon(int frameBytes) const;
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    std::chrono::microseconds replyTimeout() const;
    void noteAnswerTime(std::chrono::microseconds time);
    int retryCount() const;

    Transport *m_transport;
    StreamFramer m_framer;
    Describer m_describer;
    EngineTiming m_timing;
    EchoMode m_echoMode = EchoMode::Auto;
    LinkCounters m_counters;
    Decision m_echoSeen = Decision::Unknown;

    // Earlier requests whose answers may still come. A request that recognises its late answers
    // (Transaction::lateAnswer) owes none once it has ended.
    LateAnswers m_lateAnswers;
    // How long the recent answers took beyond their wire time, late ones included.
    std::deque<std::chrono::microseconds> m_answerTimes;

    std::deque<Transaction> m_commands;
    std::deque<Transaction> m_polls;
    std::unique_ptr<Transaction> m_current;
    State m_state = State::Idle;
    int m_attempts = 0;
    qint64 m_writtenBytes = 0;
    qint64 m_sentAtUs = 0; // when the request was handed to the port
    QByteArray m_lastRequest; // its echo may come after its exchange has ended
    QByteArray m_previousRequest; // the one before, whose echo may come during the next
    bool m_previousEchoConsumed = false;
    qint64 m_writtenAtUs = 0; // when the whole request had left
    qint64 m_firstHeardUs = -1; // when the first byte other than the echo came
    qint64 m_firstRawUs = -1; // when the first byte of any kind came, the echo included
    qint64 m_lastAcceptedUs = -1; // when the last answer accepted was complete
    int m_bytesHeard = 0;
    int m_rawSinceSend = 0; // bytes of any kind since the request went out
    std::chrono::microseconds m_replyWireTime {0};
    bool m_echoConsumed = false;
    // Auto echo detection, undecided: a frame equal to a request whose answer may equal it was
    // taken for the echo; the next frame confirms it.
    bool m_echoUnconfirmed = false;
    bool m_lateFrameThisAttempt = false; // a frame was taken for an earlier request's answer
    bool m_sawFrame = false;
    bool m_firstByteDeadline = false; // afterFirstByte: the wait now runs from the first byte
    QVector<QByteArray> m_collected; // answers so far of a request several servos answer
    QElapsedTimer m_clock;
    qint64 m_quietUntilMs = 0; // no request goes out before this: a late reply may be on its way
    quint64 m_generation = 0; // stale timer firings carry an old generation and are ignored
    bool m_nextScheduled = false;
    int m_eventDepth = 0; // inside the handling of an answer, a write or a time-out
    bool m_finishStartsNext = false; // the finish under way starts the next transaction itself
    bool m_startingAtOnce = false; // a next transaction is being started by a finish
    bool m_waitedForUnfinished = false; // a request waited once for the rest of a frame
    bool m_countersDirty = false;
    QTimer *m_countersTimer = nullptr; // a child, so it follows the engine to its thread
    PreciseTimer *m_replyTimer = nullptr; // a child too; a scan waits less than a millisecond
};

} // namespace seriallink
