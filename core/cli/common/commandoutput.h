// The output streams and link options every servoctl command shares: --echo, --trace, Ctrl-C.
#pragma once

#include "linktypes.h"
#include "requestengine.h"

#include <QEventLoop>
#include <QTextStream>

#include <functional>
#include <optional>

namespace cli {

class Arguments;

struct Output
{
    QTextStream &out;
    QTextStream &err;
    bool json = false;
};

// --echo auto|on|off (auto when absent); a UsageError for anything else.
seriallink::EchoMode echoModeOption(const Arguments &args);
// One --trace line on stderr: direction, hex, meaning and any error.
void printTrace(const Output &output, const seriallink::PacketLogEntry &entry);

// Runs `loop` until it quits, or for `seconds` when given. Ctrl-C and SIGTERM call `onSignal`
// (which quits the loop when not given); their default handling is back afterwards.
void runUntilInterrupted(QEventLoop &loop, std::optional<double> seconds = std::nullopt,
                         const std::function<void()> &onSignal = {});

} // namespace cli
