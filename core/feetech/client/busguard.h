// The GUI thread's side of the overload and thermal guard: its settings for the servos found,
// what it last said of each, and the recovery of a servo whose overload protection tripped.
#pragma once

#include "guardkeeper.h"
#include "refusal.h"

#include <QHash>
#include <QObject>

#include <optional>

namespace feetech {

class BusClient;
class OperationReply;

// Belongs to a BusClient (BusClient::guard()); on from the start. The session's GuardKeeper
// acts; this keeps its settings in step with the servos found and their limit registers.
class BusGuard : public QObject
{
    Q_OBJECT

public:
    explicit BusGuard(BusClient *client);

    // The limits of servo `index` now: those set with setSettings, else the defaults from its
    // own limit registers as last read (the table's factory values before a read).
    GuardLimits limits(int index) const;
    // Its defaults alone: from its limit registers, whatever was set.
    GuardLimits defaults(int index) const;
    // Replaces the whole guard's settings (limits set for servos not listed are dropped).
    void setSettings(const GuardSettings &settings);
    const GuardSettings &settings() const { return m_settings; }
    // The newest thing the guard said about servo `index`.
    std::optional<GuardEvent> lastEvent(int index) const;
    // Torque off and on again, then the status checked; `checkOnly` after a power cycle. The
    // result's failure is StillLatched when a power cycle is due. Nullptr and *refusal when
    // refused.
    OperationReply *recoverOverload(int index, bool checkOnly, Refusal *refusal = nullptr);

signals:
    // The guard warned or acted (the message names the servo, the figures and the action).
    void event(const feetech::GuardEvent &event);

private:
    // Sends the session each servo's limits (set, or from its registers) when they changed.
    void send();

    BusClient *m_client;
    GuardSettings m_settings; // as the user set them
    std::optional<GuardSettings> m_sent; // what the session has now
    QHash<ServoAddress, GuardEvent> m_lastEvent;
};

} // namespace feetech
