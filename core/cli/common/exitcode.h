// The exit statuses of servoctl, which scripts rely on.
#pragma once

namespace cli {

// Exit status contract (design.md, "Command-line tool").
enum ExitCode : int {
    ExitOk = 0,
    ExitDeviceFailure = 1, // no reply, bad frames, verification mismatch
    ExitUsage = 2, // bad option, key or value: nothing was sent to any device
};

} // namespace cli
