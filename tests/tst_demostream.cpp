// Tests that the demo arm's simulated bus and the link that streams from it never wait for the
// window's thread: a 50 Hz Monitor stream goes on, every SYNC READ answered in time, while that
// thread is held.
#include "busclient.h"
#include "feetechworkspace.h"
#include "mainwindow.h"
#include "monitorpage.h"
#include "servolist.h"
#include "telemetryhub.h"

#include <QSettings>
#include <QTabWidget>
#include <QThread>
#include <QtTest>

namespace {

// How long the window's thread is held: some 75 cycles at 50 Hz.
constexpr unsigned long kHoldMs = 1500;

} // namespace

class TestDemoStream : public QObject
{
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void aFiftyHertzStreamGoesOnUnmissedWhileTheWindowsThreadIsHeld()
    {
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.startArmDemo();
        feetech::BusClient *client = window.feetechClient();
        QTRY_COMPARE_WITH_TIMEOUT(client->servos()->idsInUse(), (QVector<int> {1, 2, 3, 4, 5, 6}),
                                  20000);

        FeetechWorkspace *workspace = window.feetechWorkspace();
        MonitorPage *monitor = workspace->monitorPage();
        workspace->tabs()->setCurrentWidget(monitor);
        monitor->setSelectedServos({0, 1, 2, 3, 4, 5});
        monitor->setRate(50);
        QString error;
        QVERIFY2(monitor->start(&error), qPrintable(error));
        feetech::TelemetryHub *hub = client->telemetry();
        QSignalSpy samples(hub, &feetech::TelemetryHub::samplesReceived);
        QVERIFY(samples.wait(10000));
        QSignalSpy stats(hub, &feetech::TelemetryHub::statsChanged);
        QVERIFY(stats.wait(5000));
        const seriallink::LinkCounters before = client->link()->counters();
        const feetech::TelemetryStats statsBefore = hub->stats();

        // The window's thread does nothing else for a while, as in a long repaint: the link's
        // news of the cycles run meanwhile waits for it, the cycles themselves do not.
        QThread::msleep(kHoldMs);
        samples.clear();
        QVERIFY(samples.wait(5000));
        stats.clear();
        QVERIFY(stats.wait(5000));

        const seriallink::LinkCounters after = client->link()->counters();
        const feetech::TelemetryStats statsAfter = hub->stats();
        // At 50 Hz the hold saw about 75 cycles; a third of them is plenty to know the stream
        // did not stop for it.
        QVERIFY2(statsAfter.cycles - statsBefore.cycles >= 25,
                 qPrintable(QString::number(statsAfter.cycles - statsBefore.cycles)));
        QVERIFY2(after.repliesOk - before.repliesOk >= 25,
                 qPrintable(QString::number(after.repliesOk - before.repliesOk)));
        QCOMPARE(statsAfter.missed - statsBefore.missed, 0);
        QCOMPARE(statsAfter.late - statsBefore.late, 0);
        QCOMPARE(after.timeouts - before.timeouts, 0);
        QCOMPARE(after.failures - before.failures, 0);
        monitor->stop();
    }
};

QTEST_MAIN(TestDemoStream)
#include "tst_demostream.moc"
