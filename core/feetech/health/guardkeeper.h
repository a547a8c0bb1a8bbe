// The overload and thermal guard on a session's bus: which servos are driven, their feedback
// (from the telemetry stream, or the guard's own slow reads), and the hold or torque off.
#pragma once

#include "busexchange.h"
#include "bustypes.h"
#include "overloadguard.h"
#include "telemetrycycle.h"

#include <QHash>
#include <QObject>
#include <QPair>

#include <functional>

namespace feetech {

// Lives in the session's thread. Every write, SYNC WRITE and identify the session runs is shown
// to it: a goal or torque on makes a servo driven, torque off (or All torque off) makes it slack
// again. Driven servos that the telemetry stream does not read often enough are read by the
// guard's own cycle (one SYNC READ of the feedback block per rate, kGuardRateHz times a second,
// between operations); nothing is read while no servo is driven.
class GuardKeeper : public QObject
{
    Q_OBJECT

public:
    static constexpr double kGuardRateHz = 5.0;

    explicit GuardKeeper(BusExchange &bus, QObject *parent = nullptr);

    // The session runs `work` ahead of everything queued but All torque off; `work` calls its
    // argument when its bus steps are done.
    using Urgent = std::function<void(std::function<void(std::function<void()> finished)> work)>;
    void setRunUrgent(Urgent urgent) { m_runUrgent = std::move(urgent); }
    // Called after the guard acted on a servo, so whatever moves it (an identify) stops.
    void setActed(std::function<void(const ServoInfo &)> acted) { m_acted = std::move(acted); }

    TelemetryCycle &cycle() { return *m_cycle; }
    void setSettings(const GuardSettings &settings);
    const GuardSettings &settings() const { return m_guard.settings(); }
    bool isDriven(quint8 id, qint32 baud) const { return m_driven.contains({id, baud}); }

    // What the session saw or did.
    void noteServo(const ServoInfo &servo); // found by a scan, or named by an operation
    void noteWrites(const ServoInfo &servo, const QVector<RegisterWrite> &writes);
    void noteSyncWrite(qint32 baud, int address, const QVector<SyncWriteEntry> &entries);
    void noteDriven(const ServoInfo &servo); // an identify drives it itself
    void noteAllTorqueOff();
    void noteLinkDown();
    // The telemetry stream now reads `options` (empty servos: no stream).
    void noteStream(const TelemetryOptions &options);
    void observe(const QVector<FeedbackSample> &samples);

signals:
    void guardEvent(const feetech::GuardEvent &event);

private:
    using Key = QPair<quint8, qint32>;
    void setDriven(const ServoInfo &servo, bool driven);
    void updateCycle();
    void report(GuardEvent event, const GuardLimits &limits);
    void act(const ServoInfo &servo, const GuardEvent &seen, const GuardLimits &limits);
    Step torqueOff(std::shared_ptr<ServoInfo> target); // written and read back

    BusExchange &m_bus;
    TelemetryCycle *m_cycle;
    OverloadGuard m_guard;
    Urgent m_runUrgent;
    std::function<void(const ServoInfo &)> m_acted;
    QHash<Key, ServoInfo> m_known;
    QHash<Key, ServoInfo> m_driven;
    QVector<Key> m_streamed; // read by the stream often enough for the guard
    QVector<Key> m_cycled; // read by the guard's cycle now
    quint64 m_stream = 0;
};

} // namespace feetech
