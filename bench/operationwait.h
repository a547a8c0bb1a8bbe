// Waiting for a BusClient operation to end, for the fault soak and the unplug cycles.
#pragma once

#include "bustypes.h"

#include <functional>
#include <optional>

namespace feetech {
class OperationReply;
}

namespace soak {

// Starts an operation (`start` returns its reply, nullptr when refused) and runs the event loop
// until its final result, or `timeoutMs`: nothing when it was refused or did not end in time.
std::optional<feetech::OperationResult>
runOperation(const std::function<feetech::OperationReply *()> &start, int timeoutMs);

} // namespace soak
