// Tests that the demo arm's simulated bus and the link that streams from it never wait for the
// window's thread: a 50 Hz Monitor stream goes on, every SYNC READ answered in time, while that
// thread is held, and while the window is busiest (splitters dragged, the window resized, docks
// toggled), the bus being reached in process rather than through a pseudo-terminal.
#include "busclient.h"
#include "feetechworkspace.h"
#include "inprocessport.h"
#include "mainwindow.h"
#include "monitorpage.h"
#include "packetlogdock.h"
#include "servolist.h"
#include "simulatordock.h"
#include "telemetryhub.h"

#include <QDockWidget>
#include <QMouseEvent>
#include <QSettings>
#include <QSplitter>
#include <QTabWidget>
#include <QThread>
#include <QtTest>

namespace {

// How long the window's thread is held: some 75 cycles at 50 Hz.
constexpr unsigned long kHoldMs = 1500;
// How many rounds of drags, resizes and docks toggled the window goes through.
constexpr int kBusyRounds = 30;
// How far each drag takes a splitter's handle, there and back.
constexpr int kDragPixels = 120;

// Drags the first handle of `splitter` by `by` pixels with the left button, as a user's mouse
// does: press, moves, release, each delivered to the handle and each move painted.
void dragHandle(QSplitter *splitter, int by)
{
    if (splitter->count() < 2)
        return;
    QSplitterHandle *handle = splitter->handle(1);
    const QPointF from = QRectF(handle->rect()).center();
    const QPointF step =
        splitter->orientation() == Qt::Horizontal ? QPointF(by / 4.0, 0) : QPointF(0, by / 4.0);
    const auto send = [handle](QEvent::Type type, QPointF at, Qt::MouseButton button,
                               Qt::MouseButtons buttons) {
        QMouseEvent event(type, at, handle->mapToGlobal(at), button, buttons, Qt::NoModifier);
        QCoreApplication::sendEvent(handle, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    QPointF at = from;
    for (int i = 0; i < 4; ++i) {
        at += step;
        send(QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton);
        QCoreApplication::processEvents();
    }
    send(QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
}

// The demo arm in `window`, scanned, its Monitor streaming all six joints at 50 Hz and its
// first samples in: the Monitor page, or null after a failed check.
MonitorPage *streamDemoArm(MainWindow &window)
{
    window.resize(1366, 768);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window))
        return nullptr;
    window.startArmDemo();
    feetech::BusClient *client = window.feetechClient();
    if (!QTest::qWaitFor(
            [client] { return client->servos()->idsInUse() == QVector<int> {1, 2, 3, 4, 5, 6}; },
            20000))
        return nullptr;
    FeetechWorkspace *workspace = window.feetechWorkspace();
    MonitorPage *monitor = workspace->monitorPage();
    workspace->tabs()->setCurrentWidget(monitor);
    monitor->setSelectedServos({0, 1, 2, 3, 4, 5});
    monitor->setRate(50);
    QString error;
    if (!monitor->start(&error)) {
        qWarning("the Monitor did not start: %s", qPrintable(error));
        return nullptr;
    }
    QSignalSpy samples(client->telemetry(), &feetech::TelemetryHub::samplesReceived);
    return samples.wait(10000) ? monitor : nullptr;
}

} // namespace

class TestDemoStream : public QObject
{
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void aFiftyHertzStreamGoesOnUnmissedWhileTheWindowsThreadIsHeld()
    {
        MainWindow window;
        MonitorPage *monitor = streamDemoArm(window);
        QVERIFY(monitor);
        feetech::BusClient *client = window.feetechClient();
        feetech::TelemetryHub *hub = client->telemetry();
        QSignalSpy samples(hub, &feetech::TelemetryHub::samplesReceived);
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

    void aFiftyHertzStreamMissesNothingWhileTheWindowIsDraggedResizedAndItsDocksToggled()
    {
        MainWindow window;
        MonitorPage *monitor = streamDemoArm(window);
        QVERIFY(monitor);
        feetech::BusClient *client = window.feetechClient();
        // The link reaches the simulated arm inside the program: no pseudo-terminal's kernel
        // worker, which the window's painting can starve on a small machine, stands between.
        QVERIFY(seriallink::InProcessPort::isKnown(client->link()->status().portName));
        feetech::TelemetryHub *hub = client->telemetry();
        QSignalSpy samples(hub, &feetech::TelemetryHub::samplesReceived);
        const seriallink::LinkCounters before = client->link()->counters();
        const feetech::TelemetryStats statsBefore = hub->stats();

        // Every splitter of the window, the pages' and the docks' included.
        const QList<QSplitter *> splitters = window.findChildren<QSplitter *>();
        QVERIFY(!splitters.isEmpty());
        const QList<QDockWidget *> docks = {window.packetLog(), window.simulatorDock()};
        // A number of rounds, however long each takes: the machine's speed is no behaviour.
        for (int rounds = 0; rounds < kBusyRounds; ++rounds) {
            const qsizetype samplesAtStart = samples.size();
            const int way = rounds % 2 == 0 ? 1 : -1;
            for (QSplitter *splitter : splitters) {
                if (splitter->isVisible())
                    dragHandle(splitter, way * kDragPixels);
            }
            window.resize(rounds % 2 == 0 ? QSize(1100, 650) : QSize(1366, 768));
            QCoreApplication::processEvents();
            docks.at(rounds % docks.size())->toggleViewAction()->trigger();
            QCoreApplication::processEvents();
            window.resizeDocks({window.packetLog()}, {rounds % 2 == 0 ? 120 : 260}, Qt::Vertical);
            QCoreApplication::processEvents();
            // Samples come all along, not only once the window is quiet again.
            QTRY_VERIFY_WITH_TIMEOUT(samples.size() > samplesAtStart, 5000);
        }
        for (QDockWidget *dock : docks)
            dock->show();

        // The statistics of the cycles run meanwhile, and of a few more.
        QTRY_VERIFY_WITH_TIMEOUT(hub->stats().cycles >= statsBefore.cycles + 50, 10000);
        QSignalSpy stats(hub, &feetech::TelemetryHub::statsChanged);
        QVERIFY(stats.wait(5000));
        const seriallink::LinkCounters after = client->link()->counters();
        const feetech::TelemetryStats statsAfter = hub->stats();
        QCOMPARE(statsAfter.missed - statsBefore.missed, 0);
        QCOMPARE(statsAfter.late - statsBefore.late, 0);
        QCOMPARE(after.timeouts - before.timeouts, 0);
        QCOMPARE(after.failures - before.failures, 0);
        monitor->stop();
    }
};

QTEST_MAIN(TestDemoStream)
#include "tst_demostream.moc"
