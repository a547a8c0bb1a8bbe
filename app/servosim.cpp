// servosim: simulated PTK servo or Feetech bus on a pseudo-terminal, for users and tests.
#include "eventloops.h"
#include "simcommands.h"
#include "simulator.h"
#include "translations.h"
#include "unixsignals.h"
#include "version.h"

#include <QCoreApplication>
#include <QSocketNotifier>
#include <QTextStream>

#include <csignal>
#include <cstdio>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::AllThreads);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("servosim"));
    QCoreApplication::setApplicationVersion(QStringLiteral(SERVOBENCH_VERSION));
    util::installTranslations(); // the system's language, as servoctl
    QTextStream out(stdout);
    QTextStream err(stderr);

    const QStringList arguments = QCoreApplication::arguments().mid(1);
    if (arguments.contains(QStringLiteral("--help")) || arguments.contains(QStringLiteral("-h"))) {
        out << sim::simulatorUsage();
        return 0;
    }
    QString error;
    const auto options = sim::parseSimulatorArguments(arguments, &error);
    if (!options) {
        err << "servosim: " << error << '\n' << sim::simulatorUsage();
        return 2;
    }
    auto simulator = sim::Simulator::create(*options, &error);
    if (!simulator) {
        err << "servosim: " << error << '\n';
        return 2;
    }

    util::UnixSignalWatcher watcher;
    watcher.watch(SIGINT);
    watcher.watch(SIGTERM);
#ifdef Q_OS_UNIX
    watcher.watch(SIGHUP);
#endif
    QObject::connect(&watcher, &util::UnixSignalWatcher::received, &app, [&](int number) {
#ifdef Q_OS_UNIX
        if (number == SIGHUP) {
            simulator->powerCycle();
            return;
        }
#endif
        Q_UNUSED(number)
        QCoreApplication::quit();
    });

    if (!simulator->start(&error)) {
        err << "servosim: " << error << '\n';
        return 1;
    }
    for (const QString &command : std::as_const(options->commands)) {
        const QString reply = sim::runSimulatorCommand(command, *simulator);
        if (reply.startsWith(QLatin1String("error "))) {
            err << "servosim: --command \"" << command << "\": " << reply.mid(6) << '\n';
            simulator->stop();
            return 2;
        }
        err << "servosim: " << reply.mid(3) << '\n';
    }
    out << "ready " << simulator->linkPath() << '\n';
    out.flush();

    // Commands on standard input, one reply line each; at its end the simulator runs on.
    QObject::connect(simulator.get(), &sim::Simulator::handNote, &app, [&](const QString &note) {
        err << "servosim: " << note << '\n';
        err.flush();
    });
    // (Unix only, as the pseudo-terminal is: elsewhere start() has already said why it failed.)
#ifdef Q_OS_UNIX
    QByteArray pending;
    QSocketNotifier input(STDIN_FILENO, QSocketNotifier::Read);
    QObject::connect(&input, &QSocketNotifier::activated, &app, [&] {
        char buffer[4096];
        const ssize_t count = ::read(STDIN_FILENO, buffer, sizeof buffer);
        if (count <= 0) {
            input.setEnabled(false);
            return;
        }
        pending.append(buffer, qsizetype(count));
        for (qsizetype end = pending.indexOf('\n'); end >= 0; end = pending.indexOf('\n')) {
            const QString line = QString::fromUtf8(pending.left(end));
            pending.remove(0, end + 1);
            const QString reply = sim::runSimulatorCommand(line, *simulator);
            if (!reply.isEmpty()) {
                out << reply << '\n';
                out.flush();
            }
        }
    });
#endif
    const int status = QCoreApplication::exec();
    simulator->stop(); // removes the link
    return status;
}
