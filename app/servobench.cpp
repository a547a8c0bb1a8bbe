// servobench: the desktop application's entry point.
#include "eventloops.h"
#include "languagemenu.h"
#include "mainwindow.h"
#include "startupprobe.h"
#include "translations.h"
#include "version.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QSettings>

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("ServoBench"));
    QApplication::setOrganizationName(QStringLiteral("ServoBench"));
    QApplication::setApplicationVersion(QStringLiteral(SERVOBENCH_VERSION));
    // The installed desktop entry's name: desktops match the window to it (and its icon).
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.servobench.ServoBench"));
    QIcon icon;
    for (const int size : {16, 24, 32, 48, 64, 128, 256})
        icon.addFile(QStringLiteral(":/icons/servobench-%1.png").arg(size), QSize(size, size));
    QApplication::setWindowIcon(icon);

    // The language chosen in View > Language, or the system's.
    util::installTranslations(QSettings().value(LanguageMenu::settingsKey()).toString());

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Programmer and live monitor for PTK and Feetech servos"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption demo(
        QStringLiteral("demo"),
        QApplication::translate("main",
                                "Start the simulated servos and connect to the PTK "
                                "servo (the Feetech bus is in the port list)."));
    const QCommandLineOption demoFeetech(
        QStringLiteral("demo-feetech"),
        QApplication::translate("main",
                                "Start the simulated servos, connect to the Feetech bus "
                                "and scan it."));
    const QCommandLineOption demoRobot(
        QStringLiteral("demo-robot"),
        QApplication::translate("main",
                                "Start a simulated SO-101 arm (six STS3215 at IDs 1-6, set up), "
                                "connect to it and scan it; the Simulator dock turns its joints "
                                "by hand."));
    const QCommandLineOption port(QStringList {QStringLiteral("port")},
                                  QApplication::translate("main", "Connect to PORT at start."),
                                  QStringLiteral("PORT"));
    parser.addOption(demo);
    parser.addOption(demoFeetech);
    parser.addOption(demoRobot);
    parser.addOption(port);
    parser.process(app);

    MainWindow window;
    window.show();
    StartupProbe::watchIfAsked(window); // only for bench_startup (SERVOBENCH_STARTUP_PROBE)
    if (parser.isSet(demoRobot))
        window.startArmDemo();
    else if (parser.isSet(demoFeetech))
        window.startFeetechDemo();
    else if (parser.isSet(demo))
        window.startDemo();
    else if (parser.isSet(port))
        window.connectToPort(parser.value(port));
    return QApplication::exec();
}
