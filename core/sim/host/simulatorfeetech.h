// The simulator's Feetech side: the bus built from servosim's options.
#pragma once

#include "simoptions.h"
#include "virtualfeetechbus.h"

#include <QString>

#include <memory>

namespace sim {

// The bus of the --servo specs, with the EEPROM of the --state file (which then follows every
// change), a --robot arm set up from its template and the --hand sweeps started; nothing and
// *error when the specs, the file or a sweep are refused.
std::unique_ptr<VirtualFeetechBus> createFeetechBus(const SimulatorOptions &options,
                                                    QString *error);

} // namespace sim
