// servoctl: the command-line tool's entry point.
#include "servoctl.h"
#include "eventloops.h"
#include "lineoutlet.h"
#include "translations.h"
#include "version.h"

#include <QCoreApplication>
#include <QTextStream>

#include <unistd.h>

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::AllThreads);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("servoctl"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SERVOBENCH_VERSION));
    util::installTranslations(); // the system's language (LANG, LC_ALL, LC_MESSAGES)
    // Written by threads of their own: a stream never waits for a reader who stops reading.
    util::LineOutlet outOutlet(STDOUT_FILENO);
    util::LineOutlet errOutlet(STDERR_FILENO);
    QTextStream out(&outOutlet);
    QTextStream err(&errOutlet);
    return cli::runServoctl(QCoreApplication::arguments().mid(1), out, err);
}
