// Tests that the main window fits a 1366x768 screen, offscreen, on a simulated SO-101 arm: with
// every dock open and every banner shown its least height stays within what the screen leaves
// under a desktop's panel and a title bar, and at 1366x700 the Monitor's readouts, the packet log
// and the Simulator dock keep rows and controls one can use, in English and in Chinese.
#include "busclient.h"
#include "doctorpanel.h"
#include "feetechworkspace.h"
#include "mainwindow.h"
#include "monitorpage.h"
#include "monitorreadouts.h"
#include "packetlogdock.h"
#include "servolist.h"
#include "simulatordock.h"
#include "telemetryplot.h"
#include "translations.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QtTest>

#include <memory>

namespace {

// What a 1366x768 screen leaves a window under a desktop's panel and a title bar.
constexpr int kScreenWidth = 1366;
constexpr int kUsableHeight = 700;
// The size the window takes on such a screen (MainWindow's first size there).
constexpr QSize kDefaultSize {1280, 720};
constexpr int kUsableRows = 3;

// Rows of `view` its viewport shows whole.
int rowsShown(const QAbstractItemView *view, int rowHeight)
{
    return rowHeight > 0 ? view->viewport()->height() / rowHeight : 0;
}

// For a failure message: the least heights of the window's parts, the tallest first, down to
// the widget that sets each.
QString minimumHeights(const QWidget *widget, int depth = 0)
{
    QString text =
        QStringLiteral("%1%2 '%3': least %4, now %5\n")
            .arg(QString(depth * 2, u' '), QString::fromLatin1(widget->metaObject()->className()),
                 widget->objectName())
            .arg(widget->minimumSizeHint().height())
            .arg(widget->height());
    if (depth > 12)
        return text;
    for (const QObject *child : widget->children()) {
        const auto *childWidget = qobject_cast<const QWidget *>(child);
        // A stacked widget's pages count whichever is shown; a banner hidden does not.
        const bool counted = childWidget
            && (!childWidget->isHidden() || qobject_cast<const QStackedWidget *>(widget));
        if (counted && !childWidget->isWindow() && childWidget->minimumSizeHint().height() >= 60)
            text += minimumHeights(childWidget, depth + 1);
    }
    return text;
}

} // namespace

class TestWindowFit : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<MainWindow> m_window;

    FeetechWorkspace *workspace() const { return m_window->feetechWorkspace(); }

    // The window as `servobench --demo-robot` makes it at its size on a 1366x768 screen: the
    // arm scanned, the packet log and the Simulator dock open.
    void openArmDemo()
    {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(kDefaultSize);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->startArmDemo();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->feetechClient()->servos()->count(), 6, 20000);
        QTRY_VERIFY(workspace()->currentIndex() >= 0);
        // Nothing left to report that would hide a banner shown now.
        QTRY_VERIFY(m_window->feetechClient()->servos()->at(workspace()->currentIndex()).read);
        QTRY_VERIFY(!m_window->feetechClient()->isBusy());
    }

    // As View > Doctor opens it.
    void openDoctor()
    {
        QAction *toggle = m_window->doctorPanel()->toggleViewAction();
        if (!toggle->isChecked())
            toggle->trigger();
        QVERIFY(m_window->doctorPanel()->isVisible());
        // A tab beside the packet log, in front.
        QVERIFY(
            m_window->tabifiedDockWidgets(m_window->packetLog()).contains(m_window->doctorPanel()));
        QTRY_VERIFY(!m_window->doctorPanel()->visibleRegion().isEmpty());
    }

    // Every banner and note the window and the Feetech pages can show at once, with a long
    // sentence each.
    void showEveryBanner()
    {
        const QString sentence = QStringLiteral(
            "Servo 3 stopped answering while its torque was on: check the cable between servo 2 "
            "and servo 3, then power the bus off and on again before you scan it once more.");
        for (const char *name : {"problemBanner", "guardText", "unlockedText", "statusLabel",
                                 "controlHint", "monitorMessage"}) {
            auto *label = m_window->findChild<QLabel *>(QLatin1String(name));
            QVERIFY2(label, name);
            label->setText(sentence);
            label->show();
        }
        for (const char *name : {"guardBanner", "unlockedNotice"}) {
            auto *banner = m_window->findChild<QWidget *>(QLatin1String(name));
            QVERIFY2(banner, name);
            banner->show();
        }
        settle();
        for (const char *name : {"problemBanner", "guardBanner", "unlockedNotice", "statusLabel",
                                 "controlHint", "monitorMessage"})
            QVERIFY2(!m_window->findChild<QWidget *>(QLatin1String(name))->isHidden(), name);
    }

    void settle()
    {
        QCoreApplication::processEvents();
        QCoreApplication::processEvents();
    }

    void verifyLeastHeight()
    {
        settle();
        const int least =
            std::max(m_window->minimumSizeHint().height(), m_window->minimumSize().height());
        if (least > kUsableHeight)
            qInfo().noquote() << minimumHeights(m_window.get());
        QVERIFY2(least <= kUsableHeight, qPrintable(QString::number(least)));
    }

    // At 1366x700 the key panels keep a size one can use.
    void verifyPanelsAtUsableSize()
    {
        m_window->resize(kScreenWidth, kUsableHeight);
        settle();
        QTRY_COMPARE(m_window->size(), QSize(kScreenWidth, kUsableHeight));
        verifyReadoutsAndLog();
        // The packet log's edge drags it taller: the pages above give up the height.
        PacketLogDock *log = m_window->packetLog();
        const int before = log->height();
        m_window->resizeDocks({log}, {before + 80}, Qt::Vertical);
        QTRY_VERIFY2(log->height() >= before + 20,
                     qPrintable(QStringLiteral("%1 px, was %2").arg(log->height()).arg(before)));
    }

    void verifyReadoutsAndLog()
    {
        workspace()
            ->findChild<QTabWidget *>(QStringLiteral("servoTabs"))
            ->setCurrentWidget(workspace()->monitorPage());
        settle();
        auto *readouts = workspace()->findChild<MonitorReadouts *>();
        QVERIFY(readouts);
        QVERIFY2(rowsShown(readouts, readouts->verticalHeader()->defaultSectionSize())
                     >= kUsableRows,
                 qPrintable(minimumHeights(m_window.get())));
        auto *splitter = qobject_cast<QSplitter *>(readouts->parentWidget());
        QVERIFY(splitter);
        QVERIFY(splitter->handle(1)->isVisible());
        QVERIFY(splitter->handle(1)->height() >= splitter->handleWidth());

        PacketLogDock *log = m_window->packetLog();
        log->raise();
        settle();
        auto *view = log->findChild<QTableView *>(QStringLiteral("packetLogView"));
        QVERIFY(view);
        QVERIFY2(rowsShown(view, view->verticalHeader()->defaultSectionSize()) >= kUsableRows,
                 qPrintable(QStringLiteral("log %1\n").arg(view->viewport()->height())
                            + minimumHeights(m_window.get())));
    }

    // The Simulator dock starts tall enough for all its controls: nothing cut off at the
    // bottom, no scroll bar.
    void verifySimulatorShowsWhole()
    {
        SimulatorDock *dock = m_window->simulatorDock();
        dock->raise();
        settle();
        auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
        QVERIFY(scroll);
        const QSize needed = scroll->widget()->minimumSizeHint();
        QVERIFY2(scroll->viewport()->height() >= needed.height(),
                 qPrintable(QStringLiteral("%1 of %2 px")
                                .arg(scroll->viewport()->height())
                                .arg(needed.height())));
        QVERIFY(scroll->viewport()->width() >= needed.width());
        // A note of one line does not make it scroll either.
        QVERIFY(dock->powerCycle());
        settle();
        QCOMPARE(scroll->verticalScrollBar()->maximum(), 0);
    }

private slots:
    void initTestCase() { QSettings().clear(); }

    void cleanup()
    {
        m_window.reset();
        QSettings().clear(); // the next case starts from the first layout again
    }

    void atItsFirstSizeTheMonitorShowsRowsAndSeveralValuesOnEachAxis()
    {
        openArmDemo();
        MonitorPage *monitor = workspace()->monitorPage();
        workspace()
            ->findChild<QTabWidget *>(QStringLiteral("servoTabs"))
            ->setCurrentWidget(monitor);
        monitor->findChild<QPushButton *>(QStringLiteral("monitorStartButton"))->click();
        QTRY_VERIFY_WITH_TIMEOUT(monitor->plot()->bufferedPoints() > 0, 10000);
        // The arm's joints stand apart (890 to 3070 steps): one label per pane would say nothing.
        for (const feetech::Quantity quantity : monitor->plot()->quantities()) {
            QTRY_VERIFY2(monitor->plot()->valueLabels(quantity).size() >= 3,
                         qPrintable(feetech::quantityName(quantity)));
        }
        verifyReadoutsAndLog();
        verifySimulatorShowsWhole();
    }

    void theDoctorAndABannerLeaveTheWindowOnTheScreen()
    {
        openArmDemo();
        openDoctor();
        auto *banner = m_window->findChild<QLabel *>(QStringLiteral("problemBanner"));
        banner->setText(QStringLiteral("No reply from the servos on the simulated arm."));
        banner->show();
        verifyLeastHeight();
        verifyPanelsAtUsableSize();
    }

    void everyDockAndBannerLeaveTheWindowOnTheScreen()
    {
        openArmDemo();
        openDoctor();
        showEveryBanner();
        verifyLeastHeight();
        verifyPanelsAtUsableSize();
    }

    // Last: the translation stays installed. Chinese text is taller.
    void inChineseEveryDockAndBannerLeaveTheWindowOnTheScreen()
    {
        QCOMPARE(util::installTranslations(QStringLiteral("zh_CN")).name(),
                 QStringLiteral("zh_CN"));
        openArmDemo();
        QVERIFY(m_window->doctorPanel()->windowTitle() != QLatin1String("Doctor"));
        verifySimulatorShowsWhole();
        openDoctor();
        showEveryBanner();
        verifyLeastHeight();
        verifyPanelsAtUsableSize();
    }
};

QTEST_MAIN(TestWindowFit)
#include "tst_windowfit.moc"
