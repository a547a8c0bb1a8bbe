// The settings check on the bus: one READ of a servo's settings, and the fixes of its findings
// (unlock, write, lock, each read back). Lives in the session's thread, as its steps do.
#pragma once

#include "busexchange.h"
#include "settingscheck.h"

#include <functional>

namespace feetech {

// Reads every register of the servo's table from address 0 through the present voltage (and
// through any of `keys` beyond it) in one READ. A failure is in the reading, never fatal.
void readSettings(BusExchange &bus, const ServoInfo &servo, const QStringList &keys,
                  std::function<void(const SettingsReading &)> done);

// Writes the expected value of each fixable finding of one servo and reads it back. Torque
// enable is read first: with torque on, a finding that needsTorqueOff is refused (TorqueOn) and
// not written. EEPROM writes go unlock, write, lock; the lock is closed again even when a write
// fails. `done` gets one outcome per finding, in their order.
void fixSettings(BusExchange &bus, const QVector<SettingsFinding> &findings,
                 std::function<void(const QVector<SettingsFixOutcome> &)> done);

} // namespace feetech
