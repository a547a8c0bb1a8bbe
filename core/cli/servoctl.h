// servoctl: the command-line tool's logic, callable in-process (app/servoctl.cpp is only main()).
#pragma once

#include <QStringList>
#include <QTextStream>

namespace cli {

// Exit status contract (design.md, "Command-line tool").
enum ExitCode : int {
    ExitOk = 0,
    ExitDeviceFailure = 1, // no reply, bad frames, verification mismatch
    ExitUsage = 2, // bad option, key or value: nothing was sent to any device
};

// Runs one servoctl invocation; `arguments` excludes the program name.
int runServoctl(const QStringList &arguments, QTextStream &out, QTextStream &err);

} // namespace cli
