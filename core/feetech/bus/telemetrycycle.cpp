// Feetech telemetry cycle: plans each cycle by rate and block, reads, counts misses, batches.
#include "telemetrycycle.h"

#include "feetechsessiontr.h"
#include "linksession.h"
#include "transport.h"

#include <QCoreApplication>
#include <QPointer>

#include <algorithm>
#include <limits>
#include <memory>

namespace feetech {

namespace {

// A rate above this is "as fast as the bus allows": Qt timers count whole milliseconds.
constexpr double kFastestTimedRate = 1000.0;
// The rates in the statistics are taken over this much of the recent past.
constexpr qint64 kRateWindowUs = 1'000'000;
// A read waits half as long again as the slow end of the stream's answers, plus a margin.
constexpr double kTailFactor = 1.5;
constexpr std::chrono::microseconds kTailMargin {1000};
// How many answer times the wait follows.
constexpr std::size_t kAnswerTimes = 64;
// At a set rate the reads of a cycle may wait this share of its period between them.
constexpr double kBudgetShare = 0.9;

} // namespace

TelemetryCycle::TelemetryCycle(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

void TelemetryCycle::start(const TelemetryOptions &options)
{
    stop();
    if (options.servos.isEmpty())
        return;
    ++m_generation;
    qRegisterMetaType<feetech::FeedbackSample>();
    qRegisterMetaType<QVector<feetech::FeedbackSample>>();
    qRegisterMetaType<feetech::TelemetryStats>();
    // From a value, not emplace(): clang cannot tell a nested struct with member initialisers
    // default-constructible inside its enclosing class (the fuzz build compiles with clang).
    m_state.emplace(State {});
    State &state = *m_state;
    state.options = options;
    state.startedUs = steadyMicroseconds();
    for (const ServoInfo &servo : options.servos) {
        Servo entry;
        entry.info = servo;
        entry.stats.id = servo.id;
        entry.stats.baud = servo.baud;
        state.servos.push_back(entry);
    }
    state.stats.running = true;
    state.stats.stream = options.stream;
    if (options.rateHz > 0 && options.rateHz <= kFastestTimedRate) {
        state.timer = new QTimer(this);
        state.timer->setTimerType(Qt::PreciseTimer);
        state.timer->setInterval(std::max(1, int(std::lround(1000.0 / options.rateHz))));
        connect(state.timer, &QTimer::timeout, this, &TelemetryCycle::tick);
        state.timer->start();
    }
    if (!m_flushTimer) {
        m_flushTimer = new QTimer(this);
        connect(m_flushTimer, &QTimer::timeout, this, &TelemetryCycle::onBatchDue);
        m_statsTimer = new QTimer(this);
        connect(m_statsTimer, &QTimer::timeout, this, &TelemetryCycle::onStatsDue);
    }
    m_flushTimer->start(m_bus.timing().telemetryBatchInterval);
    m_statsTimer->start(m_bus.timing().telemetryStatsInterval);
    publishStats();
    tick(); // the first cycle at once
}

void TelemetryCycle::stop()
{
    if (!m_state)
        return;
    ++m_generation; // answers still on their way belong to no stream now
    m_flushPostponed = false;
    m_statsPostponed = false;
    flush();
    updateStats();
    m_state->stats.running = false;
    const TelemetryStats last = m_state->stats;
    if (m_state->timer)
        m_state->timer->deleteLater();
    m_state.reset();
    m_flushTimer->stop();
    m_statsTimer->stop();
    emit statsChanged(last);
    // An operation may have been waiting for the cycle that will now never end.
    if (m_cycleEnded)
        QMetaObject::invokeMethod(this, m_cycleEnded, Qt::QueuedConnection);
}

void TelemetryCycle::tick()
{
    if (!m_state)
        return;
    m_state->due = true; // a tick while a cycle runs is not queued twice: the bus is full
    startIfDue();
}

bool TelemetryCycle::startIfDue()
{
    if (!m_state || !m_state->due || m_state->inCycle || (m_busBusy && m_busBusy())
        || !m_bus.link().isOpen())
        return false;
    State &state = *m_state;
    state.due = false;
    state.inCycle = true;
    state.steps.clear();
    state.nextStep = 0;
    const qint64 now = steadyMicroseconds();
    state.cycleStartedUs = now;
    // Servos by baud rate, in the order given; one SYNC READ per rate for those that have it.
    QVector<qint32> bauds;
    for (const Servo &servo : state.servos) {
        if (!bauds.contains(servo.info.baud))
            bauds.append(servo.info.baud);
    }
    for (const qint32 baud : std::as_const(bauds)) {
        QVector<int> synced;
        QVector<int> single;
        QVector<int> probes;
        for (int i = 0; i < int(state.servos.size()); ++i) {
            const Servo &servo = state.servos.at(std::size_t(i));
            if (servo.info.baud != baud)
                continue;
            if (servo.stats.missing) {
                if (servo.nextProbeUs <= now)
                    probes.append(i);
            } else if (supportsSyncRead(servo.info)) {
                synced.append(i);
            } else {
                single.append(i);
            }
        }
        if (synced.isEmpty() && single.isEmpty() && probes.isEmpty())
            continue;
        state.steps.push_back(setBaud(baud));
        // One SYNC READ asks every servo for the same block: one per block the tables give.
        QVector<std::pair<Block, QVector<int>>> byBlock;
        for (const int index : std::as_const(synced)) {
            const Block block = state.servos.at(std::size_t(index)).info.table().feedbackBlock();
            auto group = std::find_if(byBlock.begin(), byBlock.end(), [&](const auto &entry) {
                return entry.first.address == block.address && entry.first.size == block.size;
            });
            if (group == byBlock.end())
                byBlock.append({block, {index}});
            else
                group->second.append(index);
        }
        for (const auto &[block, indexes] : std::as_const(byBlock))
            state.steps.push_back(syncRead(baud, block, indexes));
        for (const int index : std::as_const(single))
            state.steps.push_back(read(index, false));
        for (const int index : std::as_const(probes))
            state.steps.push_back(read(index, true));
    }
    if (state.steps.empty()) {
        // Every servo is missing and none is due to be asked: no cycle, and no busy loop.
        state.inCycle = false;
        if (!state.timer) {
            qint64 nextProbe = std::numeric_limits<qint64>::max();
            for (const Servo &servo : state.servos)
                nextProbe = std::min(nextProbe, servo.nextProbeUs);
            const quint64 stream = m_generation;
            const int waitMs = int(std::clamp<qint64>((nextProbe - now + 999) / 1000, 1, 60000));
            QTimer::singleShot(waitMs, this, [this, stream] {
                if (m_state && stream == m_generation)
                    tick();
            });
        }
        return false;
    }
    runStep();
    return true;
}

void TelemetryCycle::runStep()
{
    if (!m_state)
        return;
    State &state = *m_state;
    if (state.nextStep >= state.steps.size()) {
        endCycle();
        return;
    }
    const auto step = state.steps.at(state.nextStep++);
    step([this] { runStep(); });
}

void TelemetryCycle::endCycle()
{
    State &state = *m_state;
    state.inCycle = false;
    state.steps.clear();
    ++state.stats.cycles;
    const qint64 now = steadyMicroseconds();
    state.history.emplace_back(now, state.stats.samples);
    while (state.history.size() > 2 && state.history.front().first < now - kRateWindowUs)
        state.history.pop_front();
    if (!state.timer)
        state.due = true; // as fast as the bus allows: the next cycle follows at once
    if (state.options.publishEachCycle)
        flush();
    // An operation that waited goes before the next cycle.
    if (m_cycleEnded)
        m_cycleEnded();
    if (m_state && m_state->due && !m_state->inCycle)
        QMetaObject::invokeMethod(
            this, [this] { startIfDue(); }, Qt::QueuedConnection);
}

std::chrono::microseconds TelemetryCycle::allowance(int servos, qint32 baud, int requestBytes,
                                                    int replyBytes) const
{
    using std::chrono::microseconds;
    const SessionTiming &timing = m_bus.timing();
    // The slow end of this stream's answers, half as much again, and a return delay for every
    // servo after the first: a wait that follows the median would end before every answer a
    // USB adapter holds back a while.
    std::optional<microseconds> tail;
    // Before this stream's first answer the wait is the longest: what the port's other
    // exchanges measured (their first bytes) says little of when a whole SYNC READ is in.
    microseconds wait = timing.maximumScanAllowance;
    tail = seriallink::slowEnd(m_state->answerTimes);
    if (tail)
        wait = microseconds(qint64(double(tail->count()) * kTailFactor))
            + kLongestReturnDelay * std::max(0, servos - 1) + kTailMargin;
    // At a set rate a cycle may spend most of its period waiting: nothing else needs the bus
    // then, and an answer waited for is a sample not missed.
    if (m_state->timer && m_state->options.rateHz > 0 && baud > 0) {
        const bool echo = m_bus.link().engine().echoDetected();
        const qint64 wireUs =
            qint64(requestBytes * (echo ? 2 : 1) + replyBytes) * 10'000'000 / baud;
        const qint64 periodUs = qint64(1e6 / m_state->options.rateHz * kBudgetShare);
        const auto readsLeft = qint64(m_state->steps.size() - m_state->nextStep) + 1;
        const qint64 budget =
            (m_state->cycleStartedUs + periodUs - steadyMicroseconds()) / readsLeft - wireUs;
        wait = std::max(wait, microseconds(budget));
    }
    return std::clamp(wait, timing.minimumTelemetryAllowance, timing.maximumScanAllowance);
}

TelemetryCycle::CycleStep TelemetryCycle::setBaud(qint32 baud)
{
    return [this, baud](std::function<void()> next) {
        if (!m_bus.link().setBaudRate(baud))
            m_bus.logNote(FeetechSessionTr::tr("The port cannot be set to %1.").arg(baudText(baud)),
                          true);
        next();
    };
}

TelemetryCycle::CycleStep TelemetryCycle::syncRead(qint32 baud, Block block,
                                                   QVector<int> servoIndexes)
{
    return [this, baud, block, servoIndexes](std::function<void()> next) {
        QVector<quint8> ids;
        for (const int index : servoIndexes)
            ids.append(m_state->servos.at(std::size_t(index)).info.id);
        seriallink::Transaction transaction;
        transaction.request = feetech::syncRead(quint8(block.address), quint8(block.size), ids);
        transaction.priority = seriallink::Transaction::Priority::Poll;
        transaction.retryCount = 0; // the next cycle is the retry
        transaction.expectedReplySize = int(ids.size()) * (kMinimumPacketSize + block.size);
        transaction.replyTimeout = allowance(int(ids.size()), baud, int(transaction.request.size()),
                                             transaction.expectedReplySize);
        transaction.logFailuresOnly = !m_state->options.logEveryFrame;
        transaction.leavesAtOnce = true;
        auto answered = std::make_shared<QVector<bool>>(ids.size(), false);
        // Each answer is decoded once, as it is accepted, and kept for the end of the read.
        auto answers = std::make_shared<QVector<Packet>>();
        const QByteArray sent = transaction.request;
        const int size = block.size;
        transaction.collectsReplies = [sent, ids, size, answered,
                                       answers](const QByteArray &frame) {
            using Answer = seriallink::Transaction::Answer;
            if (frame == sent)
                return Answer::NotMine;
            auto packet = decodePacket(frame);
            if (!packet || packet->parameters.size() != size)
                return Answer::NotMine;
            const auto position = ids.indexOf(packet->id);
            if (position < 0 || answered->at(position))
                return Answer::NotMine;
            (*answered)[position] = true;
            answers->append(std::move(*packet));
            // Servos answer in the order of the list: none answers after the last one.
            const bool last = position == ids.size() - 1
                || std::all_of(answered->begin(), answered->end(), [](bool a) { return a; });
            return last ? Answer::Complete : Answer::More;
        };
        const quint64 link = m_bus.link().generation();
        const quint64 stream = m_generation;
        // An answer after the wait still belongs to its servo: a sample, counted late.
        transaction.lateAnswer = [this, alive = QPointer<TelemetryCycle>(this), link, stream, ids,
                                  size, answered, servoIndexes](const QByteArray &frame,
                                                                std::chrono::microseconds after) {
            if (!alive || link != m_bus.link().generation() || stream != m_generation || !m_state)
                return false;
            const auto packet = decodePacket(frame);
            if (!packet || packet->parameters.size() != size)
                return false;
            const auto position = ids.indexOf(packet->id);
            if (position < 0 || answered->at(position))
                return false;
            (*answered)[position] = true;
            noteAnswerTime(after);
            noteLate(servoIndexes.at(position), *packet);
            return true;
        };
        const auto waited = *transaction.replyTimeout;
        transaction.done = [this, alive = QPointer<TelemetryCycle>(this), link, stream, baud,
                            servoIndexes, ids, answered, answers, waited,
                            next](const seriallink::TransactionResult &result) {
            // Indexes and the cycle belong to the stream that asked: not after a restart, nor
            // once the cycle itself is gone (its link may outlive it).
            if (!alive || link != m_bus.link().generation() || stream != m_generation || !m_state)
                return;
            const qint64 now = steadyMicroseconds();
            const auto noteAnswers = [&] {
                if (!answers->isEmpty()) {
                    m_bus.noteLatency(result.latency);
                    noteAnswerTime(result.completedAfter);
                }
                for (const Packet &packet : std::as_const(*answers))
                    noteAnswer(servoIndexes.at(ids.indexOf(packet.id)), packet, now);
            };
            if (answers->size() == ids.size()) {
                // Everyone answered: the next read leaves first (leavesAtOnce), and these
                // answers are decoded while it crosses the wire; the bus is idle until it goes.
                const qint64 cyclesBefore = m_state->stats.cycles;
                next();
                if (!alive || link != m_bus.link().generation() || stream != m_generation
                    || !m_state)
                    return;
                const bool cycleEnded = m_state->stats.cycles != cyclesBefore;
                noteAnswers();
                if (cycleEnded && m_state->options.publishEachCycle)
                    flush();
                doPostponed();
                return;
            }
            noteAnswers();
            QStringList silent;
            for (int i = 0; i < ids.size(); ++i) {
                if (!answered->at(i)) {
                    noteMiss(servoIndexes.at(i));
                    silent.append(QString::number(ids.at(i)));
                }
            }
            // A note, not an error: the answer may still come late, and a servo that stays
            // silent is reported as stopped once it has missed several cycles.
            if (!silent.isEmpty() && result.failure != seriallink::Failure::LinkDown)
                m_bus.logNote(FeetechSessionTr::tr("SYNC READ at %1: no answer in time from ID %2")
                                  .arg(baudText(baud), silent.join(QStringLiteral(", "))));
            if (silent.isEmpty() || result.failure != seriallink::Failure::Timeout)
                next();
            else
                settleThen(waited, next);
            if (alive)
                doPostponed();
        };
        m_bus.link().engine().submit(std::move(transaction));
    };
}

TelemetryCycle::CycleStep TelemetryCycle::read(int servoIndex, bool probe)
{
    return [this, servoIndex, probe](std::function<void()> next) {
        Servo &servo = m_state->servos.at(std::size_t(servoIndex));
        const quint8 id = servo.info.id;
        if (probe)
            servo.nextProbeUs = steadyMicroseconds()
                + std::chrono::duration_cast<std::chrono::microseconds>(
                      m_state->options.missingProbeInterval)
                      .count();
        seriallink::Transaction transaction;
        const Block block = servo.info.table().feedbackBlock();
        transaction.request = feetech::read(id, quint8(block.address), quint8(block.size));
        transaction.priority = seriallink::Transaction::Priority::Poll;
        transaction.retryCount = 0;
        transaction.expectedReplySize = kMinimumPacketSize + block.size;
        transaction.replyTimeout = allowance(1, servo.info.baud, int(transaction.request.size()),
                                             transaction.expectedReplySize);
        transaction.logFailuresOnly = !m_state->options.logEveryFrame;
        // A servo known to be missing is asked quietly: its silence is already reported.
        transaction.silenceExpected = probe;
        const QByteArray sent = transaction.request;
        auto accepted = std::make_shared<std::optional<Packet>>();
        const int size = block.size;
        transaction.acceptsReply = [sent, id, size, accepted](const QByteArray &frame) {
            if (frame == sent)
                return false;
            auto packet = decodePacket(frame);
            if (!packet || packet->id != id || packet->parameters.size() != size)
                return false;
            *accepted = std::move(packet);
            return true;
        };
        const quint64 link = m_bus.link().generation();
        const quint64 stream = m_generation;
        transaction.lateAnswer = [this, alive = QPointer<TelemetryCycle>(this), link, stream,
                                  servoIndex, id,
                                  size](const QByteArray &frame, std::chrono::microseconds after) {
            if (!alive || link != m_bus.link().generation() || stream != m_generation || !m_state)
                return false;
            const auto packet = decodePacket(frame);
            if (!packet || packet->id != id || packet->parameters.size() != size)
                return false;
            noteAnswerTime(after);
            noteLate(servoIndex, *packet);
            return true;
        };
        const auto waited = *transaction.replyTimeout;
        transaction.done = [this, alive = QPointer<TelemetryCycle>(this), link, stream, servoIndex,
                            accepted, probe, waited,
                            next](const seriallink::TransactionResult &result) {
            if (!alive || link != m_bus.link().generation() || stream != m_generation || !m_state)
                return;
            const std::optional<Packet> packet = result.ok() ? *accepted : std::nullopt;
            if (packet) {
                m_bus.noteLatency(result.latency);
                noteAnswerTime(result.completedAfter);
                noteAnswer(servoIndex, *packet, steadyMicroseconds());
            } else {
                noteMiss(servoIndex);
            }
            if (packet || probe || result.failure != seriallink::Failure::Timeout)
                next();
            else
                settleThen(waited, next);
            if (alive)
                doPostponed();
        };
        m_bus.link().engine().submit(std::move(transaction));
    };
}

void TelemetryCycle::noteAnswer(int servoIndex, const Packet &reply, qint64 steadyUs)
{
    Servo &servo = m_state->servos.at(std::size_t(servoIndex));
    const auto sample = decodeFeedback(servo.info.table(), servo.info.id, servo.info.baud, steadyUs,
                                       reply.parameters, reply.code);
    if (!sample)
        return;
    servo.missesInARow = 0;
    ++servo.stats.samples;
    ++m_state->stats.samples;
    m_batch.append(*sample);
    if (servo.stats.missing) {
        servo.stats.missing = false;
        m_bus.logNote(FeetechSessionTr::tr("%1 answers again; it is back in the cycle.")
                          .arg(feetech::servoName(servo.info)));
        publishStats();
    }
}

void TelemetryCycle::noteMiss(int servoIndex)
{
    Servo &servo = m_state->servos.at(std::size_t(servoIndex));
    ++servo.missesInARow;
    ++servo.stats.missed;
    ++m_state->stats.missed;
    if (!servo.stats.missing && servo.missesInARow >= m_state->options.missesBeforeMissing) {
        servo.stats.missing = true;
        servo.nextProbeUs = steadyMicroseconds()
            + std::chrono::duration_cast<std::chrono::microseconds>(
                  m_state->options.missingProbeInterval)
                  .count();
        // A note: its missed answers are already the log's errors, each counted a timeout.
        m_bus.logNote(FeetechSessionTr::tr(
                          "%1 stopped answering; it is left out of the cycle and asked alone "
                          "every %2 ms until it answers.")
                          .arg(feetech::servoName(servo.info))
                          .arg(m_state->options.missingProbeInterval.count()));
        publishStats();
    }
}

void TelemetryCycle::settleThen(std::chrono::microseconds wait, std::function<void()> next)
{
    // An answer that missed its wait may still be on its way. Asked again at once, the servo
    // would send it while the next request waits, and it would pass for that request's answer.
    // Waiting as long again lets it land while nothing waits: it is then taken as late.
    const quint64 stream = m_generation;
    QTimer::singleShot(std::chrono::ceil<std::chrono::milliseconds>(wait), Qt::PreciseTimer, this,
                       [this, stream, next = std::move(next)] {
                           if (m_state && stream == m_generation)
                               next();
                       });
}

void TelemetryCycle::noteLate(int servoIndex, const Packet &reply)
{
    Servo &servo = m_state->servos.at(std::size_t(servoIndex));
    ++servo.stats.late;
    ++m_state->stats.late;
    // Counted missed when its wait ended; it came after all.
    if (servo.stats.missed > 0) {
        --servo.stats.missed;
        --m_state->stats.missed;
    }
    noteAnswer(servoIndex, reply, steadyMicroseconds());
}

void TelemetryCycle::noteAnswerTime(std::chrono::microseconds time)
{
    if (!m_state)
        return;
    m_state->answerTimes.push_back(time);
    while (m_state->answerTimes.size() > kAnswerTimes)
        m_state->answerTimes.pop_front();
}

void TelemetryCycle::flush()
{
    if (m_batch.isEmpty())
        return;
    QVector<FeedbackSample> batch;
    batch.swap(m_batch);
    emit telemetry(batch, m_state ? m_state->options.stream : 0);
}

void TelemetryCycle::onBatchDue()
{
    if (m_state && m_state->inCycle)
        m_flushPostponed = true;
    else
        flush();
}

void TelemetryCycle::onStatsDue()
{
    if (m_state && m_state->inCycle)
        m_statsPostponed = true;
    else
        publishStats();
}

void TelemetryCycle::doPostponed()
{
    if (m_flushPostponed) {
        m_flushPostponed = false;
        flush();
    }
    if (m_statsPostponed) {
        m_statsPostponed = false;
        publishStats();
    }
}

void TelemetryCycle::publishStats()
{
    if (!m_state)
        return;
    updateStats();
    emit statsChanged(m_state->stats);
}

void TelemetryCycle::updateStats()
{
    State &state = *m_state;
    TelemetryStats &stats = state.stats;
    const qint64 now = steadyMicroseconds();
    stats.elapsedSeconds = double(now - state.startedUs) / 1e6;
    stats.servos.clear();
    for (const Servo &servo : state.servos)
        stats.servos.append(servo.stats);
    // Over the recent past, so a change of rate or a missing servo shows within a second.
    if (state.history.size() >= 2) {
        const auto &first = state.history.front();
        const auto &last = state.history.back();
        const double seconds = double(last.first - first.first) / 1e6;
        if (seconds > 0) {
            stats.cyclesPerSecond = double(state.history.size() - 1) / seconds;
            stats.samplesPerSecond = double(last.second - first.second) / seconds;
        }
    }
}

} // namespace feetech
