// Request engine: queueing, timeouts, retries, echo suppression, late answers, the default wait
// that follows the slow end of the link's answers, counters and the packet log.
#include "requestengine.h"

#include "transport.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLoggingCategory>

#include <algorithm>
#include <vector>

namespace {

struct RequestEngineTr
{
    Q_DECLARE_TR_FUNCTIONS(RequestEngine)
};

} // namespace

namespace seriallink {

Q_LOGGING_CATEGORY(lcRaw, "servobench.link.raw", QtWarningMsg)

namespace {

// Counters reach the GUI at most this often; a fast bus would otherwise flood it.
constexpr std::chrono::milliseconds kCounterPublishInterval {100};
// How long a frame may take to leave the program before the port counts as stuck.
constexpr std::chrono::milliseconds kWriteStallTimeout {500};
// The default wait follows this many recent answers, with this factor and margin, and grows to
// no more than kLongestGrownWait: a link slower than that is broken, not slow.
constexpr std::size_t kAnswerTimes = 32;
constexpr double kSlowEndFactor = 1.5;
constexpr std::chrono::microseconds kSlowEndMargin {2000};
constexpr std::chrono::microseconds kLongestGrownWait {250000};

TransactionResult failedWith(Failure failure)
{
    TransactionResult result;
    result.failure = failure;
    return result;
}

} // namespace

std::optional<std::chrono::microseconds> slowEnd(const std::deque<std::chrono::microseconds> &times)
{
    if (times.empty())
        return std::nullopt;
    // Asked before every request of a stream: only the one rank is put in place, not all.
    std::vector<std::chrono::microseconds> ranked(times.begin(), times.end());
    const auto slow = ranked.begin() + std::ptrdiff_t((ranked.size() - 1) * 95 / 100);
    std::nth_element(ranked.begin(), slow, ranked.end());
    return *slow;
}

RequestEngine::RequestEngine(Transport &transport, const FrameFormat &format, Describer describer,
                             QObject *parent)
    : QObject(parent)
    , m_transport(&transport)
    , m_framer(format)
    , m_describer(std::move(describer))
{
    // The link's value types cross from a session's worker thread to the GUI in queued signals.
    qRegisterMetaType<PacketLogEntry>();
    qRegisterMetaType<LinkCounters>();
    qRegisterMetaType<ConnectionStatus>();
    connectTransport();
    m_clock.start();
    m_replyTimer = new PreciseTimer(this);
    m_countersTimer = new QTimer(this);
    m_countersTimer->setSingleShot(true);
    m_countersTimer->setInterval(kCounterPublishInterval);
    connect(m_countersTimer, &QTimer::timeout, this, [this] {
        if (m_countersDirty) {
            m_countersDirty = false;
            emit countersChanged(m_counters);
        }
    });
}

void RequestEngine::setTransport(Transport &transport)
{
    if (&transport == m_transport)
        return;
    cancelAll(Failure::Cancelled);
    disconnect(m_transport, nullptr, this, nullptr);
    m_transport = &transport;
    m_framer.discardPending();
    connectTransport();
}

void RequestEngine::connectTransport()
{
    connect(m_transport, &Transport::received, this, &RequestEngine::onReceived);
    connect(m_transport, &Transport::bytesWritten, this, &RequestEngine::onBytesWritten);
}

RequestEngine::~RequestEngine() = default;

void RequestEngine::setEchoMode(EchoMode mode)
{
    m_echoMode = mode;
    m_echoSeen = Decision::Unknown;
    // A new port (or the same one again): what the last one taught about answers is forgotten.
    m_answerTimes.clear();
    m_lateAnswers.forgetLink();
    m_framer.discardPending();
    m_waitedForUnfinished = false;
}

void RequestEngine::submit(Transaction transaction)
{
    const bool leavesAtOnce = transaction.leavesAtOnce;
    if (transaction.priority == Transaction::Priority::Command)
        m_commands.push_back(std::move(transaction));
    else
        m_polls.push_back(std::move(transaction));
    if (leavesAtOnce && m_finishStartsNext && m_state == State::Idle && !m_startingAtOnce) {
        // The finish under way would start it once `done` returns: it starts now instead.
        m_startingAtOnce = true;
        startNext();
        m_startingAtOnce = false;
        return;
    }
    scheduleNext();
}

void RequestEngine::cancelAll(Failure failure)
{
    // Nothing of this link's past answers anything that follows.
    m_lateAnswers.forgetRequests();
    m_framer.discardPending();
    m_waitedForUnfinished = false;
    std::deque<Transaction> ended;
    ended.swap(m_commands);
    for (Transaction &poll : m_polls)
        ended.push_back(std::move(poll));
    m_polls.clear();
    if (m_current) {
        ++m_generation;
        finish(failure);
    }
    for (Transaction &transaction : ended) {
        if (transaction.done)
            transaction.done(failedWith(failure));
    }
}

void RequestEngine::cancelPolls()
{
    std::deque<Transaction> ended;
    ended.swap(m_polls);
    for (Transaction &transaction : ended) {
        if (transaction.done)
            transaction.done(failedWith(Failure::Cancelled));
    }
}

struct RequestEngine::HandlingEvent
{
    explicit HandlingEvent(RequestEngine &engine)
        : engine(engine)
    {
        ++engine.m_eventDepth;
    }
    ~HandlingEvent() { --engine.m_eventDepth; }
    HandlingEvent(const HandlingEvent &) = delete;
    HandlingEvent &operator=(const HandlingEvent &) = delete;
    RequestEngine &engine;
};

void RequestEngine::scheduleNext()
{
    // Queued, so that a `done` callback submitting the next request never recurses; a finish
    // that starts the next one itself, once its callback has returned, needs no pass.
    if (m_nextScheduled || m_state != State::Idle || m_finishStartsNext)
        return;
    m_nextScheduled = true;
    QMetaObject::invokeMethod(this, &RequestEngine::startNext, Qt::QueuedConnection);
}

void RequestEngine::startNext()
{
    m_nextScheduled = false;
    if (m_state != State::Idle)
        return;
    std::deque<Transaction> &queue = !m_commands.empty() ? m_commands : m_polls;
    if (queue.empty())
        return;
    m_current = std::make_unique<Transaction>(std::move(queue.front()));
    queue.pop_front();
    m_attempts = 0;
    if (!m_transport->isOpen()) {
        finish(Failure::LinkDown);
        return;
    }
    send();
}

void RequestEngine::send()
{
    // A reply that missed its timeout may still come; PTK replies name no query, so it must
    // land before the next request goes out, where it is discarded as stray input.
    const qint64 quietFor = m_quietUntilMs - m_clock.elapsed();
    if (quietFor > 0) {
        m_state = State::Settling;
        const quint64 generation = ++m_generation;
        QTimer::singleShot(std::chrono::milliseconds(quietFor), Qt::PreciseTimer, this,
                           [this, generation] {
                               if (generation == m_generation && m_state == State::Settling)
                                   send();
                           });
        return;
    }
    // Whatever is still waiting belongs to an earlier exchange; it must not answer this one.
    // Input the port has not announced yet is taken in first (and dropped as stray while
    // nothing waits), or it would arrive after the request and pass for its answer.
    m_transport->deliverPendingInput();
    const QString beforeRequest = RequestEngineTr::tr("stray input discarded before a request");
    // Also frames still in the framer: an answer that ended its exchange may have had company.
    onInputBetweenRequests(m_transport->discardInput(), beforeRequest);
    if (m_framer.pendingBytes() > 0 && !m_waitedForUnfinished && m_current
        && m_transport->isOpen()) {
        // The start of a frame is in: a late answer whose rest a USB adapter sends in its next
        // packet. Once, the request waits for it, so that it lands while nothing waits.
        m_waitedForUnfinished = true;
        m_state = State::Settling;
        const quint64 generation = ++m_generation;
        QTimer::singleShot(std::chrono::ceil<std::chrono::milliseconds>(replyTimeout()),
                           Qt::PreciseTimer, this, [this, generation] {
                               if (generation == m_generation && m_state == State::Settling)
                                   send();
                           });
        return;
    }
    m_waitedForUnfinished = false;
    if (const auto unfinished = m_framer.flush()) {
        m_counters.discardedBytes += unfinished->bytes.size();
        log(Direction::Stray, unfinished->bytes, beforeRequest);
    }
    m_framer.discardPending();
    if (!m_current || !m_transport->isOpen()) {
        // Reading the port found it gone; whoever handles that ends the transaction.
        if (m_current)
            finish(Failure::LinkDown);
        return;
    }
    ++m_attempts;
    ++m_generation;
    m_state = State::Sending;
    m_writtenBytes = 0;
    m_bytesHeard = 0;
    m_rawSinceSend = 0;
    m_firstHeardUs = -1;
    m_firstRawUs = -1;
    m_lastAcceptedUs = -1;
    // The request before: its echo may still come, behind a USB adapter's packet.
    m_previousRequest = m_lastRequest;
    m_previousEchoConsumed = m_echoConsumed;
    m_echoConsumed = false;
    m_echoUnconfirmed = false;
    m_lateFrameThisAttempt = false;
    m_sawFrame = false;
    m_firstByteDeadline = false;
    m_collected.clear();
    ++m_counters.framesSent;
    if (!m_current->logFailuresOnly)
        log(Direction::Out, m_current->request);
    m_sentAtUs = m_clock.nsecsElapsed() / 1000;
    m_writtenAtUs = m_sentAtUs; // until the port says the frame has left
    m_lastRequest = m_current->request;
    m_transport->write(m_current->request);
    publishCounters();
    // A port that never confirms the write must not hang the queue.
    const quint64 generation = m_generation;
    const auto stalled = wireTime(int(m_current->request.size())) + kWriteStallTimeout;
    QTimer::singleShot(std::chrono::duration_cast<std::chrono::milliseconds>(stalled), this,
                       [this, generation] { onTimeout(generation); });
}

void RequestEngine::onBytesWritten(qint64 count)
{
    const HandlingEvent handling(*this);
    if (m_state != State::Sending)
        return;
    m_writtenBytes += count;
    if (m_writtenBytes < m_current->request.size())
        return;
    // The whole frame has left the program: the clock for the answer starts now. It includes
    // the time the frame, its echo and the reply take on the wire at this baud rate.
    m_state = State::AwaitingReply;
    ++m_generation; // the stall guard of send() no longer applies
    const int requestSize = int(m_current->request.size());
    const int echoSize = echoExpected() ? requestSize : 0;
    const quint64 generation = m_generation;
    // Bytes already in show the frame had left before the port said so (a device that answers
    // at once, a busy event loop): it left when it was written (send() said so), or the
    // answer's latency would come out negative.
    if (m_firstRawUs < 0)
        m_writtenAtUs = m_clock.nsecsElapsed() / 1000;
    m_replyWireTime = wireTime(echoSize);
    if (!m_current->expectsReply() && echoKnown() && m_echoConsumed) {
        finish(Failure::None); // the echo was back before the port said the frame had left
        return;
    }
    std::chrono::microseconds wait;
    if (!m_current->expectsReply() && echoKnown())
        // A frame nothing answers ends when its echo is back: behind a USB adapter that can be
        // a packet later, and it must not come while the next request waits.
        wait = wireTime(requestSize + echoSize) + replyTimeout();
    else if (!m_current->expectsReply())
        wait = wireTime(requestSize + echoSize) + m_timing.writeSettle;
    else if (m_current->afterFirstByte)
        wait = replyTimeout();
    else
        wait = wireTime(requestSize + echoSize + m_current->expectedReplySize) + replyTimeout();
    // Only a scan's wait is cut to the microsecond; every other keeps the whole milliseconds
    // it always had (telemetry's waits are tuned to them).
    if (!m_current->afterFirstByte)
        wait = std::chrono::ceil<std::chrono::milliseconds>(wait);
    m_replyTimer->start(wait, [this, generation] { onTimeout(generation); });
    if (m_firstHeardUs >= 0)
        armAfterFirstByte(); // the answer began before the write was confirmed
}

void RequestEngine::armAfterFirstByte()
{
    if (m_firstByteDeadline || !m_current || !m_current->afterFirstByte
        || m_state != State::AwaitingReply)
        return;
    // From the first byte beyond the echo: an echo alone is no answer begun. While it is not
    // known whether the adapter echoes, the first byte may be either: the answer then gets the
    // echo's wire time on top.
    qint64 fromUs = m_firstHeardUs;
    std::chrono::microseconds echoTime {0};
    if (fromUs < 0 && m_firstRawUs >= 0 && !echoDecided()) {
        fromUs = m_firstRawUs;
        echoTime = wireTime(int(m_current->request.size()));
    }
    if (fromUs < 0)
        return;
    m_firstByteDeadline = true;
    const qint64 elapsed = m_clock.nsecsElapsed() / 1000 - fromUs;
    const quint64 generation = m_generation;
    m_replyTimer->start(*m_current->afterFirstByte + echoTime - std::chrono::microseconds(elapsed),
                        [this, generation] { onTimeout(generation); });
}

void RequestEngine::onReceived(const QByteArray &bytes)
{
    qCDebug(lcRaw) << "rx" << bytes.toHex(' ');
    const HandlingEvent handling(*this);
    if (m_state == State::Idle || m_state == State::Settling || !m_current) {
        // Nothing is waiting for these: a late reply, noise, or an echo after the fact.
        onInputBetweenRequests(bytes, RequestEngineTr::tr("received while no request was waiting"));
        return;
    }
    // The first byte an echo does not account for (one past the request's length, or one that
    // differs from the request) starts the answer: that is when the line answered, even if the
    // bytes never make a frame (two servos at once).
    if (m_firstRawUs < 0)
        m_firstRawUs = m_clock.nsecsElapsed() / 1000;
    if (m_firstHeardUs < 0) {
        const QByteArray &request = m_current->request;
        bool beyondEcho = !echoExpected();
        for (qsizetype i = 0; i < bytes.size() && !beyondEcho; ++i) {
            const qsizetype at = m_rawSinceSend + i;
            beyondEcho = at >= request.size() || bytes.at(i) != request.at(at);
        }
        if (beyondEcho)
            m_firstHeardUs = m_clock.nsecsElapsed() / 1000;
    }
    m_rawSinceSend += int(bytes.size());
    m_framer.append(bytes);
    while (auto item = m_framer.next()) {
        switch (item->kind) {
        case StreamItem::Kind::Frame: {
            const bool isOwnEcho =
                item->bytes == m_current->request && !m_echoConsumed && echoExpected();
            if (isOwnEcho) {
                m_echoConsumed = true;
                // Undecided, a frame the answer could equal proves nothing yet: an answer
                // after it will (and a second such frame is then that answer).
                if (m_echoMode == EchoMode::Auto && m_echoSeen == Decision::Unknown
                    && m_current->answerMayEqualRequest)
                    m_echoUnconfirmed = true;
                else
                    m_echoSeen = Decision::Yes;
                m_counters.echoBytes += item->bytes.size();
                if (!m_current->logFailuresOnly)
                    log(Direction::Echo, item->bytes);
                if (!m_current->expectsReply() && m_state == State::AwaitingReply) {
                    finish(Failure::None);
                    return;
                }
                break;
            }
            if (item->bytes == m_previousRequest && !m_previousEchoConsumed && echoExpected()) {
                // The echo of the request before, come late (behind a USB adapter's packet).
                m_previousEchoConsumed = true;
                m_counters.echoBytes += item->bytes.size();
                log(Direction::Echo, item->bytes, {}, RequestEngineTr::tr("late"));
                break;
            }
            const bool tooSoon = cameTooSoon(int(item->bytes.size()));
            // On a link that answers at once every answer comes too soon: this request's
            // answer is not offered to the ended ones first.
            if (tooSoon && !m_lateAnswers.answersAtOnce() && takeLateAnswer(item->bytes))
                break;
            if (tooSoon && m_lateAnswers.answerOwed(nowUs())) {
                // Sooner than the wire could carry the request and an answer, while an earlier
                // request is owed one: this is that late answer (PTK replies name no query).
                // It says nothing of when this request is answered: no first-byte deadline
                // starts. With nothing owed, the frame is the answer of a device that answers
                // at once.
                m_lateAnswers.answerPaid();
                m_lateFrameThisAttempt = true;
                m_counters.discardedBytes += item->bytes.size();
                ++m_counters.lateReplies;
                log(Direction::Stray, item->bytes,
                    RequestEngineTr::tr(
                        "came sooner than any answer to this request could: a late answer "
                        "to an earlier one, discarded"));
                break;
            }
            if (m_echoMode == EchoMode::Auto && m_echoSeen == Decision::Unknown && !m_sawFrame)
                m_echoSeen = m_echoUnconfirmed ? Decision::Yes : Decision::No;
            m_sawFrame = true;
            heard(int(item->bytes.size()));
            if (m_current->acceptsReply && m_current->acceptsReply(item->bytes)) {
                // Taken though it came sooner than the wire allows: the device answers at once.
                if (tooSoon)
                    m_lateAnswers.answeredAtOnce();
                m_lastAcceptedUs = m_clock.nsecsElapsed() / 1000;
                ++m_counters.repliesOk;
                if (!m_current->logFailuresOnly)
                    log(Direction::In, item->bytes);
                finish(Failure::None, item->bytes);
                return;
            }
            const auto answer = m_current->collectsReplies ? m_current->collectsReplies(item->bytes)
                                                           : Transaction::Answer::NotMine;
            if (answer != Transaction::Answer::NotMine) {
                if (tooSoon)
                    m_lateAnswers.answeredAtOnce();
                m_lastAcceptedUs = m_clock.nsecsElapsed() / 1000;
                if (m_collected.isEmpty())
                    ++m_counters.repliesOk; // one answered request, however many frames
                if (!m_current->logFailuresOnly)
                    log(Direction::In, item->bytes);
                m_collected.append(item->bytes);
                if (answer == Transaction::Answer::Complete) {
                    finish(Failure::None, item->bytes);
                    return;
                }
                break;
            }
            if (takeLateAnswer(item->bytes))
                break;
            // Where several servos may answer (a broadcast a scan listens to), a frame that is
            // no answer of this request is one of theirs: heard, not thrown away in error.
            if (m_current->collisionsExpected) {
                log(Direction::In, item->bytes, {},
                    RequestEngineTr::tr("heard while several may answer"));
                break;
            }
            m_counters.discardedBytes += item->bytes.size();
            log(Direction::In, item->bytes, RequestEngineTr::tr("unexpected frame, ignored"));
            break;
        }
        case StreamItem::Kind::BadChecksum:
            heard(int(item->bytes.size()));
            // A scan asks where several servos may answer at once: garbled answers are what
            // it looks for there (and asks again), not a fault of the link.
            if (m_current->collisionsExpected) {
                log(Direction::In, item->bytes, {},
                    RequestEngineTr::tr("garbled: answers at once"));
                break;
            }
            ++m_counters.checksumErrors;
            log(Direction::In, item->bytes, RequestEngineTr::tr("bad checksum"));
            break;
        case StreamItem::Kind::Garbage:
        case StreamItem::Kind::Incomplete:
            heard(int(item->bytes.size()));
            // Answers at once are what a scan looks for: counted only where they are a fault.
            if (m_current->collisionsExpected) {
                log(Direction::Stray, item->bytes, {},
                    RequestEngineTr::tr("garbled: answers at once"));
                break;
            }
            m_counters.discardedBytes += item->bytes.size();
            log(Direction::Stray, item->bytes, RequestEngineTr::tr("bytes that form no frame"));
            break;
        }
    }
    armAfterFirstByte();
    publishCounters();
}

void RequestEngine::onTimeout(quint64 generation)
{
    const HandlingEvent handling(*this);
    if (generation != m_generation || m_state == State::Idle || !m_current)
        return; // a timer of an exchange that has already ended
    if (m_state == State::AwaitingReply && m_current->expectsReply()) {
        // The answer may be waiting unread; if it completes the exchange, this timer is stale.
        const bool waitedForFirstByte = !m_firstByteDeadline;
        m_transport->deliverPendingInput();
        if (generation != m_generation || m_state == State::Idle || !m_current)
            return;
        if (waitedForFirstByte && m_firstByteDeadline)
            return; // an answer began just now: it gets its own time
    }
    if (m_state == State::AwaitingReply && !m_current->expectsReply()) {
        finish(Failure::None);
        return;
    }
    if (m_state == State::AwaitingReply && !m_collected.isEmpty()) {
        // Several servos were asked and some answered: the caller sees who did not.
        log(Direction::In, {}, {},
            RequestEngineTr::tr("%n answer(s) in time; the others are missing", nullptr,
                                int(m_collected.size())));
        finish(Failure::Timeout);
        return;
    }
    const bool counted = !m_current->silenceExpected;
    if (counted)
        ++m_counters.timeouts;
    const bool retrying = m_attempts <= retryCount() && m_transport->isOpen();
    // Its answer may still come if nothing came (garbled bytes were the device answering), and
    // if a frame was taken for an earlier request's late answer, which may have been this
    // one's, from a device that answers at once: its retry, the same request, may take it, the
    // next request must not. A request that recognises its late answers owes none once it has
    // ended; one that expects silence (a scan, a broadcast) is owed nothing, nor one that never
    // left (the port stalled).
    const bool silent = m_firstHeardUs < 0 && !m_lateFrameThisAttempt;
    if (counted && m_state == State::AwaitingReply
        && (retrying ? silent : (silent || m_lateFrameThisAttempt) && !m_current->lateAnswer))
        m_lateAnswers.oweAnswer(nowUs());
    if (m_timing.settleAfterTimeout)
        m_quietUntilMs = m_clock.elapsed()
            + std::chrono::duration_cast<std::chrono::milliseconds>(replyTimeout()).count();
    const QString noReply =
        RequestEngineTr::tr("no reply (attempt %1 of %2)").arg(m_attempts).arg(retryCount() + 1);
    // One account of errors: a timeout the counters count is an error in the log too (red,
    // in the log's error count); a silence that was asked for (a scan's empty ID, a free ID)
    // is a note.
    if (counted)
        log(Direction::In, {}, noReply);
    else
        log(Direction::In, {}, {},
            RequestEngineTr::tr("%1: silence was expected, not counted as an error",
                                "no reply (attempt …)")
                .arg(noReply));
    if (retrying) {
        if (counted)
            ++m_counters.retries;
        send();
        return;
    }
    if (counted)
        ++m_counters.failures;
    finish(Failure::Timeout);
}

void RequestEngine::finish(Failure failure, const QByteArray &reply)
{
    std::unique_ptr<Transaction> done = std::move(m_current);
    TransactionResult result = failedWith(failure);
    result.reply = reply;
    result.attempts = m_attempts;
    result.frames.swap(m_collected);
    // Bytes that form no frame yet (two servos answering at once) were heard all the same.
    result.bytesHeard = m_bytesHeard + int(m_framer.pendingBytes());
    result.onlyOwnFrame = m_echoUnconfirmed && !m_sawFrame && m_echoSeen == Decision::Unknown;
    const qint64 now = m_clock.nsecsElapsed() / 1000;
    if (m_firstHeardUs >= 0)
        result.latency =
            std::max(std::chrono::microseconds(0),
                     std::chrono::microseconds(m_firstHeardUs - m_writtenAtUs) - m_replyWireTime);
    if (m_lastAcceptedUs >= 0) {
        result.completedAfter = std::max(std::chrono::microseconds(0),
                                         std::chrono::microseconds(m_lastAcceptedUs - m_writtenAtUs)
                                             - m_replyWireTime - wireTime(m_bytesHeard));
        noteAnswerTime(result.completedAfter);
    }
    if (done && done->lateAnswer && failure == Failure::Timeout) {
        LateAnswers::EndedRequest ended;
        ended.lateAnswer = done->lateAnswer;
        ended.writtenAtUs = m_writtenAtUs;
        ended.endedAtUs = now;
        ended.wireTime = m_replyWireTime + wireTime(done->expectedReplySize);
        ended.request = done->request;
        ended.several = bool(done->collectsReplies);
        m_lateAnswers.remember(std::move(ended));
    }
    m_state = State::Idle;
    ++m_generation;
    publishCounters();
    // Ended by what the port or a timer just did, the next transaction (whatever `done` queues
    // first) starts once `done` has returned, in this pass: nothing of this handler runs after
    // a finish. Not while a finish is already starting one, where a lost link would finish the
    // whole queue in one deep recursion.
    const bool startHere = m_eventDepth > 0 && !m_startingAtOnce;
    const bool outerFinishStarts = m_finishStartsNext;
    m_finishStartsNext = startHere;
    if (done && done->done)
        done->done(result);
    m_finishStartsNext = outerFinishStarts;
    if (!startHere) {
        scheduleNext();
        return;
    }
    if (m_state != State::Idle)
        return;
    m_startingAtOnce = true;
    startNext();
    m_startingAtOnce = false;
}

bool RequestEngine::takeLateAnswer(const QByteArray &frame)
{
    const auto after = m_lateAnswers.take(frame, nowUs(), echoExpected());
    if (!after)
        return false;
    noteAnswerTime(*after);
    ++m_counters.lateReplies;
    log(Direction::In, frame, {},
        RequestEngineTr::tr("late answer, %1 ms after its request")
            .arg(double(after->count()) / 1000.0, 0, 'f', 1));
    return true;
}

void RequestEngine::onInputBetweenRequests(const QByteArray &bytes, const QString &why)
{
    // Frame by frame: a late answer is no stray input. What forms no frame yet stays in the
    // framer (the rest of a late answer may follow) until the next request goes out.
    const bool settling = m_state == State::Settling;
    m_framer.append(bytes);
    QByteArray stray;
    while (auto item = m_framer.next()) {
        if (item->kind == StreamItem::Kind::Frame) {
            if (item->bytes == m_lastRequest && !m_echoConsumed && echoExpected()) {
                // The echo of the last request, after its exchange had ended.
                m_echoConsumed = true;
                m_counters.echoBytes += item->bytes.size();
                log(Direction::Echo, item->bytes, {}, RequestEngineTr::tr("late"));
                continue;
            }
            if (takeLateAnswer(item->bytes)) {
                m_lateAnswers.answeredLate();
                continue;
            }
            // Whatever comes while nothing waits may be the answer an earlier request is owed.
            m_lateAnswers.answerPaid();
            if (settling) {
                m_lateAnswers.answeredLate();
                // The engine holds requests back after a timeout precisely for this answer.
                noteAnswerTime(std::max(
                    std::chrono::microseconds(0),
                    std::chrono::microseconds(m_clock.nsecsElapsed() / 1000 - m_writtenAtUs)
                        - m_replyWireTime - wireTime(int(item->bytes.size()))));
                ++m_counters.lateReplies;
                m_counters.discardedBytes += item->bytes.size();
                log(Direction::In, item->bytes, {}, RequestEngineTr::tr("late answer, discarded"));
                continue;
            }
        }
        stray += item->bytes;
    }
    if (!stray.isEmpty()) {
        m_counters.discardedBytes += stray.size();
        log(Direction::Stray, stray, why);
    }
    publishCounters();
}

std::chrono::microseconds RequestEngine::replyTimeout() const
{
    if (m_current && m_current->replyTimeout)
        return *m_current->replyTimeout;
    // Behind an adapter that holds answers back (FTDI's latency timer, an echo and its answer
    // in two of its packets), the set time may be too short: the slow end of the answers says.
    const auto slow = slowEnd(m_answerTimes);
    if (!slow)
        return m_timing.replyTimeout;
    const auto bySlowEnd =
        std::chrono::microseconds(qint64(double(slow->count()) * kSlowEndFactor)) + kSlowEndMargin;
    return std::max<std::chrono::microseconds>(m_timing.replyTimeout,
                                               std::min(bySlowEnd, kLongestGrownWait));
}

void RequestEngine::noteAnswerTime(std::chrono::microseconds time)
{
    // An answer slower than any wait may grow to says nothing about the link's pace (a servo
    // that was busy, bytes measured from a request long gone).
    if (time > kLongestGrownWait)
        return;
    m_answerTimes.push_back(time);
    while (m_answerTimes.size() > kAnswerTimes)
        m_answerTimes.pop_front();
}

void RequestEngine::log(Direction direction, const QByteArray &bytes, const QString &error,
                        const QString &note)
{
    PacketLogEntry entry;
    entry.timestampMs = QDateTime::currentMSecsSinceEpoch();
    entry.direction = direction;
    entry.bytes = bytes;
    entry.error = error;
    entry.summary = note;
    if (!bytes.isEmpty() && m_describer && direction != Direction::Stray) {
        // Only an answer is described after its request (it may have the request's bytes).
        const QString described = m_describer(
            bytes, m_current && direction == Direction::In ? m_current->request : QByteArray());
        entry.summary = note.isEmpty()
            ? described
            : RequestEngineTr::tr("%1 (%2)", "frame summary (note)").arg(described, note);
    }
    emit packetLogged(entry);
}

void RequestEngine::heard(int bytes)
{
    if (m_firstHeardUs < 0)
        m_firstHeardUs = m_clock.nsecsElapsed() / 1000;
    m_bytesHeard += bytes;
}

void RequestEngine::publishCounters()
{
    m_countersDirty = true;
    if (!m_countersTimer->isActive())
        m_countersTimer->start();
}

bool RequestEngine::echoKnown() const
{
    return m_echoMode == EchoMode::On
        || (m_echoMode == EchoMode::Auto && m_echoSeen == Decision::Yes);
}

bool RequestEngine::echoExpected() const
{
    switch (m_echoMode) {
    case EchoMode::On:
        return true;
    case EchoMode::Off:
        return false;
    case EchoMode::Auto:
        return m_echoSeen != Decision::No;
    }
    return false;
}

int RequestEngine::retryCount() const
{
    if (m_current && m_current->retryCount)
        return *m_current->retryCount;
    return m_timing.retryCount;
}

bool RequestEngine::cameTooSoon(int frameBytes) const
{
    if (!m_timing.discardImpossiblyEarlyAnswers)
        return false;
    // The write was asked for at m_sentAtUs: its bytes cannot have left sooner, and a frame is
    // seen only once its last byte is in, however late the program hears of it. A tenth off
    // for clocks that run a little fast.
    const auto earliest =
        (wireTime(int(m_current->request.size())) + wireTime(frameBytes)) * 9 / 10;
    return m_clock.nsecsElapsed() / 1000 - m_sentAtUs < earliest.count();
}

std::chrono::microseconds RequestEngine::wireTime(int bytes) const
{
    const qint32 baud = m_transport->baudRate() > 0 ? m_transport->baudRate() : 9600;
    // 8N1: ten bit times per byte.
    return std::chrono::microseconds(qint64(bytes) * 10 * 1'000'000 / baud);
}

} // namespace seriallink
