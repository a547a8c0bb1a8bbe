// Tests that the main window opens with its menus, connection bar and status bar, and that it
// remembers its size, layout and last connection, resets its layout and shows what it is (About).
#include "connectionbar.h"
#include "mainwindow.h"
#include "packetlogdock.h"
#include "shortcutsdialog.h"
#include "skippablequestion.h"

#include <QCheckBox>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTableWidget>
#include <QtTest>

class TestMainWindow : public QObject
{
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void opensWithTitleMenusAndDisconnectedState()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QCOMPARE(window.windowTitle(), QStringLiteral("ServoBench"));
        QStringList menus;
        for (QAction *action : window.menuBar()->actions())
            menus.append(action->text());
        QCOMPARE(menus,
                 (QStringList {QStringLiteral("&File"), QStringLiteral("&Link"),
                               QStringLiteral("&Robot"), QStringLiteral("&View"),
                               QStringLiteral("&Help")}));
        auto *state = window.findChild<QLabel *>(QStringLiteral("connectionState"));
        QVERIFY(state);
        QCOMPARE(state->text(), QStringLiteral("Not connected"));
    }

    void quitActionClosesTheWindow()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto *quit = window.findChild<QAction *>(QStringLiteral("quitAction"));
        QVERIFY(quit);
        quit->trigger();
        QVERIFY(!window.isVisible());
    }

    void keyboardShortcutsListsTheMenusShortcuts()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QAction *>(QStringLiteral("shortcutsAction"))->trigger();
        auto *dialog = window.findChild<ShortcutsDialog *>();
        QVERIFY(dialog && dialog->isVisible());
        QStringList rows;
        for (int row = 0; row < dialog->table()->rowCount(); ++row)
            rows.append(dialog->table()->item(row, 0)->text() + QStringLiteral(" = ")
                        + dialog->table()->item(row, 1)->text());
        const auto keys = [](const QKeySequence &sequence) {
            return sequence.toString(QKeySequence::NativeText);
        };
        QVERIFY2(
            rows.contains(keys(QKeySequence::Save) + QStringLiteral(" = File > Save profile…")),
            qPrintable(rows.join(u'\n')));
        QVERIFY(rows.contains(keys(QKeySequence(Qt::Key_Escape))
                              + QStringLiteral(" = Link > All torque off")));
        QVERIFY(rows.contains(keys(QKeySequence(Qt::CTRL | Qt::Key_F5))
                              + QStringLiteral(" = Link > Scan the Feetech bus…")));
    }

    void aboutShowsVersionQtLicenceAndHome()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QString text;
        // The dialog is modal: read it and close it once it is up (whatever came up instead is
        // closed too, so the test fails rather than waits).
        QTimer::singleShot(0, &window, [&text] {
            QWidget *modal = QApplication::activeModalWidget();
            if (auto *box = qobject_cast<QMessageBox *>(modal))
                text = box->text();
            if (modal)
                modal->close();
        });
        window.findChild<QAction *>(QStringLiteral("aboutAction"))->trigger();
        QVERIFY2(text.contains(QStringLiteral("Built with Qt " QT_VERSION_STR)), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("GNU General Public License, version 3")));
        QVERIFY2(
            text.contains(QStringLiteral("<a href=\"https://github.com/servobench/servobench\">")),
            qPrintable(text));
    }

    void remembersSizeLayoutAndLastConnection()
    {
        const QString missing = QDir::temp().filePath(QStringLiteral("servobench-no-such-port"));
        QSize chosen;
        {
            MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            window.resize(900, 600); // as far as the window's minimum size allows
            chosen = window.size();
            QVERIFY(chosen.width() == 900);
            window.packetLog()->hide();
            window.connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
            window.connectionBar()->setBaud(500000);
            window.connectToPort(missing); // fails (no such port), but was asked for
            QVERIFY(window.close());
        }
        MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QCOMPARE(again.size(), chosen);
        QVERIFY(again.packetLog()->isHidden());
        QCOMPARE(again.connectionBar()->port(), missing);
        QCOMPARE(again.connectionBar()->protocol(), ConnectionBar::Protocol::Feetech);
        QCOMPARE(again.connectionBar()->baud(), 500000);
    }

    // The welcome page says to leave Protocol on Auto: a demo run must not change that.
    void aDemoRunChangesNoRememberedConnection()
    {
        const QString missing = QDir::temp().filePath(QStringLiteral("servobench-no-such-port"));
        {
            MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QCOMPARE(window.connectionBar()->protocol(), ConnectionBar::Protocol::Auto);
            window.startArmDemo();
            QCOMPARE(window.connectionBar()->protocol(), ConnectionBar::Protocol::Feetech);
            QVERIFY(!QSettings().contains(QStringLiteral("connection/protocol")));
            QVERIFY(!QSettings().contains(QStringLiteral("connection/port")));
            // A real port chosen next is probed again, as before the demo.
            window.connectionBar()->setPort(missing);
            QCOMPARE(window.connectionBar()->protocol(), ConnectionBar::Protocol::Auto);
            QVERIFY(window.close());
        }
        MainWindow again;
        QCOMPARE(again.connectionBar()->protocol(), ConnectionBar::Protocol::Auto);
    }

    void aSkippedQuestionIsAskedAgainFromTheViewMenu()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        auto *askAgain = window.findChild<QAction *>(QStringLiteral("askAgainAction"));
        QVERIFY(askAgain);
        const SkippableQuestion question(QStringLiteral("test"), QStringLiteral("Move?"),
                                         QStringLiteral("Move it"));
        // Going ahead with "Don't ask again" ticked skips it from then on.
        QTimer::singleShot(0, this, [] {
            QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            box->findChild<QCheckBox *>(QStringLiteral("dontAskAgainBox"))->setChecked(true);
            box->findChild<QPushButton *>(QStringLiteral("goAheadButton"))->click();
        });
        QVERIFY(question.ask(&window, QStringLiteral("It moves.")));
        QVERIFY(question.isSkipped());
        QVERIFY(question.ask(&window, QStringLiteral("It moves."))); // no box: skipped
        QVERIFY(SkippableQuestion::anySkipped());
        for (QMenu *menu : window.findChildren<QMenu *>()) {
            if (menu->actions().contains(askAgain))
                emit menu->aboutToShow(); // the View menu opens
        }
        QVERIFY(askAgain->isEnabled());
        askAgain->trigger();
        QVERIFY(!question.isSkipped());
        QVERIFY(!SkippableQuestion::anySkipped());
        // A tick with Cancel is not remembered: skipping always means going ahead.
        QTimer::singleShot(0, this, [] {
            QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            box->findChild<QCheckBox *>(QStringLiteral("dontAskAgainBox"))->setChecked(true);
            box->button(QMessageBox::Cancel)->click();
        });
        QVERIFY(!question.ask(&window, QStringLiteral("It moves.")));
        QVERIFY(!question.isSkipped());
    }

    void resetLayoutBringsBackTheFirstLayout()
    {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QSize first = window.size();
        window.resize(700, 500);
        window.packetLog()->hide();
        window.connectionBar()->hide();
        auto *reset = window.findChild<QAction *>(QStringLiteral("resetLayoutAction"));
        QVERIFY(reset);
        reset->trigger();
        QCOMPARE(window.size(), first);
        QVERIFY(window.packetLog()->isVisible());
        QVERIFY(window.connectionBar()->isVisible());
        QVERIFY(!QSettings().contains(QStringLiteral("window/layout")));
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
