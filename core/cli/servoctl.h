// servoctl: the command-line tool's logic, callable in-process (app/servoctl.cpp is only main()).
#pragma once

#include "exitcode.h"

#include <QStringList>
#include <QTextStream>

namespace cli {

// Runs one servoctl invocation; `arguments` excludes the program name.
int runServoctl(const QStringList &arguments, QTextStream &out, QTextStream &err);

} // namespace cli
