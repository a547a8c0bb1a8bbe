// servobench: the desktop application's entry point.
#include "mainwindow.h"
#include "version.h"

#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("ServoBench"));
    QApplication::setOrganizationName(QStringLiteral("ServoBench"));
    QApplication::setApplicationVersion(QStringLiteral(SERVOBENCH_VERSION));

    QTranslator translator;
    if (translator.load(QLocale(), QStringLiteral("servobench"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")))
        QApplication::installTranslator(&translator);

    MainWindow window;
    window.show();
    return QApplication::exec();
}
