// GUI tests of the Robot actions against a simulated bus (STS3215 ×2, SCS15): the Robot menu,
// identify from the joint table (refused with a reason during a motion test), a profile and a
// template applied to the servos selected in the tree with the result table, and the robot
// template dialog's round trip to the user's template folder.
#include "batchprogram.h"
#include "batchresultdialog.h"
#include "connectionbar.h"
#include "feetechwindow.h"
#include "feetechworkspace.h"
#include "jointtable.h"
#include "mainwindow.h"
#include "motiontest.h"
#include "robotactions.h"
#include "robottemplatedialog.h"
#include "servotree.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTimer>
#include <QTreeWidget>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;

QString cell(const QTableWidget *table, int row, int column)
{
    const QTableWidgetItem *item = table->item(row, column);
    return item ? item->text() : QString();
}

} // namespace

class TestRobotActions : public testsupport::FeetechWindowTest
{
    Q_OBJECT

private:
    RobotActions *actions() const { return workspace()->robotActions(); }

    void connectAndScan()
    {
        connectAndScanUpTo(5);
        QTRY_VERIFY(!client()->isBusy());
    }

    // Applies `file` to every servo in the tree and waits for the result table.
    BatchResultDialog *applyToAll(const feetech::SettingsFile &file)
    {
        workspace()->servoTree()->selectAll();
        if (workspace()->servoTree()->selectedServos().size() != 3) {
            qWarning("the tree selection holds %d servos",
                     int(workspace()->servoTree()->selectedServos().size()));
            return nullptr;
        }
        QString error;
        if (!actions()->applyToSelected(file, &error)) {
            qWarning("refused: %s", qPrintable(error));
            return nullptr;
        }
        if (!QTest::qWaitFor([this] { return actions()->resultDialog() != nullptr; }, 30000))
            return nullptr;
        return actions()->resultDialog();
    }

private slots:
    void initTestCase()
    {
        // Before anything touches settings or paths: the user's template folder is a test one.
        QStandardPaths::setTestModeEnabled(true);
        QDir(feetech::userRobotTemplateFolder()).removeRecursively();
    }

    void init() { openWindowOnBus(); }

    void cleanup()
    {
        closeWindow();
        QDir(feetech::userRobotTemplateFolder()).removeRecursively();
    }

    void theRobotMenuFollowsTheLinkMenuAndWaitsForAScannedBus()
    {
        QStringList titles;
        for (QAction *menu : m_window->menuBar()->actions())
            titles.append(menu->text());
        QVERIFY(titles.indexOf(QStringLiteral("&Robot"))
                == titles.indexOf(QStringLiteral("&Link")) + 1);
        auto *robot = m_window->menuBar()->findChild<QMenu *>(QStringLiteral("robotMenu"));
        QVERIFY(robot);
        QVERIFY(robot->actions().contains(actions()->applyProfileAction()));
        for (QAction *action : actions()->actions()) {
            QVERIFY(!action->isEnabled());
            QVERIFY(action->toolTip().contains(QStringLiteral("Connect")));
        }
        connectAndScan();
        QTRY_VERIFY(actions()->identifyAction()->isEnabled());
        QVERIFY(actions()->saveTemplateAction()->isEnabled());
        workspace()->servoTree()->selectAll();
        QVERIFY(actions()->applyProfileAction()->isEnabled());
        QVERIFY(actions()->applyTemplateAction()->isEnabled());
    }

    void theJointTablesIdentifyButtonSaysWhyDuringAMotionTestAndWorksAfter()
    {
        connectAndScan();
        JointTable *joints = workspace()->jointTable();
        const int row = joints->rowOf({1, k1M});
        QPushButton *button = joints->identifyButton(row);
        QVERIFY(button);
        QTRY_VERIFY(button->isEnabled());
        const int index = client()->servos()->indexOf({1, k1M});
        client()->readServo(index);
        QTRY_VERIFY(!client()->isBusy());
        feetech::MotionTest test(client(), testsupport::quickMotionTiming());
        feetech::MotionTestRefusal refusal;
        QVERIFY2(test.startSweep(testsupport::longSweep(index), &refusal),
                 qPrintable(refusal.describe()));
        QTRY_VERIFY(!button->isEnabled());
        QVERIFY(button->toolTip().contains(QStringLiteral("motion test")));
        // The other servos stay free.
        QVERIFY(joints->identifyButton(joints->rowOf({2, k1M}))->isEnabled());
        test.cancel();
        QTRY_VERIFY(button->isEnabled());
        QTRY_VERIFY(!client()->isBusy());
        // Identify asks first; the answer goes ahead.
        QTimer::singleShot(0, this, [] {
            QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
            QApplication::activeModalWidget()
                ->findChild<QPushButton *>(QStringLiteral("goAheadButton"))
                ->click();
        });
        button->click(); // returns once the question is answered
        QVERIFY(client()->identify()->isRunning(index));
        QTRY_VERIFY_WITH_TIMEOUT(!client()->identify()->isRunning(index), 20000);
        QTRY_VERIFY(joints->message().contains(QStringLiteral("wiggled")));
    }

    void aProfileAppliedToTheSelectedServosEndsInTheResultTable()
    {
        connectAndScan();
        util::FileError error;
        const auto file = feetech::SettingsFile::load(
            writeTestFile(QStringLiteral("gains.json"),
                          R"({"format": "servobench-profile", "version": 1, "family": "sts",
                          "parameters": {"p_gain": 21, "max_temperature": 61}})"),
            &error);
        QVERIFY2(file, qPrintable(error.describe()));
        BatchResultDialog *dialog = applyToAll(*file);
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QTableWidget *table = dialog->table();
        QCOMPARE(table->rowCount(), 3);
        for (const int row : {0, 1}) {
            QCOMPARE(cell(table, row, BatchResultDialog::StatusColumn),
                     QStringLiteral("written and verified"));
            QCOMPARE(cell(table, row, BatchResultDialog::ChangedColumn),
                     QStringLiteral("max_temperature, p_gain"));
        }
        QCOMPARE(cell(table, 2, BatchResultDialog::ServoColumn), QStringLiteral("ID 3"));
        QCOMPARE(cell(table, 2, BatchResultDialog::StatusColumn), QStringLiteral("failed"));
        QVERIFY(cell(table, 2, BatchResultDialog::ErrorColumn).contains(QStringLiteral("scs")));
        for (const quint8 id : {1, 2}) {
            QCOMPARE(simulatorValue(id, u"p_gain"), 21);
            QCOMPARE(simulatorValue(id, u"max_temperature"), 61);
            QVERIFY(!client()
                         ->servos()
                         ->parameters(client()->servos()->indexOf({id, k1M}))
                         ->hasEdits());
        }
        // Every operation rebuilds the tree: the selection outlives them.
        QCOMPARE(workspace()->servoTree()->selectedServos().size(), 3);
        dialog->close();
        QTRY_VERIFY(!actions()->resultDialog());

        // Again: nothing left to write.
        dialog = applyToAll(*file);
        QVERIFY(dialog);
        QCOMPARE(cell(dialog->table(), 0, BatchResultDialog::StatusColumn),
                 QStringLiteral("unchanged"));
        QCOMPARE(cell(dialog->table(), 1, BatchResultDialog::StatusColumn),
                 QStringLiteral("unchanged"));
    }

    void aTemplatesSettingsGoToEachServoByJointId()
    {
        connectAndScan();
        feetech::RobotTemplate robot;
        robot.name = QStringLiteral("Bench arm");
        robot.joints = {{QStringLiteral("base"),
                         1,
                         QStringLiteral("STS3215"),
                         false,
                         {{QStringLiteral("d_gain"), 11}},
                         {}},
                        {QStringLiteral("elbow"),
                         2,
                         QStringLiteral("STS3215"),
                         false,
                         {{QStringLiteral("d_gain"), 12}},
                         {}}};
        BatchResultDialog *dialog = applyToAll(feetech::SettingsFile::fromTemplate(robot));
        QVERIFY(dialog);
        QCOMPARE(simulatorValue(1, u"d_gain"), 11);
        QCOMPARE(simulatorValue(2, u"d_gain"), 12);
        QCOMPARE(cell(dialog->table(), 2, BatchResultDialog::StatusColumn),
                 QStringLiteral("failed"));
        QVERIFY(cell(dialog->table(), 2, BatchResultDialog::ErrorColumn)
                    .contains(QStringLiteral("no joint with ID 3")));
    }

    void theTemplateDialogSavesWhatLoadingAcceptsAndAsksBeforeReplacing()
    {
        RobotTemplateDialog dialog(client());
        QVERIFY(dialog.baseChooser()->count() >= 4); // the built-in arms
        dialog.baseChooser()->setCurrentIndex(3);
        QTableWidget *joints = dialog.jointTable();
        QCOMPARE(joints->rowCount(), 6);
        // A built-in template's copy gets a name of its own; the built-in's name is refused.
        QVERIFY(dialog.saveButton()->isEnabled());
        dialog.nameEdit()->setText(feetech::builtInRobotTemplates().at(3).name);
        QVERIFY(!dialog.saveButton()->isEnabled());
        QVERIFY(dialog.errorLabel()->text().contains(QStringLiteral("built-in")));
        dialog.nameEdit()->setText(QStringLiteral("Bench SO-101"));
        QVERIFY(dialog.saveButton()->isEnabled());
        QVERIFY(dialog.errorLabel()->text().isEmpty());

        // Two joints at one ID: what loading would refuse is shown, and nothing is saved.
        joints->item(1, RobotTemplateDialog::IdColumn)->setText(QStringLiteral("1"));
        QVERIFY(!dialog.saveButton()->isEnabled());
        QVERIFY(dialog.errorLabel()->text().contains(QStringLiteral("ID 1")));
        joints->item(1, RobotTemplateDialog::IdColumn)->setText(QStringLiteral("7"));
        joints->item(0, RobotTemplateDialog::SettingsColumn)->setText(QStringLiteral("p_gain=20"));
        QVERIFY2(dialog.saveButton()->isEnabled(), qPrintable(dialog.errorLabel()->text()));

        QSignalSpy saved(&dialog, &RobotTemplateDialog::saved);
        QString error;
        QVERIFY2(dialog.save(&error), qPrintable(error));
        QCOMPARE(saved.size(), 1);
        const QString path = saved.first().first().toString();
        QCOMPARE(QFileInfo(path).fileName(), QStringLiteral("Bench SO-101.json"));
        QVERIFY(path.startsWith(feetech::userRobotTemplateFolder()));

        const QVector<feetech::RobotTemplate> available = feetech::availableRobotTemplates();
        const auto found = std::find_if(available.cbegin(), available.cend(), [](const auto &r) {
            return r.name == QStringLiteral("Bench SO-101");
        });
        QVERIFY(found != available.cend());
        QCOMPARE(found->joints.size(), 6);
        QCOMPARE(found->joints.at(1).id, 7);
        QCOMPARE(found->joints.at(0).settings,
                 (QMap<QString, qint32> {{QStringLiteral("p_gain"), 20}}));

        // Saving again asks first; "no" keeps the file as it was.
        joints->item(0, RobotTemplateDialog::SettingsColumn)->setText(QStringLiteral("p_gain=30"));
        QStringList asked;
        dialog.setOverwriteQuestion([&asked](const QString &at) {
            asked.append(at);
            return false;
        });
        QVERIFY(!dialog.save(&error));
        QCOMPARE(asked, QStringList {path});
        util::FileError why;
        QCOMPARE(feetech::loadRobotTemplate(path, &why)
                     ->joints.at(0)
                     .settings.value(QStringLiteral("p_gain")),
                 20);
        dialog.setOverwriteQuestion([](const QString &) { return true; });
        QVERIFY(dialog.save(&error));
        QCOMPARE(feetech::loadRobotTemplate(path, &why)
                     ->joints.at(0)
                     .settings.value(QStringLiteral("p_gain")),
                 30);
    }

    void theTemplateDialogStartsFromTheScannedServosAndTakesAServosValues()
    {
        connectAndScan();
        setSimulatorValue(2, u"p_gain", 23);
        RobotTemplateDialog dialog(client());
        dialog.baseChooser()->setCurrentIndex(dialog.baseChooser()->count() - 1);
        QTableWidget *joints = dialog.jointTable();
        QCOMPARE(joints->rowCount(), 3);
        QCOMPARE(joints->item(2, RobotTemplateDialog::ModelColumn)->text(),
                 QStringLiteral("SCS15"));
        QCOMPARE(joints->item(1, RobotTemplateDialog::IdColumn)->text(), QStringLiteral("2"));
        joints->item(1, RobotTemplateDialog::SettingsColumn)->setText(QStringLiteral("p_gain=1"));
        joints->setCurrentCell(1, RobotTemplateDialog::NameColumn);
        dialog.servoChooser()->setCurrentIndex(client()->servos()->indexOf({2, k1M}));
        dialog.takeSettingsFromServo();
        QTRY_COMPARE_WITH_TIMEOUT(joints->item(1, RobotTemplateDialog::SettingsColumn)->text(),
                                  QStringLiteral("p_gain=23"), 10000);
        QVERIFY(dialog.saveButton()->isEnabled());
    }
};

QTEST_MAIN(TestRobotActions)
#include "tst_robotactions.moc"
