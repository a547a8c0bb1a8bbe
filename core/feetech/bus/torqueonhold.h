// Torque on never jumps: before a write switches a servo's torque on, its goal is set to where
// the horn stands, so the servo holds its place instead of driving to an old goal. Also the
// checks around a test that moves a servo and puts it back: whether it may move, and after.
#pragma once

#include "busexchange.h"
#include "bustypes.h"

#include <QHash>
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>
#include <optional>

namespace feetech {

// Whether `writes` switch torque on (torque enable to the table's "on" value) without also
// setting the goal position: the writes the hold must go before.
bool needsHoldBeforeTorqueOn(const ServoInfo &servo, const QVector<RegisterWrite> &writes);

// Reads torque enable; when it is not on already, reads the present position, writes it as the
// goal and reads the goal back. Fails (so nothing after it runs) when any of that fails.
Step holdBeforeTorqueOn(BusExchange &bus, std::shared_ptr<ServoInfo> servo);

// Reads the present position, writes it as the goal and reads the goal back, whatever the
// torque: the servo stops pushing where it stands (the guard's hold). `heldAt`, when given,
// gets the goal written. Only in position mode: a servo in another mode (wheel, PWM, step,
// where the goal is no position) is left alone, the step fails and `notInPositionMode`, when
// given, is set.
Step holdAtPresentPosition(BusExchange &bus, std::shared_ptr<ServoInfo> servo,
                           std::shared_ptr<std::optional<qint32>> heldAt = {},
                           std::shared_ptr<bool> notInPositionMode = {});

// For a test that moves a servo and then puts everything back (the health move test, joint
// identification), judged on its registers as read before (`before`, by key): why it must be
// left alone (not in position mode, or a torque enable neither on nor off), or empty when it may
// be moved; `torqueWasOn` then says whether its torque was on.
QString whyNotToMove(const ServoInfo &servo, const QHash<QString, qint32> &before,
                     bool *torqueWasOn);

// After such a test has put the registers `keys` back and read them again (`now`): what differs
// from `before` ("it was not restored as it was: ..."), or empty when every one reads as before.
QString notRestoredAsItWas(const QStringList &keys, const QHash<QString, qint32> &before,
                           const QHash<QString, qint32> &now);

} // namespace feetech
