// The overload and thermal guard's rules: per-servo limits (defaults from the register table),
// and the decisions made from each feedback sample of a driven servo: warn, then act.
#pragma once

#include "bustypes.h"
#include "telemetry.h"

#include <QHash>
#include <QMetaType>
#include <QPair>
#include <QString>
#include <QVector>

#include <chrono>
#include <functional>
#include <optional>

namespace feetech {

// What the guard does once a servo is overloaded or too hot. Either way nothing moves that was
// not asked to: holding sets the goal to where the horn stands, torque off lets it go slack.
enum class GuardAction { Hold, TorqueOff };
QString guardActionKey(GuardAction action); // "hold", "torque-off" (command line, settings)
QString guardActionName(GuardAction action); // translated
std::optional<GuardAction> guardActionFromKey(QStringView key);

// The limits one servo is watched against.
struct GuardLimits
{
    bool enabled = true;
    // |load| (percent of the maximum torque) above this, for holdTime, is an overload.
    double loadPercent = 80.0;
    // Where the model reports no load against an overload torque but has a protection current:
    // |current| above this (mA), for holdTime, is an overload too.
    std::optional<double> currentMilliamps;
    std::chrono::milliseconds holdTime {1000};
    double maxTemperature = 70.0; // °C, the servo's own limit
    double temperatureMargin = 5.0; // acts this close to maxTemperature
    double temperatureWarnMargin = 10.0; // warns this close to it
    GuardAction action = GuardAction::Hold;

    bool operator==(const GuardLimits &other) const;
    bool operator!=(const GuardLimits &other) const { return !(*this == other); }
};

// A register's value as the servo holds it (register units), when known.
using RegisterLookup = std::function<std::optional<qint32>(QStringView key)>;

// The limits for a servo of `table`: the overload torque, protection current, protection time
// and max temperature registers as `lookup` gives them (the servo's own values), else the
// table's factory defaults, else fixed fallbacks (80 %, 1 s, 70 °C). The hold time is a quarter
// of the protection time (200 ms to 1 s): the guard acts before the servo's own trip.
GuardLimits defaultGuardLimits(const RegisterTable &table, const RegisterLookup &lookup = {});

// The guard's settings for a whole bus: on or off, and the limits of servos set by hand (the
// others get defaultGuardLimits).
struct GuardSettings
{
    bool enabled = true;
    QHash<QPair<quint8, qint32>, GuardLimits> servos; // by ID and baud
};

enum class GuardCause {
    Overload, // load (or current) above its limit for the hold time
    Heat, // temperature near its maximum
    LatchedOverload // the servo's own overload protection tripped (status bit 0x20)
};
enum class GuardStage {
    Warning, // the condition is there: the action follows if it stays
    Acted, // the action was taken (see GuardEvent::ok)
    StillLoaded, // held, yet the load stays above the limit: the servo's protection may trip
    Cleared // a latched overload cleared, or a recovery finished
};

// What the guard saw or did, for the status bar, the packet log, pages and servoctl.
struct GuardEvent
{
    quint8 id = 0;
    qint32 baud = 0;
    GuardCause cause = GuardCause::Overload;
    GuardStage stage = GuardStage::Warning;
    GuardAction action = GuardAction::Hold;
    double value = 0.0; // the load (%), current (mA) or temperature (°C) that was seen
    double limit = 0.0; // what it was measured against
    bool current = false; // `value` is a current, not a load
    std::optional<qint32> heldAt; // Acted with Hold: the goal written (steps)
    bool ok = true; // Acted: whether the action went through
    qint64 steadyUs = 0;
    QString message; // translated, names the servo, the figures and what was done
};

// One decision for one sample; the session turns Acted into a bus operation.
struct GuardDecision
{
    GuardCause cause = GuardCause::Overload;
    GuardStage stage = GuardStage::Warning;
    double value = 0.0;
    double limit = 0.0;
    bool current = false;
};

// The message of an event: says which servo, what was seen against which limit, and what the
// guard did (or will do).
QString guardEventText(const GuardEvent &event, const GuardLimits &limits);

// The status bit the servo's overload protection sets: the table's "Load" bit, else 0x20.
quint8 overloadStatusBit(const RegisterTable &table);

// Pure logic, fed in sample order. A condition warns once when it starts (an overload after
// half the hold time) and acts once when it lasts; it starts again only after it has gone (or
// after rearm: a new goal was asked for).
class OverloadGuard
{
public:
    void setSettings(const GuardSettings &settings);
    const GuardSettings &settings() const { return m_settings; }
    // The limits servo `info` is watched against now.
    GuardLimits limitsFor(const ServoInfo &info) const;

    QVector<GuardDecision> observe(const ServoInfo &info, const FeedbackSample &sample);
    // A new goal or torque on was asked for: after an action, the next overload (or the heat
    // still there) is a new one.
    void rearm(quint8 id, qint32 baud);
    void forget(quint8 id, qint32 baud);
    void clear() { m_states.clear(); }

private:
    struct State
    {
        std::optional<qint64> overloadSinceUs;
        bool overloadWarned = false;
        bool overloadActed = false;
        bool stillLoadedSaid = false;
        bool heatWarned = false;
        bool heatActed = false;
        bool latchSeen = false;
    };
    void observeOverload(State &state, const GuardLimits &limits, const FeedbackSample &sample,
                         QVector<GuardDecision> &out) const;
    void observeHeat(State &state, const GuardLimits &limits, const FeedbackSample &sample,
                     QVector<GuardDecision> &out) const;

    GuardSettings m_settings;
    QHash<QPair<quint8, qint32>, State> m_states;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::GuardEvent)
Q_DECLARE_METATYPE(feetech::GuardSettings)
