// The Feetech telemetry cycle: SYNC READs of the feedback block between operations.
#pragma once

#include "busexchange.h"
#include "bustypes.h"
#include "telemetry.h"

#include <QObject>
#include <QTimer>

#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace feetech {

// One cycle reads every streamed servo's feedback block: one SYNC READ per baud rate for the
// families that have it, one READ per servo otherwise. A servo that misses several cycles in a
// row is left out and asked alone now and then, so it cannot slow the others. Cycles and the
// session's operations take turns on the bus: the session says when the bus is free, and hears
// when a cycle ends. Lives in the session's thread.
class TelemetryCycle : public QObject
{
    Q_OBJECT

public:
    TelemetryCycle(BusExchange &bus, QObject *parent = nullptr);

    // Whether an operation holds the bus now (a cycle then waits for it).
    void setBusBusy(std::function<bool()> busy) { m_busBusy = std::move(busy); }
    // Called when a cycle ends: an operation that waited may go first.
    void setCycleEnded(std::function<void()> ended) { m_cycleEnded = std::move(ended); }

    void start(const feetech::TelemetryOptions &options);
    // Ends the stream: samples still batched are sent, answers on their way are ignored.
    void stop();
    bool isStreaming() const { return m_state.has_value(); }
    bool inCycle() const { return m_state && m_state->inCycle; }
    // Starts a cycle if one is due and the bus is free; true when it started.
    bool startIfDue();

signals:
    void telemetry(const QVector<feetech::FeedbackSample> &samples, quint64 stream);
    void statsChanged(const feetech::TelemetryStats &stats);

private:
    using CycleStep = std::function<void(std::function<void()> next)>;
    struct Servo
    {
        ServoInfo info;
        ServoTelemetry stats;
        int missesInARow = 0;
        qint64 nextProbeUs = 0; // when a missing servo is asked again
    };
    struct State
    {
        TelemetryOptions options;
        std::vector<Servo> servos;
        QTimer *timer = nullptr; // the cycle clock; none when running as fast as possible
        bool due = false; // a cycle should start as soon as the bus is free
        bool inCycle = false;
        std::vector<CycleStep> steps; // of the running cycle
        std::size_t nextStep = 0;
        qint64 startedUs = 0;
        qint64 cycleStartedUs = 0; // of the running cycle
        // How long this stream's answers took beyond their wire time, newest last.
        std::deque<std::chrono::microseconds> answerTimes;
        TelemetryStats stats;
        std::deque<std::pair<qint64, qint64>> history; // (time, samples) at each cycle's end
    };

    void tick();
    void planCycle(qint64 now);
    void waitForNextProbe(qint64 now);
    void runStep();
    void endCycle();
    CycleStep setBaud(qint32 baud);
    CycleStep syncRead(qint32 baud, Block block, QVector<int> servoIndexes);
    CycleStep read(int servoIndex, bool probe);
    void noteAnswer(int servoIndex, const Packet &reply, qint64 steadyUs);
    void noteMiss(int servoIndex);
    // Calls `next` once late answers to a read that timed out have had `wait` to come.
    void settleThen(std::chrono::microseconds wait, std::function<void()> next);
    // An answer that came after its wait: a sample all the same, counted late, not missed.
    void noteLate(int servoIndex, const Packet &reply);
    void noteAnswerTime(std::chrono::microseconds time);
    // The wait beyond the wire time for `servos` answers at `baud` to a request of
    // `requestBytes` that expects `replyBytes`.
    std::chrono::microseconds allowance(int servos, qint32 baud, int requestBytes,
                                        int replyBytes) const;
    void flush();
    void publishStats();
    void updateStats();
    // The batch and statistics timers: what they send waits while a read is on the wire and
    // goes once its answers are in and the next read has left (doPostponed), so that neither
    // delays a request.
    void onBatchDue();
    void onStatsDue();
    void doPostponed();

    BusExchange &m_bus;
    std::function<bool()> m_busBusy;
    std::function<void()> m_cycleEnded;
    std::optional<State> m_state;
    quint64 m_generation = 0; // a new stream or a stop: earlier answers are ignored
    QVector<FeedbackSample> m_batch;
    QTimer *m_flushTimer = nullptr;
    QTimer *m_statsTimer = nullptr;
    bool m_flushPostponed = false;
    bool m_statsPostponed = false;
};

} // namespace feetech
