// GUI tests of the Feetech workspace against a simulated bus: scan, tree, memory-table edits.
#include "connectionbar.h"
#include "feetechwindow.h"
#include "feetechworkspace.h"
#include "healthpage.h"
#include "jointtable.h"
#include "mainwindow.h"
#include "memorytablepage.h"
#include "operationlog.h"
#include "parameterpage.h"
#include "registertablemodel.h"
#include "servotree.h"
#include "settingscheckservice.h"
#include "telemetryhub.h"

#include <QAbstractItemView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;

// Presses the default button of the next message box that opens (a confirmation).
void acceptNextMessageBox()
{
    QTimer::singleShot(0, [] {
        QTRY_VERIFY(qobject_cast<QMessageBox *>(QApplication::activeModalWidget()));
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        box->button(QMessageBox::Ok)->click();
    });
}

} // namespace

class TestFeetechGui : public testsupport::FeetechWindowTest
{
    Q_OBJECT

private:
    void connectAndScan()
    {
        connectAndScanUpTo(10);
        // The first servo is shown and read by itself.
        QTRY_VERIFY(workspace()->currentIndex() >= 0
                    && client()->servos()->at(workspace()->currentIndex()).read);
    }

    QModelIndex valueIndex(const QString &key) const
    {
        QAbstractItemModel *model = workspace()->memoryPage()->table()->model();
        for (int row = 0; row < model->rowCount(); ++row) {
            const QModelIndex index = model->index(row, RegisterTableModel::ValueColumn);
            if (index.data(RegisterTableModel::KeyRole).toString() == key)
                return index;
        }
        return {};
    }

private slots:
    void init() { openWindowOnBus(); }

    void cleanup() { closeWindow(); }

    void scanFillsTheTreeByPortAndBaud()
    {
        connectAndScan();
        QTreeWidget *tree = workspace()->servoTree();
        QCOMPARE(tree->topLevelItemCount(), 1); // the port
        QTreeWidgetItem *baud = tree->topLevelItem(0)->child(0);
        QVERIFY(baud->text(0).contains(QLatin1String("1 Mbps")));
        QCOMPARE(baud->childCount(), 3);
        QCOMPARE(baud->child(0)->text(0), QStringLiteral("ID 1"));
        QCOMPARE(baud->child(0)->text(1), QStringLiteral("STS3215"));
        QCOMPARE(baud->child(2)->text(1), QStringLiteral("SCS15"));
        QCOMPARE(baud->child(2)->text(2), QStringLiteral("SCS"));
        // SCS has no offset register: no middle calibration offered.
        tree->setCurrentItem(baud->child(2));
        QTRY_VERIFY(client()->servos()->at(workspace()->currentIndex()).info.id == 3);
        QTRY_VERIFY(
            !m_window->findChild<QPushButton *>(QStringLiteral("calibrateButton"))->isEnabled());
    }

    void aSharedIdIsMarkedInTheTreeAndNothingIsWrittenThere()
    {
        // Two servos answer at ID 4: the tree says so and no write reaches that ID.
        m_window.reset();
        auto options = busOptions({{1, QStringLiteral("STS3215"), 1000000},
                                   {4, QStringLiteral("STS3215"), 1000000},
                                   {4, QStringLiteral("STS3215"), 1000000}});
        options.allowSharedIds = true;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        m_window->connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_VERIFY(client()->link()->isConnected());
        feetech::ScanOptions scan;
        scan.lastId = 10;
        QSignalSpy finished(client(), &feetech::BusClient::scanFinished);
        workspace()->startScan(scan);
        QVERIFY(finished.wait(20000));
        QCOMPARE(client()->servos()->count(), 2);
        QTreeWidgetItem *baud = workspace()->servoTree()->topLevelItem(0)->child(0);
        QCOMPARE(baud->child(0)->text(0), QStringLiteral("ID 1"));
        QCOMPARE(baud->child(1)->text(0), QStringLiteral("ID 4 (shared!)"));
        QVERIFY2(baud->child(1)->toolTip(0).contains(QLatin1String("Nothing is written")),
                 qPrintable(baud->child(1)->toolTip(0)));
        const int shared = client()->servos()->indexOf({4, 1000000});
        feetech::Refusal refusal;
        QVERIFY(
            !client()->writeValues(shared, {{QStringLiteral("max_temperature"), 70}}, &refusal));
        QCOMPARE(refusal.code(), feetech::Refusal::Code::SharedId);
        QCOMPARE(refusal.servoId(), std::optional<quint8>(4));
        QVERIFY2(refusal.describe().contains(QLatin1String("ID 4")),
                 qPrintable(refusal.describe()));
        refusal = {};
        QVERIFY(!client()->changeId(shared, 7, &refusal));
        QCOMPARE(refusal.code(), feetech::Refusal::Code::SharedId);
        QVERIFY(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).isEmpty());
    }

    void escapeSwitchesEveryServosTorqueOffFromAnyTab()
    {
        connectAndScan();
        for (const quint8 id : {1, 2, 3})
            setSimulatorValue(id, u"torque_enable", 1);
        QTabWidget *tabs = workspace()->tabs();
        tabs->setCurrentWidget(workspace()->jointTable());
        OperationLog finishedLog(client());
        QSignalSpy finished(&finishedLog, &OperationLog::finished);
        QTest::keyClick(m_window.get(), Qt::Key_Escape);
        // The Joints tab's own reads (it reads the servos when it opens) may finish first.
        const auto torqueOff = [&finished]() -> std::optional<feetech::OperationResult> {
            for (const QList<QVariant> &arguments : std::as_const(finished)) {
                const auto result = arguments.first().value<feetech::OperationResult>();
                if (result.operation == feetech::Operation::TorqueOff)
                    return result;
            }
            return std::nullopt;
        };
        QTRY_VERIFY_WITH_TIMEOUT(torqueOff().has_value(), 10000);
        const feetech::OperationResult result = *torqueOff();
        QVERIFY2(result.ok, qPrintable(result.message));
        for (const quint8 id : {1, 2, 3})
            QCOMPARE(simulatorValue(id, u"torque_enable"), 0);
        // The red button does the same.
        setSimulatorValue(2, u"torque_enable", 1);
        workspace()->allTorqueOffButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(2, u"torque_enable"), 0, 10000);
    }

    void memoryTableEditIsAppliedAndVerified()
    {
        connectAndScan();
        workspace()->tabs()->setCurrentIndex(1);
        QTableView *table = workspace()->memoryPage()->table();
        const QModelIndex cell = valueIndex(QStringLiteral("max_temperature"));
        QVERIFY(cell.isValid());
        QTRY_VERIFY(cell.flags() & Qt::ItemIsEditable);
        // Typed into the cell as a person would.
        table->setCurrentIndex(cell);
        table->edit(cell);
        auto *editor = table->findChild<QLineEdit *>();
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("66"));
        QTest::keyClick(editor, Qt::Key_Return); // the delegate commits on its next turn
        QTRY_COMPARE(valueIndex(QStringLiteral("max_temperature")).data().toString(),
                     QStringLiteral("66 °C"));
        QVERIFY(valueIndex(QStringLiteral("max_temperature"))
                    .data(RegisterTableModel::PendingRole)
                    .toBool());
        auto *apply = m_window->findChild<QPushButton *>(QStringLiteral("tableApplyButton"));
        QTRY_VERIFY(apply->isEnabled());
        apply->click();
        model::ParameterModel *parameters =
            client()->servos()->parameters(workspace()->currentIndex());
        QTRY_COMPARE(parameters->state(QStringLiteral("max_temperature")), model::State::Verified);
        QCOMPARE(simulatorValue(1, QStringLiteral("max_temperature")), 66);
        // Written to EEPROM with the lock closed again: it survives a power cycle.
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
        QCOMPARE(simulatorValue(1, QStringLiteral("max_temperature")), 66);
    }

    void aLiveRefreshNeverTouchesTheValueBeingTyped()
    {
        connectAndScan();
        workspace()->tabs()->setCurrentIndex(1);
        QVERIFY(workspace()->memoryPage()->refreshesLive()); // the default
        QTableView *table = workspace()->memoryPage()->table();
        const QString key = QStringLiteral("acceleration"); // RAM: refreshed live
        QTRY_VERIFY(valueIndex(key).flags() & Qt::ItemIsEditable);
        table->setCurrentIndex(valueIndex(key));
        table->edit(valueIndex(key));
        auto *editor = table->findChild<QLineEdit *>();
        QVERIFY(editor);
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("5000")); // step/s², 100 a raw step
        // The servo's value changes meanwhile, and the live refresh shows it in the table.
        setSimulatorValue(1, key, 7);
        model::ParameterModel *parameters =
            client()->servos()->parameters(workspace()->currentIndex());
        QTRY_COMPARE_WITH_TIMEOUT(parameters->deviceValue(key), std::optional<qint64>(7), 5000);
        QVERIFY2(editor->text().startsWith(QLatin1String("5000 ")), qPrintable(editor->text()));
        QTest::keyClick(editor, Qt::Key_Return);
        QTRY_VERIFY(valueIndex(key).data(RegisterTableModel::PendingRole).toBool());
        QCOMPARE(parameters->pendingValue(key), std::optional<qint64>(50));
    }

    void memoryTableSnapsAValueBetweenStepsVisibly()
    {
        connectAndScan();
        workspace()->tabs()->setCurrentIndex(1);
        QTableView *table = workspace()->memoryPage()->table();
        const QModelIndex cell = valueIndex(QStringLiteral("acceleration"));
        QVERIFY(cell.isValid());
        QTRY_VERIFY(cell.flags() & Qt::ItemIsEditable);
        // The tooltip names the register's step in its unit.
        QVERIFY2(cell.data(Qt::ToolTipRole).toString().contains(QStringLiteral("100 step/s²")),
                 qPrintable(cell.data(Qt::ToolTipRole).toString()));
        table->setCurrentIndex(cell);
        table->edit(cell);
        auto *editor = table->findChild<QSpinBox *>(QStringLiteral("registerValueEditor"));
        QVERIFY(editor);
        // The editor steps by the register's resolution, in its unit.
        QCOMPARE(editor->suffix(), QStringLiteral(" step/s²"));
        const int before = editor->value();
        editor->stepUp();
        QCOMPARE(editor->value(), before + 1);
        QCOMPARE(editor->text(), QStringLiteral("%1 step/s²").arg((before + 1) * 100));
        editor->selectAll();
        QTest::keyClicks(editor, QStringLiteral("50"));
        QTest::keyClick(editor, Qt::Key_Return);
        // 50 step/s² is no step of 100 step/s²: it becomes 100, in the row and under the table.
        QTRY_COMPARE(valueIndex(QStringLiteral("acceleration")).data().toString(),
                     QStringLiteral("100 step/s²"));
        const QModelIndex state = valueIndex(QStringLiteral("acceleration"))
                                      .siblingAtColumn(RegisterTableModel::StateColumn);
        QVERIFY2(state.data().toString().contains(QLatin1String("snapped")),
                 qPrintable(state.data().toString()));
        auto *note =
            workspace()->memoryPage()->findChild<QLabel *>(QStringLiteral("memoryValueNote"));
        QVERIFY(note && !note->isHidden());
        QVERIFY2(note->text().contains(QStringLiteral("50 step/s²"))
                     && note->text().contains(QStringLiteral("100 step/s²")),
                 qPrintable(note->text()));
        // Applied, it is what the servo holds: one step.
        workspace()->findChild<QPushButton *>(QStringLiteral("tableApplyButton"))->click();
        model::ParameterModel *parameters =
            client()->servos()->parameters(workspace()->currentIndex());
        QTRY_COMPARE(parameters->state(QStringLiteral("acceleration")), model::State::Verified);
        QCOMPARE(simulatorValue(1, QStringLiteral("acceleration")), 1);
        // A value on a step is taken without a note; the row's note goes with the edit.
        QVERIFY(table->model()->setData(valueIndex(QStringLiteral("acceleration")),
                                        QStringLiteral("300")));
        QVERIFY(!valueIndex(QStringLiteral("acceleration"))
                     .siblingAtColumn(RegisterTableModel::StateColumn)
                     .data()
                     .toString()
                     .contains(QLatin1String("snapped")));
    }

    void anUnplugLeavesNoStaleScanNorHealthOutcome()
    {
        connectAndScan();
        auto *scanState = workspace()->findChild<QLabel *>(QStringLiteral("scanState"));
        QVERIFY(scanState->text().contains(QLatin1String("3 servo(s) found")));
        auto *healthState =
            workspace()->healthPage()->findChild<QLabel *>(QStringLiteral("healthState"));
        QVERIFY(workspace()->healthPage()->check());
        QTRY_VERIFY_WITH_TIMEOUT(healthState->text().contains(QLatin1String("checked")), 20000);
        m_simulator->stop();
        QTRY_VERIFY_WITH_TIMEOUT(!client()->link()->isConnected(), 10000);
        // The list stays for a reconnect, but no scan outcome speaks for it now.
        QCOMPARE(client()->servos()->count(), 3);
        QVERIFY2(scanState->text().startsWith(QLatin1String("Not connected")),
                 qPrintable(scanState->text()));
        QCOMPARE(healthState->text(), QString());
        auto *healthTable =
            workspace()->healthPage()->findChild<QTableWidget *>(QStringLiteral("healthTable"));
        QCOMPARE(healthTable->item(0, HealthPage::VerdictColumn)->text(),
                 QStringLiteral("not checked"));
    }

    void settingsIdChangeAsksThenFollowsTheServo()
    {
        connectAndScan();
        ParameterPage *settings = workspace()->settingsPage();
        auto *idEditor = qobject_cast<QSpinBox *>(settings->editor(QStringLiteral("id")));
        QVERIFY(idEditor);
        QTRY_VERIFY(idEditor->isEnabled());
        idEditor->setValue(7);
        acceptNextMessageBox();
        settings->findChild<QPushButton *>(QStringLiteral("applyButton"))->click();
        QTRY_VERIFY_WITH_TIMEOUT(client()->servos()->indexOf({7, k1M}) >= 0, 10000);
        QCOMPARE(client()->servos()->indexOf({1, k1M}), -1);
        QTRY_COMPARE(client()->servos()->at(workspace()->currentIndex()).info.id, quint8(7));
        QCOMPARE(simulatorValue(7, QStringLiteral("id")), 7);
        // Verified, and the page keeps saying so once the status bar's message has gone.
        auto *verified = workspace()->findChild<QLabel *>(QStringLiteral("verifiedMark"));
        QTRY_VERIFY(verified && !verified->isHidden());
        QVERIFY2(verified->text().contains(QLatin1String("Verified"))
                     && verified->text().contains(QLatin1String("7")),
                 qPrintable(verified->text()));
        // The tree shows it under its new ID.
        QTreeWidgetItem *baud = workspace()->servoTree()->topLevelItem(0)->child(0);
        QStringList ids;
        for (int i = 0; i < baud->childCount(); ++i)
            ids.append(baud->child(i)->text(0));
        QVERIFY(ids.contains(QStringLiteral("ID 7")));
    }

    // The mark under the servo's header speaks of that servo only: fixes of the settings check
    // on other servos say their outcome on the Health page, not under ID 1.
    void fixesOfOtherServosPutNoVerifiedMarkUnderTheServoShown()
    {
        connectAndScan();
        QCOMPARE(client()->servos()->at(workspace()->currentIndex()).info.id, quint8(1));
        QVector<feetech::SettingsFinding> findings;
        for (const quint8 id : {1, 2}) {
            setSimulatorValue(id, QStringLiteral("return_delay"), 250);
            feetech::SettingsFinding finding;
            finding.servo = client()->servos()->at(client()->servos()->indexOf({id, k1M})).info;
            finding.code = QStringLiteral("return-delay");
            finding.key = QStringLiteral("return_delay");
            finding.value = 250;
            finding.expected = 0;
            findings.append(finding);
        }
        feetech::OperationReply *reply = client()->settingsCheck()->fix(findings);
        QVERIFY(reply);
        QSignalSpy finished(reply, &feetech::OperationReply::finished);
        QVERIFY(finished.wait(10000));
        QVERIFY(finished.first().first().value<feetech::OperationResult>().ok);
        QCOMPARE(simulatorValue(2, QStringLiteral("return_delay")), 0);
        // "2 of 2 fixed" is not ID 1's to say.
        auto *verified = workspace()->findChild<QLabel *>(QStringLiteral("verifiedMark"));
        QVERIFY(verified);
        QVERIFY2(verified->isHidden(), qPrintable(verified->text()));
    }

    // A servo unplugged mid-stream: its missed samples are in the status bar's counters, which
    // said "timeouts 0" while the Monitor counted them.
    void theStatusBarCountsWhatAStreamMissed()
    {
        connectAndScan();
        QVERIFY(client()->telemetry()->subscribe(this, {0, 1, 2}, 50));
        const auto stop = qScopeGuard([this] { client()->telemetry()->unsubscribe(this); });
        QSignalSpy samples(client()->telemetry(), &feetech::TelemetryHub::samplesReceived);
        QVERIFY(samples.wait(5000));
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(1); });
        auto *counters = m_window->findChild<QLabel *>(QStringLiteral("linkCounters"));
        QVERIFY(counters);
        QTRY_VERIFY_WITH_TIMEOUT(counters->text().contains(QLatin1String("stream missed")), 10000);
    }

    void unknownModelIsReadOnlyRawBytes()
    {
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(2)->setValue(u"model_major", 77);
        });
        connectAndScan();
        workspace()->selectServo({2, k1M});
        QTRY_VERIFY(client()->servos()->at(workspace()->currentIndex()).read);
        workspace()->tabs()->setCurrentIndex(1);
        const QModelIndex byte = valueIndex(QStringLiteral("byte_003"));
        QVERIFY(byte.isValid());
        QCOMPARE(byte.data().toString(), QStringLiteral("77"));
        QVERIFY(!(byte.flags() & Qt::ItemIsEditable));
        QVERIFY(!m_window->findChild<QPushButton *>(QStringLiteral("changeIdButton"))->isEnabled());
    }
};

QTEST_MAIN(TestFeetechGui)
#include "tst_feetechgui.moc"
