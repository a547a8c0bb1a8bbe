// servoctl share: ServoBench between another program and the servos, from the command line.
#pragma once

#include "arguments.h"
#include "commandoutput.h"

#include <QStringList>

namespace cli {

// `servoctl --port DEVICE [--baud N] share --link PATH [--record FILE] [--watch]
// [--duration S] [--json]`; `rest` is what follows the command's name.
int runShareCommand(const Arguments &args, const QStringList &rest, const Output &output);

} // namespace cli
