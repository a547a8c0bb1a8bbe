// servoctl: the command-line tool's entry point.
#include "cli/servoctl.h"
#include "version.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("servoctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SERVOBENCH_VERSION));
    QTextStream out(stdout);
    QTextStream err(stderr);
    return cli::runServoctl(QCoreApplication::arguments().mid(1), out, err);
}
