// A bench case for power lost in the middle of an EEPROM write: when the servo loses it.
#pragma once

#include "feetechpacket.h"

#include <QString>

#include <optional>

namespace sim {

class VirtualFeetechServo;

// After the servo has taken (and answered) the frame that opens its EEPROM lock, or the first
// write to its EEPROM after that, it loses power: the rest of the write sequence finds it dead.
enum class PowerCut { None, AfterUnlock, AfterWrite };

// "after-unlock", "after-write"; nothing for another word.
std::optional<PowerCut> powerCutFromName(const QString &name);
// Whether `packet`, just executed by `servo`, is the moment `cut` waits for.
bool cutsPower(PowerCut cut, const VirtualFeetechServo &servo, const feetech::Packet &packet);

} // namespace sim
