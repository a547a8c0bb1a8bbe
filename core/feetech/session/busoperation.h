// One operation as the session queues and runs it: what it is, how it starts, and what the
// session must know of it before its turn comes.
#pragma once

#include "bustypes.h"

#include <functional>

namespace feetech {

class OperationContext;

struct BusOperation
{
    enum class Priority {
        Normal, // in the order submitted
        // All torque off: ahead of everything queued; a running scan is cancelled, and what was
        // submitted before it that would power the servos is not sent
        Emergency
    };
    Operation kind = Operation::Read;
    Priority priority = Priority::Normal;
    // It may power or move the servos: refused, nothing sent, when All torque off was asked for
    // after it was submitted. Its pauses are told whether one was asked for meanwhile.
    bool powersServos = false;
    // The submission it answers (OperationResult::ticket); 0 when nobody waits for a reply.
    quint64 ticket = 0;
    // Runs as it is submitted, in the session's thread: what must hold before anything queued
    // behind it runs (a cancel flag cleared, so a cancel asked while it waits reaches it).
    std::function<void(OperationContext &)> submitted;
    // Runs when its turn comes. It ends through OperationContext::finish, a scan through the
    // scan's end.
    std::function<void(OperationContext &)> start;
};

} // namespace feetech
