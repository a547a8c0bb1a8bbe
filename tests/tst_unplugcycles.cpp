// The short form of bench_unplug: three unplug cycles of each kind of work (polling, an Apply, a
// scan, an EEPROM write, a flow, a stream, servoctl) with no hang, a reconnection each time,
// what is shown afterwards what the simulator holds, and no thread or open file left behind.
#include "unplugcycles.h"

#include <QtTest>

class TestUnplugCycles : public QObject
{
    Q_OBJECT

private slots:
    void eachKindOfWorkSurvivesThePortGoingAndComingBack_data()
    {
        QTest::addColumn<int>("work");
        for (const unplug::Work work : unplug::allWork())
            QTest::newRow(qPrintable(unplug::workName(work))) << int(work);
    }
    void eachKindOfWorkSurvivesThePortGoingAndComingBack()
    {
        QFETCH(int, work);
        const unplug::CycleReport report = unplug::runCycles(unplug::Work(work), 3);
        QVERIFY2(report.problems == 0, qPrintable(report.examples.join(QLatin1Char('\n'))));
        QCOMPARE(report.cycles, 3);
        // What the first cycle opened stays open; later cycles add nothing.
        QVERIFY2(report.last.threads <= report.first.threads + 1,
                 qPrintable(QStringLiteral("threads %1 -> %2")
                                .arg(report.first.threads)
                                .arg(report.last.threads)));
        QVERIFY2(report.last.openFiles <= report.first.openFiles + 1,
                 qPrintable(QStringLiteral("open files %1 -> %2")
                                .arg(report.first.openFiles)
                                .arg(report.last.openFiles)));
    }
};

QTEST_GUILESS_MAIN(TestUnplugCycles)
#include "tst_unplugcycles.moc"
