// servoctl ptk: read, write, save, load and monitor a PTK servo through a serial port.
#pragma once

#include "cli/arguments.h"
#include "link/linktypes.h"
#include "link/requestengine.h"
#include "ptk/ptkparameters.h"

#include <QEventLoop>
#include <QTextStream>

#include <functional>
#include <optional>

namespace cli {

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

// `rest` is what follows "ptk". Usage errors are thrown as UsageError before anything is sent.
int runPtkCommand(const Arguments &args, const QStringList &rest, const Output &output);

// NAME=VALUE in user units ("on"/"off"/"true"/"false" for switches) into wire values; throws
// UsageError naming the bad name or value.
ptk::ParameterSet parsePtkAssignments(const QStringList &assignments);

} // namespace cli
