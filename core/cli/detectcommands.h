// servoctl detect and servoctl doctor: who is on a port, and what is wrong with the bus.
#pragma once

#include "arguments.h"
#include "commandoutput.h"

#include <QStringList>

namespace cli {

// `rest` is what follows the command's name.
int runDetectCommand(const Arguments &args, const QStringList &rest, const Output &output);
int runDoctorCommand(const Arguments &args, const QStringList &rest, const Output &output);

} // namespace cli
