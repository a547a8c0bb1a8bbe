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

// For a stream (monitor, share, teleoperation, recording), before it starts: from then to the
// command's end, output nobody reads is lost and counted, never waited for (the bus's timing
// must not follow a reader); a line says how many when reading resumes ({"dropped": N} on
// stdout with --json).
void streamWithoutWaiting(const Output &output);
// "dropped 1,204 lines nobody read", or empty when every line was read.
QString droppedLinesNote(const Output &output);
// The note above on stderr, when there is one: as a stream ends.
void sayDroppedLines(const Output &output);

} // namespace cli
