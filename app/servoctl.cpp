// servoctl: the command-line tool's entry point.
#include "servoctl.h"
#include "eventloops.h"
#include "translations.h"
#include "version.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::AllThreads);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("servoctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SERVOBENCH_VERSION));
    util::installTranslations(); // the system's language (LANG, LC_ALL, LC_MESSAGES)
    QTextStream out(stdout);
    QTextStream err(stderr);
    return cli::runServoctl(QCoreApplication::arguments().mid(1), out, err);
}
