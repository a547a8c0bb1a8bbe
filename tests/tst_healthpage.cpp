// GUI tests of the Health page against a simulated bus: the empty state, a check with its
// verdicts in colour, cancelling, the move test's confirmation, saving the report, and the
// Settings section: its findings, Fix and Fix all, verified on the simulated bus.
#include "feetechbus.h"
#include "feetechworkspace.h"
#include "healthpage.h"
#include "settingscheckpanel.h"

#include <QComboBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTableWidget>
#include <QtTest>

#include <memory>

namespace {

constexpr qint32 k1M = 1000000;

} // namespace

class TestHealthPage : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<HealthPage> m_page;

    void startSimulatorAndScan(std::initializer_list<QStringView> models)
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, models)), &error),
                 qPrintable(error));
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 4));
        QCOMPARE(m_client->servos()->count(), int(models.size()));
    }

    QString cell(int row, int column) const
    {
        const QTableWidgetItem *item = m_page->table()->item(row, column);
        return item ? item->text() : QString();
    }

    // Clicks Check and waits for the verdicts.
    void checkAll()
    {
        QSignalSpy finished(m_client->health(), &feetech::HealthService::checkFinished);
        QTRY_VERIFY_WITH_TIMEOUT(m_page->checkButton()->isEnabled(), 10000);
        QTest::mouseClick(m_page->checkButton(), Qt::LeftButton);
        QVERIFY(m_page->progressBar()->isVisible());
        QVERIFY(finished.wait(20000));
        QVERIFY(!m_page->progressBar()->isVisible());
    }

    // Clicks Check settings and waits for the findings.
    void checkSettings()
    {
        SettingsCheckPanel *panel = m_page->settingsPanel();
        QSignalSpy checked(m_client->settingsCheck(), &feetech::SettingsCheckService::checked);
        QTRY_VERIFY_WITH_TIMEOUT(panel->checkButton()->isEnabled(), 10000);
        QTest::mouseClick(panel->checkButton(), Qt::LeftButton);
        QVERIFY(checked.wait(20000));
    }

    // Clicks `button` (a Fix or Fix all) and waits for the fix's outcomes.
    void clickFix(QPushButton *button)
    {
        QSignalSpy fixed(m_client->settingsCheck(), &feetech::SettingsCheckService::fixed);
        QVERIFY(button);
        QTRY_VERIFY_WITH_TIMEOUT(button->isEnabled(), 10000);
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(fixed.wait(20000));
    }

    QString settingsCell(int row, int column) const
    {
        const QTableWidgetItem *item = m_page->settingsPanel()->table()->item(row, column);
        return item ? item->text() : QString();
    }

    int writesReceived() const
    {
        return int(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size());
    }

private slots:
    void init()
    {
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
        m_page = std::make_unique<HealthPage>(m_client.get());
        m_page->resize(1100, 600);
        m_page->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
    }

    void cleanup()
    {
        m_page.reset();
        m_client.reset();
        m_simulator.reset();
    }

    void withoutServosItShowsTheEmptyStateAndNothingToDo()
    {
        QVERIFY(m_page->emptyState()->isVisible());
        QVERIFY(!m_page->table()->isVisible());
        QVERIFY(!m_page->checkButton()->isEnabled());
        QVERIFY(!m_page->moveTestButton()->isEnabled());
        QVERIFY(!m_page->saveButton()->isEnabled());
        QString error;
        QVERIFY(!m_page->check(&error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(m_page->stateLabel()->text(), error);
    }

    void aSettingsFindingIsShownAndItsFixMakesItGoAwayOnTheBus()
    {
        startSimulatorAndScan({u"STS3215", u"STS3215"});
        SettingsCheckPanel *panel = m_page->settingsPanel();
        QVERIFY(panel->isVisible());
        setSimulatorValue(2, u"return_delay", 250);
        checkSettings();
        QCOMPARE(panel->table()->rowCount(), 1);
        QCOMPARE(settingsCell(0, SettingsCheckPanel::IdColumn), QStringLiteral("2"));
        QCOMPARE(settingsCell(0, SettingsCheckPanel::SettingColumn),
                 QStringLiteral("return_delay"));
        QCOMPARE(settingsCell(0, SettingsCheckPanel::ValueColumn), QStringLiteral("250"));
        QCOMPARE(settingsCell(0, SettingsCheckPanel::ExpectedColumn), QStringLiteral("0"));
        QVERIFY(!settingsCell(0, SettingsCheckPanel::WhyColumn).isEmpty());
        QCOMPARE(writesReceived(), 0);

        clickFix(panel->fixButton(0));
        QCOMPARE(settingsCell(0, SettingsCheckPanel::ResultColumn),
                 QStringLiteral("Fixed, verified"));
        QVERIFY(!panel->fixButton(0)->isEnabled());
        QCOMPARE(simulatorValue(2, u"return_delay"), 0);
        QCOMPARE(simulatorValue(2, u"lock"), 1);

        checkSettings();
        QCOMPARE(panel->table()->rowCount(), 0);
        QVERIFY(panel->stateLabel()->text().contains(QStringLiteral("No problem")));
    }

    void fixAllFixesWhatTorqueAllowsAndSaysWhyNotForTheRest()
    {
        startSimulatorAndScan({u"STS3215", u"STS3215"});
        SettingsCheckPanel *panel = m_page->settingsPanel();
        panel->chooseTemplate(QStringLiteral("SO-101 follower arm"));
        setSimulatorValue(1, u"mode", 1);
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) {
            s.setValue(u"goal_position", s.value(u"present_position"));
            s.setValue(u"torque_enable", 1);
        }));
        checkSettings();
        QVERIFY(panel->table()->rowCount() > 1);
        int modeRow = -1;
        for (int row = 0; row < panel->table()->rowCount(); ++row) {
            if (settingsCell(row, SettingsCheckPanel::SettingColumn) == QLatin1String("mode")
                && settingsCell(row, SettingsCheckPanel::IdColumn) == QLatin1String("1"))
                modeRow = row;
        }
        QVERIFY(modeRow >= 0);
        clickFix(panel->fixAllButton());
        QVERIFY2(settingsCell(modeRow, SettingsCheckPanel::ResultColumn)
                     .contains(QStringLiteral("torque is on")),
                 qPrintable(settingsCell(modeRow, SettingsCheckPanel::ResultColumn)));
        QVERIFY(panel->fixButton(modeRow)->isEnabled()); // it can be tried again, torque off
        QCOMPARE(simulatorValue(1, u"mode"), 1);
        // The template's gains are written, and nothing else is left to fix.
        QCOMPARE(simulatorValue(1, u"p_gain"), 16);
        QCOMPARE(simulatorValue(2, u"p_gain"), 16);
        QVERIFY(m_page->settingsPanel()->fixAllButton()->isEnabled());
        setSimulatorValue(1, u"torque_enable", 0);
        clickFix(panel->fixButton(modeRow));
        QCOMPARE(settingsCell(modeRow, SettingsCheckPanel::ResultColumn),
                 QStringLiteral("Fixed, verified"));
        QCOMPARE(simulatorValue(1, u"mode"), 0);
        QVERIFY(!panel->fixAllButton()->isEnabled());
    }

    void aFixOfAServoUnpluggedSinceTheCheckSaysWhyInItsRow()
    {
        startSimulatorAndScan({u"STS3215", u"STS3215"});
        SettingsCheckPanel *panel = m_page->settingsPanel();
        setSimulatorValue(2, u"return_delay", 250);
        checkSettings();
        QCOMPARE(panel->table()->rowCount(), 1);
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(1); });
        clickFix(panel->fixButton(0));
        const QString result = settingsCell(0, SettingsCheckPanel::ResultColumn);
        QVERIFY2(result.contains(QStringLiteral("servo 2 does not answer")), qPrintable(result));
        QVERIFY(panel->fixButton(0)->isEnabled()); // it may be tried again once plugged in
        QVERIFY(!panel->stateLabel()->text().isEmpty());
    }

    void withoutServosTheSettingsCheckIsRefusedWithItsReason()
    {
        SettingsCheckPanel *panel = m_page->settingsPanel();
        QVERIFY(!panel->checkButton()->isEnabled());
        QVERIFY(!panel->fixAllButton()->isEnabled());
        QString error;
        QVERIFY(!panel->check(&error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(panel->stateLabel()->text(), error);
    }

    // Four joints of an SO-101 answer, its wrist roll and gripper do not: the check says so, it
    // does not say "4 servo(s) checked" as if that were the arm.
    void jointsOfTheArmThatDoNotAnswerAreAFinding()
    {
        startSimulatorAndScan({u"STS3215", u"STS3215", u"STS3215", u"STS3215"});
        checkAll();
        const QString said = m_page->stateLabel()->text();
        for (const char *part : {"did not answer the scan", "ID 5", "ID 6"})
            QVERIFY2(said.contains(QLatin1String(part)), qPrintable(said));
        // The servos by joint, as the tree names them.
        QCOMPARE(cell(0, 0), QStringLiteral("shoulder_pan (ID 1)"));
    }

    void theWorkspaceHasAHealthTab()
    {
        FeetechWorkspace workspace(m_client.get());
        QVERIFY(workspace.healthPage());
        QCOMPARE(workspace.tabs()->tabText(workspace.tabs()->indexOf(workspace.healthPage())),
                 QStringLiteral("Health"));
    }

    void aCheckShowsEachServosVerdictInColourWithItsReasons()
    {
        startSimulatorAndScan({u"STS3215", u"STS3215"});
        QVERIFY(m_page->table()->isVisible());
        QCOMPARE(m_page->table()->rowCount(), 2);
        QCOMPARE(cell(0, HealthPage::VerdictColumn), QStringLiteral("not checked"));
        const qint32 maximum = simulatorValue(2, u"max_temperature");
        QVERIFY(withServo(
            2, k1M, [maximum](sim::VirtualFeetechServo &s) { s.setTemperature(maximum + 1); }));
        checkAll();
        QCOMPARE(cell(0, HealthPage::VerdictColumn), QStringLiteral("OK"));
        QCOMPARE(cell(0, HealthPage::FirmwareColumn), QStringLiteral("3.10"));
        QVERIFY(cell(0, HealthPage::VoltageColumn).endsWith(QStringLiteral(" V")));
        QVERIFY(cell(0, HealthPage::CommColumn).startsWith(QStringLiteral("20/20")));
        QCOMPARE(cell(1, HealthPage::VerdictColumn), QStringLiteral("Fault"));
        QVERIFY(!cell(1, HealthPage::ReasonsColumn).isEmpty());
        QVERIFY(m_page->table()
                    ->item(1, HealthPage::ReasonsColumn)
                    ->toolTip()
                    .contains(QStringLiteral("temperature-over")));
        QVERIFY(m_page->table()->item(0, HealthPage::VerdictColumn)->foreground().color()
                != m_page->table()->item(1, HealthPage::VerdictColumn)->foreground().color());
        QVERIFY(m_page->saveButton()->isEnabled());
        QCOMPARE(writesReceived(), 0);
    }

    void aCheckCanBeCancelled()
    {
        startSimulatorAndScan({u"STS3215", u"STS3215", u"STS3215", u"STS3215"});
        QSignalSpy finished(m_client->health(), &feetech::HealthService::checkFinished);
        QTRY_VERIFY_WITH_TIMEOUT(m_page->checkButton()->isEnabled(), 10000);
        QVERIFY(m_page->check());
        QVERIFY(m_page->cancelButton()->isEnabled());
        QTest::mouseClick(m_page->cancelButton(), Qt::LeftButton);
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY(m_page->results().size() < 4);
        QTRY_VERIFY_WITH_TIMEOUT(m_page->checkButton()->isEnabled(), 10000);
    }

    void theMoveTestAsksFirstAndMovesNothingWithoutYes()
    {
        startSimulatorAndScan({u"STS3215"});
        checkAll();
        m_page->table()->selectRow(0);
        QTRY_VERIFY_WITH_TIMEOUT(m_page->moveTestButton()->isEnabled(), 10000);
        QString asked;
        m_page->setConfirmation([&asked](const QString &question) {
            asked = question;
            return false;
        });
        QTest::mouseClick(m_page->moveTestButton(), Qt::LeftButton);
        QVERIFY2(asked.startsWith(QStringLiteral("ID 1 (")), qPrintable(asked));
        QVERIFY(m_page->stateLabel()->text().contains(QStringLiteral("nothing moved")));
        QCOMPARE(writesReceived(), 0);

        m_page->setConfirmation([](const QString &) { return true; });
        QSignalSpy moved(m_client->health(), &feetech::HealthService::moveTested);
        QTest::mouseClick(m_page->moveTestButton(), Qt::LeftButton);
        QVERIFY(moved.wait(20000));
        const auto result = moved.first().at(0).value<feetech::MoveTestResult>();
        QVERIFY2(result.ok, qPrintable(result.message));
        QVERIFY(cell(0, HealthPage::MoveColumn).contains(QStringLiteral("rise")));
        QVERIFY(writesReceived() > 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void theReportIsSavedAsHtmlOrJsonAndAFailureIsShown()
    {
        startSimulatorAndScan({u"STS3215"});
        checkAll();
        const QString json = m_dir.filePath(QStringLiteral("health.json"));
        QVERIFY(m_page->saveReport(json));
        QFile file(json);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonArray servos = QJsonDocument::fromJson(file.readAll())
                                      .object()
                                      .value(QStringLiteral("servos"))
                                      .toArray();
        QCOMPARE(servos.size(), 1);
        QCOMPARE(servos.at(0)[QStringLiteral("verdict")].toString(), QStringLiteral("ok"));
        const QString html = m_dir.filePath(QStringLiteral("health.html"));
        QVERIFY(m_page->saveReport(html));
        QVERIFY(QFileInfo(html).size() > 0);

        QSignalSpy problems(m_page.get(), &HealthPage::problem);
        QString error;
        QVERIFY(
            !m_page->saveReport(m_dir.filePath(QStringLiteral("no/such/dir/health.html")), &error));
        QCOMPARE(problems.size(), 1);
        QVERIFY(error.contains(QStringLiteral("health.html")));
        QCOMPARE(m_page->stateLabel()->text(), error);
        QVERIFY(!m_page->saveReport(m_dir.filePath(QStringLiteral("health.txt")), &error));
        QVERIFY(error.contains(QStringLiteral(".json")));
    }
};

QTEST_MAIN(TestHealthPage)
#include "tst_healthpage.moc"
