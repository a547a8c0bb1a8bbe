// Feetech session, live part: the telemetry cycle between operations, torque off for the whole
// bus, and SYNC WRITE.
#include "feetech/feetechsession.h"

#include "link/transport.h"

#include <QCoreApplication>
#include <QDateTime>

#include <algorithm>
#include <limits>

namespace feetech {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

constexpr int kTorqueEnableAddress = 40; // every family (spec §5)
// A rate above this is "as fast as the bus allows": Qt timers count whole milliseconds.
constexpr double kFastestTimedRate = 1000.0;
// The rates in the statistics are taken over this much of the recent past.
constexpr qint64 kRateWindowUs = 1'000'000;

} // namespace

// ---- telemetry

void Session::startTelemetry(const TelemetryOptions &options)
{
    stopTelemetry();
    if (options.servos.isEmpty())
        return;
    ++m_telemetryGeneration;
    qRegisterMetaType<feetech::FeedbackSample>();
    qRegisterMetaType<QVector<feetech::FeedbackSample>>();
    qRegisterMetaType<feetech::TelemetryStats>();
    m_telemetry.emplace();
    TelemetryState &state = *m_telemetry;
    state.options = options;
    state.startedUs = steadyMicroseconds();
    for (const ServoInfo &servo : options.servos) {
        TelemetryServo entry;
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
        connect(state.timer, &QTimer::timeout, this, &Session::telemetryTick);
        state.timer->start();
    }
    if (!m_telemetryFlushTimer) {
        m_telemetryFlushTimer = new QTimer(this);
        connect(m_telemetryFlushTimer, &QTimer::timeout, this, &Session::flushTelemetry);
        m_telemetryStatsTimer = new QTimer(this);
        connect(m_telemetryStatsTimer, &QTimer::timeout, this, &Session::publishTelemetryStats);
    }
    m_telemetryFlushTimer->start(m_timing.telemetryBatchInterval);
    m_telemetryStatsTimer->start(m_timing.telemetryStatsInterval);
    publishTelemetryStats();
    telemetryTick(); // the first cycle at once
}

void Session::stopTelemetry()
{
    if (!m_telemetry)
        return;
    ++m_telemetryGeneration; // answers still on their way belong to no stream now
    flushTelemetry();
    updateTelemetryStats();
    m_telemetry->stats.running = false;
    const TelemetryStats last = m_telemetry->stats;
    if (m_telemetry->timer)
        m_telemetry->timer->deleteLater();
    m_telemetry.reset();
    m_telemetryFlushTimer->stop();
    m_telemetryStatsTimer->stop();
    emit telemetryStats(last);
    // An operation may have been waiting for the cycle that will now never end.
    if (!m_running)
        QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
}

void Session::telemetryTick()
{
    if (!m_telemetry)
        return;
    m_telemetry->due = true; // a tick while a cycle runs is not queued twice: the bus is full
    startTelemetryCycleIfDue();
}

bool Session::startTelemetryCycleIfDue()
{
    if (!m_telemetry || !m_telemetry->due || m_telemetry->inCycle || m_running
        || !m_transport->isOpen())
        return false;
    TelemetryState &state = *m_telemetry;
    state.due = false;
    state.inCycle = true;
    state.steps.clear();
    state.nextStep = 0;
    const qint64 now = steadyMicroseconds();
    // Servos by baud rate, in the order given; one SYNC READ per rate for those that have it.
    QVector<qint32> bauds;
    for (const TelemetryServo &servo : state.servos) {
        if (!bauds.contains(servo.info.baud))
            bauds.append(servo.info.baud);
    }
    for (const qint32 baud : std::as_const(bauds)) {
        QVector<int> synced;
        QVector<int> single;
        QVector<int> probes;
        for (int i = 0; i < int(state.servos.size()); ++i) {
            const TelemetryServo &servo = state.servos.at(std::size_t(i));
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
        state.steps.push_back([this, baud](std::function<void()> next) {
            if (m_transport->baudRate() != baud) {
                if (!m_transport->setBaudRate(baud)) {
                    logNote(Tr::tr("The port cannot be set to %1.").arg(baudText(baud)), true);
                    next();
                    return;
                }
                m_status.baud = baud;
            }
            next();
        });
        if (!synced.isEmpty())
            state.steps.push_back(telemetrySyncRead(baud, synced));
        for (const int index : std::as_const(single))
            state.steps.push_back(telemetryRead(index, false));
        for (const int index : std::as_const(probes))
            state.steps.push_back(telemetryRead(index, true));
    }
    if (state.steps.empty()) {
        // Every servo is missing and none is due to be asked: no cycle, and no busy loop.
        state.inCycle = false;
        if (!state.timer) {
            qint64 nextProbe = std::numeric_limits<qint64>::max();
            for (const TelemetryServo &servo : state.servos)
                nextProbe = std::min(nextProbe, servo.nextProbeUs);
            const quint64 stream = m_telemetryGeneration;
            const int waitMs = int(std::clamp<qint64>((nextProbe - now + 999) / 1000, 1, 60000));
            QTimer::singleShot(waitMs, this, [this, stream] {
                if (m_telemetry && stream == m_telemetryGeneration)
                    telemetryTick();
            });
        }
        return false;
    }
    runTelemetryStep();
    return true;
}

void Session::runTelemetryStep()
{
    if (!m_telemetry)
        return;
    TelemetryState &state = *m_telemetry;
    if (state.nextStep >= state.steps.size()) {
        endTelemetryCycle();
        return;
    }
    const auto step = state.steps.at(state.nextStep++);
    step([this] { runTelemetryStep(); });
}

void Session::endTelemetryCycle()
{
    TelemetryState &state = *m_telemetry;
    state.inCycle = false;
    state.steps.clear();
    ++state.stats.cycles;
    const qint64 now = steadyMicroseconds();
    state.history.emplace_back(now, state.stats.samples);
    while (state.history.size() > 2 && state.history.front().first < now - kRateWindowUs)
        state.history.pop_front();
    if (!state.timer)
        state.due = true; // as fast as the bus allows: the next cycle follows at once
    if (!m_queue.empty() && !m_running) {
        startQueuedOperation(); // an operation that waited goes before the next cycle
        return;
    }
    if (state.due)
        QMetaObject::invokeMethod(
            this, [this] { startTelemetryCycleIfDue(); }, Qt::QueuedConnection);
}

std::chrono::microseconds Session::telemetryAllowance(int servos) const
{
    // Replies of a SYNC READ come one after the other, each after its servo's return delay.
    const auto allowance = scanAllowance() + kLongestReturnDelay * std::max(0, servos - 1);
    return std::clamp(allowance, m_timing.minimumTelemetryAllowance, m_timing.maximumScanAllowance);
}

std::function<void(std::function<void()>)> Session::telemetrySyncRead(qint32 baud,
                                                                      QVector<int> servoIndexes)
{
    return [this, baud, servoIndexes](std::function<void()> next) {
        QVector<quint8> ids;
        for (const int index : servoIndexes)
            ids.append(m_telemetry->servos.at(std::size_t(index)).info.id);
        seriallink::Transaction transaction;
        transaction.request = feetech::syncRead(kFeedbackAddress, kFeedbackSize, ids);
        transaction.priority = seriallink::Transaction::Priority::Poll;
        transaction.retryCount = 0; // the next cycle is the retry
        transaction.replyTimeout = telemetryAllowance(int(ids.size()));
        transaction.expectedReplySize = int(ids.size()) * (kMinimumPacketSize + kFeedbackSize);
        transaction.logFailuresOnly = !m_telemetry->options.logEveryFrame;
        auto answered = std::make_shared<QVector<bool>>(ids.size(), false);
        const QByteArray sent = transaction.request;
        transaction.collectsReplies = [sent, ids, answered](const QByteArray &frame) {
            using Answer = seriallink::Transaction::Answer;
            if (frame == sent)
                return Answer::NotMine;
            const auto packet = decodePacket(frame);
            if (!packet || packet->parameters.size() != kFeedbackSize)
                return Answer::NotMine;
            const auto position = ids.indexOf(packet->id);
            if (position < 0 || answered->at(position))
                return Answer::NotMine;
            (*answered)[position] = true;
            // Servos answer in the order of the list: none answers after the last one.
            const bool last = position == ids.size() - 1
                || std::all_of(answered->begin(), answered->end(), [](bool a) { return a; });
            return last ? Answer::Complete : Answer::More;
        };
        const quint64 generation = m_generation;
        const quint64 stream = m_telemetryGeneration;
        transaction.done = [this, generation, stream, baud, servoIndexes, ids, answered,
                            next](const seriallink::TransactionResult &result) {
            // Indexes and the cycle belong to the stream that asked: not after a restart.
            if (generation != m_generation || stream != m_telemetryGeneration || !m_telemetry)
                return;
            const qint64 now = steadyMicroseconds();
            if (!result.frames.isEmpty())
                noteLatency(result.latency);
            for (const QByteArray &frame : result.frames) {
                const auto packet = decodePacket(frame);
                const auto position = packet ? ids.indexOf(packet->id) : -1;
                if (position >= 0)
                    noteTelemetryAnswer(servoIndexes.at(position), *packet, now);
            }
            QStringList silent;
            for (int i = 0; i < ids.size(); ++i) {
                if (!answered->at(i)) {
                    noteTelemetryMiss(servoIndexes.at(i));
                    silent.append(QString::number(ids.at(i)));
                }
            }
            if (!silent.isEmpty() && result.failure != seriallink::Failure::LinkDown)
                logNote(Tr::tr("SYNC READ at %1: no answer from ID %2")
                            .arg(baudText(baud), silent.join(QStringLiteral(", "))),
                        true);
            next();
        };
        m_engine->submit(std::move(transaction));
    };
}

std::function<void(std::function<void()>)> Session::telemetryRead(int servoIndex, bool probe)
{
    return [this, servoIndex, probe](std::function<void()> next) {
        TelemetryServo &servo = m_telemetry->servos.at(std::size_t(servoIndex));
        const quint8 id = servo.info.id;
        if (probe)
            servo.nextProbeUs = steadyMicroseconds()
                + std::chrono::duration_cast<std::chrono::microseconds>(
                      m_telemetry->options.missingProbeInterval)
                      .count();
        seriallink::Transaction transaction;
        transaction.request = feetech::read(id, kFeedbackAddress, kFeedbackSize);
        transaction.priority = seriallink::Transaction::Priority::Poll;
        transaction.retryCount = 0;
        transaction.replyTimeout = telemetryAllowance(1);
        transaction.expectedReplySize = kMinimumPacketSize + kFeedbackSize;
        transaction.logFailuresOnly = !m_telemetry->options.logEveryFrame;
        // A servo known to be missing is asked quietly: its silence is already reported.
        transaction.silenceExpected = probe;
        const QByteArray sent = transaction.request;
        transaction.acceptsReply = [sent, id](const QByteArray &frame) {
            if (frame == sent)
                return false;
            const auto packet = decodePacket(frame);
            return packet && packet->id == id && packet->parameters.size() == kFeedbackSize;
        };
        const quint64 generation = m_generation;
        const quint64 stream = m_telemetryGeneration;
        transaction.done = [this, generation, stream, servoIndex,
                            next](const seriallink::TransactionResult &result) {
            if (generation != m_generation || stream != m_telemetryGeneration || !m_telemetry)
                return;
            const auto packet = result.ok() ? decodePacket(result.reply) : std::nullopt;
            if (packet) {
                noteLatency(result.latency);
                noteTelemetryAnswer(servoIndex, *packet, steadyMicroseconds());
            } else {
                noteTelemetryMiss(servoIndex);
            }
            next();
        };
        m_engine->submit(std::move(transaction));
    };
}

void Session::noteTelemetryAnswer(int servoIndex, const Packet &reply, qint64 steadyUs)
{
    TelemetryServo &servo = m_telemetry->servos.at(std::size_t(servoIndex));
    const auto sample = decodeFeedback(servo.info.table(), servo.info.id, servo.info.baud, steadyUs,
                                       reply.parameters, reply.code);
    if (!sample)
        return;
    servo.missesInARow = 0;
    ++servo.stats.samples;
    ++m_telemetry->stats.samples;
    m_telemetryBatch.append(*sample);
    if (servo.stats.missing) {
        servo.stats.missing = false;
        logNote(Tr::tr("%1 answers again; it is back in the cycle.").arg(servoName(servo.info)));
        publishTelemetryStats();
    }
}

void Session::noteTelemetryMiss(int servoIndex)
{
    TelemetryServo &servo = m_telemetry->servos.at(std::size_t(servoIndex));
    ++servo.missesInARow;
    ++servo.stats.missed;
    ++m_telemetry->stats.missed;
    if (!servo.stats.missing && servo.missesInARow >= m_telemetry->options.missesBeforeMissing) {
        servo.stats.missing = true;
        servo.nextProbeUs = steadyMicroseconds()
            + std::chrono::duration_cast<std::chrono::microseconds>(
                  m_telemetry->options.missingProbeInterval)
                  .count();
        logNote(Tr::tr("%1 stopped answering; it is left out of the cycle and asked alone "
                       "every %2 ms until it answers.")
                    .arg(servoName(servo.info))
                    .arg(m_telemetry->options.missingProbeInterval.count()),
                true);
        publishTelemetryStats();
    }
}

void Session::flushTelemetry()
{
    if (m_telemetryBatch.isEmpty())
        return;
    QVector<FeedbackSample> batch;
    batch.swap(m_telemetryBatch);
    emit telemetry(batch, m_telemetry ? m_telemetry->options.stream : 0);
}

void Session::publishTelemetryStats()
{
    if (!m_telemetry)
        return;
    updateTelemetryStats();
    emit telemetryStats(m_telemetry->stats);
}

void Session::updateTelemetryStats()
{
    TelemetryState &state = *m_telemetry;
    TelemetryStats &stats = state.stats;
    const qint64 now = steadyMicroseconds();
    stats.elapsedSeconds = double(now - state.startedUs) / 1e6;
    stats.servos.clear();
    for (const TelemetryServo &servo : state.servos)
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

void Session::logNote(const QString &note, bool error)
{
    seriallink::PacketLogEntry entry;
    entry.timestampMs = QDateTime::currentMSecsSinceEpoch();
    entry.direction = seriallink::Direction::In;
    if (error)
        entry.error = note;
    else
        entry.summary = note;
    emit packetLogged(entry);
}

// ---- control

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

void Session::torqueOffAll(const QVector<qint32> &bauds, const QVector<ServoInfo> &servos)
{
    if (m_scan)
        m_scan->cancelled = true; // nothing may hold torque off back for seconds
    ++m_torqueOffEpoch; // writes asked for before this must not power the servos again
    const auto start = [this, bauds, servos] {
        // Every step goes on whatever failed before it: one silent servo or an odd rate must
        // not keep the others powered.
        auto problems = std::make_shared<QStringList>();
        auto confirmed = std::make_shared<int>(0);
        const auto tolerant = [problems](Step step) -> Step {
            return [problems, step = std::move(step)](Done next) {
                step([problems, next](bool ok, const QString &message) {
                    if (!ok)
                        problems->append(message);
                    next(true, {});
                });
            };
        };
        std::vector<Step> steps;
        for (const qint32 baud : bauds) {
            steps.push_back(tolerant(stepSetBaud(baud)));
            steps.push_back(
                tolerant(stepWrite(kBroadcastId, kTorqueEnableAddress, QByteArray(1, char(0)),
                                   false, Tr::tr("Torque off at %1").arg(baudText(baud)))));
            for (const ServoInfo &servo : servos) {
                if (servo.baud != baud)
                    continue;
                steps.push_back(tolerant([this, servo, confirmed](Done next) {
                    Exchange ask;
                    ask.request = feetech::read(servo.id, kTorqueEnableAddress, 1);
                    ask.replyId = servo.id;
                    ask.replyDataSize = 1;
                    exchange(
                        ask,
                        [this, servo, confirmed, next](const seriallink::TransactionResult &,
                                                       const std::optional<Packet> &reply) {
                            if (!reply) {
                                next(
                                    false,
                                    Tr::tr("%1 did not confirm (no reply).").arg(servoName(servo)));
                                return;
                            }
                            emit memoryRead(servo.id, servo.baud, kTorqueEnableAddress,
                                            reply->parameters, ReadSource::ReadBack, reply->code);
                            if (reply->parameters.at(0) != 0) {
                                next(false,
                                     Tr::tr("%1 still has torque on.").arg(servoName(servo)));
                                return;
                            }
                            ++*confirmed;
                            next(true, {});
                        });
                }));
            }
        }
        runSteps(std::move(steps), [this, problems, confirmed, servos](bool, const QString &) {
            const QString message = problems->isEmpty()
                ? Tr::tr("Torque off: sent to the whole bus; %n servo(s) confirmed it.", nullptr,
                         *confirmed)
                : Tr::tr("Torque off was sent to the whole bus, but: %1")
                      .arg(problems->join(QLatin1Char(' ')));
            finishOperation({Operation::TorqueOff, problems->isEmpty(), message, {}, {}});
        });
    };
    // Ahead of everything waiting: this is the emergency stop.
    m_queue.push_front({Operation::TorqueOff, start});
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
        const auto frame = feetech::syncWrite(quint8(address), quint8(length), entries);
        if (!frame) {
            finishOperation({Operation::SyncWrite,
                             false,
                             Tr::tr("The SYNC WRITE does not fit in one packet."),
                             {},
                             {}});
            return;
        }
        std::vector<Step> steps {stepSetBaud(baud),
                                 stepInstruction(kBroadcastId, *frame, false,
                                                 Tr::tr("SYNC WRITE at %1").arg(baudText(baud)))};
        runSteps(std::move(steps), [this, entries](bool ok, const QString &message) {
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

} // namespace feetech
