// servoctl ptk: read, write, save, load and monitor a PTK servo through a serial port.
#pragma once

#include "arguments.h"
#include "commandoutput.h"
#include "ptkparameters.h"

#include <QStringList>

namespace cli {

// `rest` is what follows "ptk". Usage errors are thrown as UsageError before anything is sent.
int runPtkCommand(const Arguments &args, const QStringList &rest, const Output &output);

// NAME=VALUE in user units ("on"/"off"/"true"/"false" for switches) into wire values; throws
// UsageError naming the bad name or value.
ptk::ParameterSet parsePtkAssignments(const QStringList &assignments);

} // namespace cli
