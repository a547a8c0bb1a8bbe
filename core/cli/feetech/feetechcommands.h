// servoctl feetech: scan a Feetech bus and read, program and service one servo on it.
#pragma once

#include "arguments.h"
#include "commandoutput.h"

#include <QStringList>

namespace cli {

// `rest` is what follows "feetech". Usage errors are thrown as UsageError; those found in the
// arguments alone are thrown before the port is opened, those that need the servo's register
// table (unknown key, value out of range, a profile for another family) after only its
// identification was sent, never after a write.
int runFeetechCommand(const Arguments &args, const QStringList &rest, const Output &output);

} // namespace cli
