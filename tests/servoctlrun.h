// Test helper: runs servoctl in-process and captures its exit code, stdout and stderr.
#pragma once

#include "servoctl.h"

#include <QStringList>
#include <QTextStream>

namespace testsupport {

struct ServoctlResult
{
    int exitCode = -1;
    QString out;
    QString err;
};

inline ServoctlResult runServoctl(const QStringList &arguments)
{
    ServoctlResult result;
    QTextStream out(&result.out);
    QTextStream err(&result.err);
    result.exitCode = cli::runServoctl(arguments, out, err);
    out.flush();
    err.flush();
    return result;
}

} // namespace testsupport
