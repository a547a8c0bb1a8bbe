// Unplug cycles (item of trust): the port disappearing and coming back in the middle of each kind
// of work, 50 times each by default; prints JSON with the problems found and the process's
// threads, open files and memory after the first cycle and after the last.
//
//   bench_unplug [--cycles N] [--work NAME]...
#include "eventloops.h"
#include "unplugcycles.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>

#include <cstdio>

int main(int argc, char **argv)
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    const QStringList arguments = QCoreApplication::arguments().mid(1);
    int cycles = 50;
    QVector<unplug::Work> works;
    for (int i = 0; i + 1 < arguments.size(); i += 2) {
        if (arguments.at(i) == QLatin1String("--cycles")) {
            cycles = arguments.at(i + 1).toInt();
        } else if (arguments.at(i) == QLatin1String("--work")) {
            for (const unplug::Work work : unplug::allWork()) {
                if (unplug::workName(work) == arguments.at(i + 1))
                    works.append(work);
            }
        }
    }
    if (arguments.size() % 2 != 0 || cycles < 1) {
        std::fprintf(stderr, "usage: bench_unplug [--cycles N] [--work NAME]...\n");
        return 2;
    }
    if (works.isEmpty())
        works = unplug::allWork();
    QJsonArray reports;
    bool clean = true;
    for (const unplug::Work work : works) {
        std::fprintf(stderr, "bench_unplug: %s\n", qPrintable(unplug::workName(work)));
        const unplug::CycleReport report = unplug::runCycles(work, cycles);
        clean = clean && report.problems == 0;
        reports.append(report.toJson());
    }
    std::printf("%s", QJsonDocument(reports).toJson(QJsonDocument::Indented).constData());
    return clean ? 0 : 1;
}
