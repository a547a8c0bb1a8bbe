// The simulator's Feetech side: building the bus from --servo specs and its --state file.
#include "sim/simulator.h"

#include <QFileInfo>

namespace sim {

std::unique_ptr<VirtualDevice> createFeetechBus(const SimulatorOptions &options, QString *error)
{
    auto bus = VirtualFeetechBus::create(options.servos, error);
    if (!bus)
        return nullptr;
    if (!options.statePath.isEmpty()) {
        // A missing file is a first run; anything else must load cleanly.
        if (QFileInfo::exists(options.statePath) && !bus->loadState(options.statePath, error))
            return nullptr;
        bus->setStatePath(options.statePath);
    }
    return bus;
}

VirtualFeetechBus *Simulator::feetechBus()
{
    return dynamic_cast<VirtualFeetechBus *>(m_device.get());
}

} // namespace sim
