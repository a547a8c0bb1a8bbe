// Tests the welcome page beside the connection bar: the port chosen is the first USB adapter
// until the user chooses, both show the same choice, both offer Connect by the same rule, and
// the page's Connect connects the port chosen.
#include "connectionbar.h"
#include "mainwindow.h"
#include "ptkclient.h"
#include "serialports.h"
#include "welcomepanel.h"

#include <QHeaderView>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QtTest>

class TestWelcomePanel : public QObject
{
    Q_OBJECT

private:
    static QPushButton *barConnect(MainWindow &window)
    {
        return window.connectionBar()->findChild<QPushButton *>(QStringLiteral("connectButton"));
    }

    static QString selectedPort(MainWindow &window)
    {
        QTableWidget *table = window.welcomePanel()->portTable();
        const QList<QTableWidgetItem *> selected = table->selectedItems();
        return selected.isEmpty()
            ? QString()
            : table->item(selected.first()->row(), 0)->data(Qt::UserRole).toString();
    }

private slots:
    void init() { QSettings().clear(); }

    void theFirstUsbAdapterIsChosenUntilTheUserChooses()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QVector<SerialPort> ports = availableSerialPorts();
        const QString first = ports.isEmpty() ? QString() : ports.first().path;
        QTRY_COMPARE(window.connectionBar()->port(), first);
        QCOMPARE(selectedPort(window), first);
        if (!ports.isEmpty())
            QCOMPARE(window.welcomePanel()->portTable()->item(0, 0)->data(Qt::UserRole).toString(),
                     first);
        QCOMPARE(window.welcomePanel()->connectButton()->isEnabled(), !first.isEmpty());
        QCOMPARE(barConnect(window)->isEnabled(), !first.isEmpty());
    }

    // The description gets the room; a short column never takes it from it (the Chinese
    // window gave 描述 28 px and the USB ID 620).
    void theDescriptionTakesTheRoomTheShortColumnsLeave()
    {
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTableWidget *table = window.welcomePanel()->portTable();
        QHeaderView *header = table->horizontalHeader();
        const int description = header->sectionSize(1);
        for (const int shortColumn : {0, 4})
            QVERIFY2(description > header->sectionSize(shortColumn),
                     qPrintable(QStringLiteral("%1 against %2")
                                    .arg(description)
                                    .arg(header->sectionSize(shortColumn))));
    }

    void bothConnectButtonsFollowTheSameRule()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        ConnectionBar *bar = window.connectionBar();
        QPushButton *page = window.welcomePanel()->connectButton();
        bar->setPort(QString());
        QVERIFY(bar->port().isEmpty());
        QVERIFY(!barConnect(window)->isEnabled());
        QVERIFY(!page->isEnabled());
        bar->setPort(ConnectionBar::kSimulatedArmPort);
        QVERIFY(barConnect(window)->isEnabled());
        QVERIFY(page->isEnabled());
        QCOMPARE(selectedPort(window), QString()); // a simulated arm has no row
        const QString typed = QDir::temp().filePath(QStringLiteral("servobench-typed-port"));
        bar->setPort(typed);
        QVERIFY(barConnect(window)->isEnabled());
        QVERIFY(page->isEnabled());
        // The user's choice stays while the ports are listed again.
        bar->refreshPorts();
        window.welcomePanel()->refreshPorts();
        QCOMPARE(bar->port(), typed);
    }

    void selectingAPortsRowChoosesItInTheBar()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTableWidget *table = window.welcomePanel()->portTable();
        if (table->rowCount() == 0)
            QSKIP("This machine has no serial port to list");
        window.connectionBar()->setPort(ConnectionBar::kSimulatedPtkPort);
        QCOMPARE(selectedPort(window), QString());
        const int last = table->rowCount() - 1;
        table->selectRow(last);
        QCOMPARE(window.connectionBar()->port(),
                 table->item(last, 0)->data(Qt::UserRole).toString());
        QVERIFY(window.welcomePanel()->connectButton()->isEnabled());
    }

    void thePagesConnectConnectsThePortChosen()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.connectionBar()->setPort(ConnectionBar::kSimulatedPtkPort);
        QTest::mouseClick(window.welcomePanel()->connectButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(window.ptkClient()->isConnected(), 10000);
        QCOMPARE(barConnect(window)->text(), QStringLiteral("Disconnect"));
    }
};

QTEST_MAIN(TestWelcomePanel)
#include "tst_welcomepanel.moc"
