// The arm calibration wizard and the calibration file actions, offscreen against a simulated
// SO-101 arm whose joints a scripted hand turns: results, verified writes, Cancel, LeRobot files.
#include "feetechbus.h"
#include "scriptedhand.h"

#include "calibrationfiles.h"
#include "calibrationsaver.h"
#include "calibrationwizard.h"
#include "lerobotcalibration.h"
#include "loadcalibrationdialog.h"
#include "mainwindow.h"
#include "recentfiles.h"
#include "robottemplate.h"
#include "setupwizard.h"

#include <QAction>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QScopeGuard>
#include <QSettings>
#include <QStyledItemDelegate>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

using testsupport::ScriptedHand;

namespace {

constexpr int kOffsetAddress = 31;

// A language that names one joint: what the window shows changes, the file's keys do not.
class JointTranslator : public QTranslator
{
public:
    QString translate(const char *context, const char *source, const char *, int) const override
    {
        if (qstrcmp(context, "Joint") == 0 && qstrcmp(source, "shoulder_pan") == 0)
            return QStringLiteral("Schulterdrehung");
        return {};
    }
    bool isEmpty() const override { return false; }
};

} // namespace

class TestCalibrationWizard : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;

    void startArm()
    {
        QVector<sim::FeetechServoSpec> specs;
        for (int id = 1; id <= 6; ++id)
            specs.append({quint8(id), QStringLiteral("STS3215"), 1000000});
        QString error;
        QVERIFY2(startSimulator(busOptions(specs), &error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 6));
        QCOMPARE(m_client->servos()->count(), 6);
    }

    static QString summary(const CalibrationWizard &wizard)
    {
        return wizard.findChild<QLabel *>(QStringLiteral("calibrationResultsSummary"))->text();
    }
    static QString status(const CalibrationWizard &wizard)
    {
        return wizard.findChild<QLabel *>(QStringLiteral("calibrationStatus"))->text();
    }

    // Answers the next file dialog once it shows: *folderShown says whether it opened in the
    // folder of the file it offers (which must exist for that), `accept` whether it is accepted.
    static void answerFileDialog(bool *folderShown, bool accept)
    {
        auto *poll = new QTimer;
        poll->setInterval(10);
        QObject::connect(poll, &QTimer::timeout, poll, [poll, folderShown, accept] {
            auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            const QStringList offered = dialog->selectedFiles();
            *folderShown = offered.size() == 1
                && QDir(dialog->directory()).absolutePath()
                    == QFileInfo(offered.first()).absolutePath();
            if (accept)
                QMetaObject::invokeMethod(dialog, "accept"); // protected, a slot
            else
                dialog->reject();
            poll->deleteLater();
        });
        poll->start();
    }

    // Answers the arm's name (asked before the first save of an arm) with `name`; nothing
    // when empty: the question is cancelled.
    static void answerArmName(const QString &name)
    {
        auto *poll = new QTimer;
        poll->setInterval(10);
        QObject::connect(poll, &QTimer::timeout, poll, [poll, name] {
            auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            if (name.isEmpty()) {
                dialog->reject();
            } else {
                dialog->setTextValue(name);
                dialog->accept();
            }
            poll->deleteLater();
        });
        poll->start();
    }

    static void click(QWidget *parent, const char *name)
    {
        auto *button = parent->findChild<QPushButton *>(QLatin1String(name));
        QVERIFY2(button, name);
        QVERIFY2(button->isEnabled(), name);
        button->click();
    }

    // Torque off and recording, the hand starting once every joint has been sampled.
    static void startRecording(CalibrationWizard &wizard, ScriptedHand &hand)
    {
        click(&wizard, "calibrationNextButton");
        QCOMPARE(wizard.page(), CalibrationWizard::Page::Warning);
        hand.start([&wizard] {
            if (wizard.page() != CalibrationWizard::Page::Recording)
                return false;
            const auto &joints = wizard.recordings();
            return std::all_of(joints.begin(), joints.end(),
                               [](const auto &joint) { return joint.range.hasSamples(); });
        });
        click(&wizard, "torqueOffStartButton");
    }

private slots:
    void init() { QSettings().clear(); } // nothing remembered from an earlier case

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void theWizardCalibratesTheArmAndSavesLeRobotsFile()
    {
        startArm();
        setSimulatorValue(3, u"position_offset", 300);
        CalibrationWizard wizard(m_client.get());
        wizard.show();
        auto *table = wizard.findChild<QTableWidget *>(QStringLiteral("calibrationJointTable"));
        QCOMPARE(table->item(0, 3)->text(), QStringLiteral("shoulder_pan"));
        QCOMPARE(table->item(4, 3)->text(), QStringLiteral("wrist_roll"));
        QCOMPARE(table->item(4, 4)->checkState(), Qt::Checked); // full turn, from the template
        table->item(5, 3)->setText(QStringLiteral("claw"));

        ScriptedHand hand(*m_simulator);
        hand.place(1, 2000);
        hand.script(1, {500, 3000, 1800});
        hand.place(2, 3600);
        hand.script(2, {3500, 4096 + 700, 4000});
        hand.place(3, 2000);
        hand.script(3, {1200, 2800, 2100});
        hand.place(4, 2048);
        hand.script(4, {1000, 3000, 2000});
        hand.place(5, 100);
        hand.script(5, {1100, 600});
        hand.place(6, 2100);
        hand.script(6, {1900, 2600, 2000});
        startRecording(wizard, hand);
        const QString warning = wizard.findChild<QLabel *>(QStringLiteral("torqueWarning"))->text();
        QVERIFY(warning.startsWith(QLatin1String("Support the arm")));
        // A joint a line: no separator of one language between them, and the page is filled.
        QCOMPARE(warning.count(QStringLiteral("\n• ")), 6);
        QTRY_COMPARE_WITH_TIMEOUT(wizard.page(), CalibrationWizard::Page::Recording, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 30000);
        // What the servo read while recording: the elbow's offset of 300 taken off.
        QTRY_COMPARE(wizard.recordings().at(1).range.maximum(), 4096 + 700);
        QTRY_COMPARE(wizard.recordings().at(2).range.minimum(), 1200 - 300);
        QTRY_COMPARE(wizard.recordings().at(5).range.present(), 2000);
        QVERIFY(wizard.findChild<QLabel *>(QStringLiteral("rangeValues_2"))
                    ->text()
                    .contains(QLatin1String("max 4796")));

        click(&wizard, "finishRecordingButton");
        QCOMPARE(wizard.page(), CalibrationWizard::Page::Results);
        const int offsets[] = {1750 - 2048, 4148 - 4096 - 2048, 2000 - 2048,
                               2000 - 2048, 600 - 2048,         2250 - 2048};
        for (int i = 0; i < 6; ++i) {
            QVERIFY2(wizard.results().at(i).ok(), qPrintable(wizard.results().at(i).refusal));
            QCOMPARE(wizard.results().at(i).offset, offsets[i]);
        }
        QCOMPARE(testsupport::writesReceived(logPath(), 2, kOffsetAddress),
                 0); // nothing until Write
        QVERIFY(summary(wizard).endsWith(QLatin1String("Nothing has been written yet.")));

        QSignalSpy written(&wizard, &CalibrationWizard::writingFinished);
        click(&wizard, "writeCalibrationButton");
        QVERIFY(written.wait(20000));
        QCOMPARE(written.first().at(0).toBool(), true);
        auto *results = wizard.findChild<QTableWidget *>(QStringLiteral("calibrationResultTable"));
        QCOMPARE(results->item(1, 4)->text(), QStringLiteral("Written and verified"));
        // The page says one thing of the writes, and it is what happened.
        QCOMPARE(summary(wizard),
                 QStringLiteral("Every joint's offset and limits were written to its EEPROM and "
                                "read back as written."));
        QCOMPARE(status(wizard),
                 QStringLiteral("Save LeRobot's file if you use LeRobot with this arm."));
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
        QCOMPARE(simulatorValue(2, u"position_offset"), -1996);
        QCOMPARE(simulatorValue(2, u"min_angle_limit"), 2048 - 648);
        QCOMPARE(simulatorValue(2, u"max_angle_limit"), 2048 + 648);
        QCOMPARE(simulatorValue(5, u"max_angle_limit"), 4095);

        const QString file = m_dir.filePath(QStringLiteral("follower.json"));
        util::FileError error;
        QVERIFY2(wizard.saveLeRobotFile(file, &error), qPrintable(error.describe()));
        const auto saved = feetech::loadLeRobotCalibration(file, &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->size(), 6);
        QCOMPARE(saved->at(5).name, QStringLiteral("claw"));
        QCOMPARE(saved->at(1).homingOffset, -1996);
        QVERIFY(!m_client->telemetry()->isStreaming());
    }

    void leRobotsOrderTakesTheMiddlePoseFirst()
    {
        startArm();
        CalibrationWizard wizard(m_client.get());
        wizard.findChild<QRadioButton *>(QStringLiteral("middlePoseFirstRadio"))->setChecked(true);
        ScriptedHand hand(*m_simulator);
        for (quint8 id = 1; id <= 6; ++id)
            hand.place(id, 1000 + 100 * id);
        hand.script(1, {600, 1600, 1100});
        click(&wizard, "calibrationNextButton");
        click(&wizard, "torqueOffStartButton");
        QTRY_COMPARE_WITH_TIMEOUT(wizard.page(), CalibrationWizard::Page::MiddlePose, 10000);
        QTRY_VERIFY(m_client->telemetry()->latestSample(5).has_value());
        for (int i = 0; i < 6; ++i)
            QTRY_VERIFY(m_client->telemetry()->latestSample(i).has_value());
        hand.start([&wizard] {
            return wizard.page() == CalibrationWizard::Page::Recording
                && wizard.recordings().first().range.hasSamples();
        });
        click(&wizard, "takeMiddlePoseButton");
        QCOMPARE(wizard.recordings().first().middlePose, std::optional<int>(1100));
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 30000);
        QTRY_COMPARE(wizard.recordings().first().range.maximum(), 1600);
        QTRY_COMPARE(wizard.recordings().first().range.present(), 1100);
        click(&wizard, "finishRecordingButton");
        const feetech::JointCalibration &pan = wizard.results().first();
        QVERIFY2(pan.ok(), qPrintable(pan.refusal));
        QCOMPARE(pan.offset, 1100 - 2047);
        QCOMPARE(pan.minimumLimit, 2047 - 500);
        QCOMPARE(pan.maximumLimit, 2047 + 500);
        // The joints the hand never moved are refused, and only the pan is written.
        QVERIFY(wizard.results().at(1).refusal.contains(QLatin1String("never moved")));
        QSignalSpy written(&wizard, &CalibrationWizard::writingFinished);
        click(&wizard, "writeCalibrationButton");
        QVERIFY(written.wait(20000));
        QCOMPARE(summary(wizard),
                 QStringLiteral("1 of 6 joint(s) were written and verified; the "
                                "status column says what became of the "
                                "others."));
        QCOMPARE(simulatorValue(1, u"position_offset"), 1100 - 2047);
        for (quint8 id = 2; id <= 6; ++id)
            QCOMPARE(testsupport::writesReceived(logPath(), id, kOffsetAddress), 0);
    }

    void cancelWritesNothing()
    {
        startArm();
        auto *wizard = new CalibrationWizard(m_client.get());
        wizard->setAttribute(Qt::WA_DeleteOnClose);
        wizard->show();
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.script(1, {600, 1600});
        startRecording(*wizard, hand);
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 30000);
        QVERIFY(m_client->telemetry()->isStreaming());
        // The window stays usable, but nothing else moves the joints a hand is turning.
        QCOMPARE(m_client->identify()->blocker(0).code(), feetech::Refusal::Code::ServoHeld);
        QPointer<CalibrationWizard> alive(wizard);
        click(wizard, "calibrationCancelButton");
        QTRY_VERIFY(alive.isNull());
        QVERIFY(!m_client->telemetry()->isStreaming());
        QVERIFY(!m_client->identify()->blocker(0));
        for (quint8 id = 1; id <= 6; ++id)
            QCOMPARE(testsupport::writesReceived(logPath(), id, kOffsetAddress), 0);
    }

    void aWriteThatFailsSaysNothingWasWrittenAndVerified()
    {
        startArm();
        CalibrationWizard wizard(m_client.get());
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.script(1, {600, 1600, 1000});
        startRecording(wizard, hand);
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 30000);
        QTRY_COMPARE(wizard.recordings().first().range.maximum(), 1600);
        click(&wizard, "finishRecordingButton");
        QVERIFY(wizard.results().first().ok());
        // The only joint to write is unplugged before it is written.
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(0); });
        QSignalSpy written(&wizard, &CalibrationWizard::writingFinished);
        click(&wizard, "writeCalibrationButton");
        QVERIFY(written.wait(30000));
        QCOMPARE(written.first().at(0).toBool(), false);
        QCOMPARE(summary(wizard),
                 QStringLiteral("No joint's calibration was written and "
                                "verified: the status column says why."));
        QVERIFY(status(wizard).isEmpty());
        QVERIFY(
            !wizard.findChild<QPushButton *>(QStringLiteral("saveLeRobotFileButton"))->isEnabled());
    }

    void recordingAgainForgetsTheFirstRecording()
    {
        startArm();
        CalibrationWizard wizard(m_client.get());
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.script(1, {600, 1600, 1000});
        startRecording(wizard, hand);
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 30000);
        QTRY_COMPARE(wizard.recordings().first().range.maximum(), 1600);
        click(&wizard, "finishRecordingButton");
        QVERIFY(wizard.results().first().ok());
        QVERIFY(!m_client->telemetry()->isStreaming());
        click(&wizard, "recordAgainButton");
        QCOMPARE(wizard.page(), CalibrationWizard::Page::Recording);
        QVERIFY(m_client->telemetry()->isStreaming());
        // The joint rests at 1000 now: that is all the new recording holds.
        QTRY_VERIFY(wizard.recordings().first().range.hasSamples());
        QCOMPARE(wizard.recordings().first().range.maximum(), 1000);
        click(&wizard, "finishRecordingButton");
        QVERIFY(wizard.results().first().refusal.contains(QLatin1String("never moved")));
        QCOMPARE(testsupport::writesReceived(logPath(), 1, kOffsetAddress), 0);
    }

    void aLoadedFileShowsItsDifferencesAndIsWrittenVerified()
    {
        startArm();
        const QVector<feetech::LeRobotMotor> motors {
            {QStringLiteral("shoulder_pan"), 1, 0, -1200, 800, 3300},
            {QStringLiteral("elbow_flex"), 3, 0, 0, 0, 4095},
            {QStringLiteral("ghost"), 9, 0, 0, 10, 20}};
        LoadCalibrationDialog dialog(m_client.get(), motors, QStringLiteral("arm.json"));
        QSignalSpy ready(&dialog, &LoadCalibrationDialog::ready);
        QVERIFY(dialog.isReady() || ready.wait(10000));
        QCOMPARE(dialog.changedJoints(), 1);
        auto *table = dialog.findChild<QTableWidget *>(QStringLiteral("calibrationDiffTable"));
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("0 → -1200"));
        QCOMPARE(table->item(1, 4)->text(), QStringLiteral("Unchanged"));
        QVERIFY(table->item(2, 4)->text().contains(QLatin1String("not on the bus")));
        QCOMPARE(testsupport::writesReceived(logPath(), 1, kOffsetAddress),
                 0); // nothing before Write
        QSignalSpy written(&dialog, &LoadCalibrationDialog::writingFinished);
        click(&dialog, "writeLoadedCalibrationButton");
        QVERIFY(written.wait(20000));
        QCOMPARE(written.first().at(0).toBool(), true);
        QCOMPARE(table->item(0, 4)->text(), QStringLiteral("Written and verified"));
        QCOMPARE(simulatorValue(1, u"position_offset"), -1200);
        QCOMPARE(simulatorValue(1, u"max_angle_limit"), 3300);
    }

    void aServoOfTheFileThatDoesNotAnswerIsNotWritten()
    {
        startArm();
        // Index 1: servo ID 2, found by the scan, silent now.
        m_simulator->call([](sim::Simulator &simulator) { simulator.feetechBus()->unplug(1); });
        const QVector<feetech::LeRobotMotor> motors {
            {QStringLiteral("shoulder_pan"), 1, 0, -1200, 800, 3300},
            {QStringLiteral("shoulder_lift"), 2, 0, -500, 700, 3000}};
        LoadCalibrationDialog dialog(m_client.get(), motors, QStringLiteral("arm.json"));
        QSignalSpy ready(&dialog, &LoadCalibrationDialog::ready);
        QVERIFY(dialog.isReady() || ready.wait(20000));
        QCOMPARE(dialog.changedJoints(), 1);
        auto *table = dialog.findChild<QTableWidget *>(QStringLiteral("calibrationDiffTable"));
        QVERIFY2(table->item(1, 4)->text().contains(QLatin1String("could not be read")),
                 qPrintable(table->item(1, 4)->text()));
        QCOMPARE(table->item(0, 4)->text(), QStringLiteral("To write"));
        QSignalSpy written(&dialog, &LoadCalibrationDialog::writingFinished);
        click(&dialog, "writeLoadedCalibrationButton");
        QVERIFY(written.wait(20000));
        QCOMPARE(written.first().at(0).toBool(), true);
        QCOMPARE(simulatorValue(1, u"position_offset"), -1200);
        QCOMPARE(testsupport::writesReceived(logPath(), 2, kOffsetAddress), 0);
    }

    void theSavedCalibrationNamesTheJointsByTheTemplate()
    {
        startArm();
        setSimulatorValue(2, u"position_offset", -5);
        CalibrationSaver saver(m_client.get());
        QSignalSpy finished(&saver, &CalibrationSaver::finished);
        const QString file = m_dir.filePath(QStringLiteral("saved.json"));
        util::FileError error;
        QVERIFY2(saver.save(file, &error), qPrintable(error.describe()));
        QVERIFY(finished.wait(20000));
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        const auto saved = feetech::loadLeRobotCalibration(file, &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->size(), 6);
        QCOMPARE(saved->at(1).name, QStringLiteral("shoulder_lift"));
        QCOMPARE(saved->at(1).homingOffset, -5);
    }

    void jointNamesShowInTheUsersLanguageAndStayLeRobotsKeys()
    {
        JointTranslator translator;
        QVERIFY(QCoreApplication::installTranslator(&translator));
        startArm();
        CalibrationWizard wizard(m_client.get());
        auto *table = wizard.findChild<QTableWidget *>(QStringLiteral("calibrationJointTable"));
        QTableWidgetItem *pan = table->item(0, 3);
        QCOMPARE(pan->text(), QStringLiteral("shoulder_pan")); // what is edited and saved
        auto *delegate = qobject_cast<QStyledItemDelegate *>(table->itemDelegateForColumn(3));
        QVERIFY(delegate);
        QCOMPARE(delegate->displayText(pan->data(Qt::DisplayRole), QLocale()),
                 QStringLiteral("Schulterdrehung (shoulder_pan)"));
        QCOMPARE(delegate->displayText(table->item(1, 3)->data(Qt::DisplayRole), QLocale()),
                 QStringLiteral("shoulder_lift")); // no translation: the key alone
        click(&wizard, "calibrationNextButton");
        QVERIFY2(wizard.findChild<QLabel *>(QStringLiteral("torqueWarning"))
                     ->text()
                     .contains(QLatin1String("Schulterdrehung (ID 1)")),
                 qPrintable(wizard.findChild<QLabel *>(QStringLiteral("torqueWarning"))->text()));
        QCOMPARE(wizard.recordings().first().name, QStringLiteral("shoulder_pan"));
        QCoreApplication::removeTranslator(&translator);
    }

    void savingOffersLeRobotsFolderForTheArmAndMakesIt()
    {
        QTemporaryDir root;
        QVERIFY(root.isValid());
        const QByteArray saved = qgetenv("HF_LEROBOT_CALIBRATION");
        qputenv("HF_LEROBOT_CALIBRATION", QFile::encodeName(root.path()));
        const auto restore = qScopeGuard([&saved] {
            if (saved.isNull())
                qunsetenv("HF_LEROBOT_CALIBRATION");
            else
                qputenv("HF_LEROBOT_CALIBRATION", saved);
        });
        const feetech::RobotTemplate *follower =
            feetech::defaultRobotTemplateIn(feetech::builtInRobotTemplates());
        QVERIFY(follower);
        const QString folder = root.filePath(QStringLiteral("robots/so101_follower"));
        QCOMPARE(suggestedCalibrationFile(follower),
                 QDir(folder).filePath(QStringLiteral("my_arm.json")));

        // The first save asks the arm's name, which names the file, as LeRobot's --robot.id
        // does; cancelled, nothing is offered and no folder is made.
        answerArmName({});
        QVERIFY(chooseCalibrationFileToSave(nullptr, QStringLiteral("Save"), follower).isEmpty());
        QVERIFY(!QDir(root.filePath(QStringLiteral("robots"))).exists());
        const QString suggested = QDir(folder).filePath(QStringLiteral("left_follower.json"));

        // Cancelled at the file: the folders made for the dialog go again.
        bool folderShown = false;
        answerArmName(QStringLiteral("left follower"));
        answerFileDialog(&folderShown, false);
        QVERIFY(chooseCalibrationFileToSave(nullptr, QStringLiteral("Save"), follower).isEmpty());
        QVERIFY(folderShown);
        QVERIFY(!QDir(root.filePath(QStringLiteral("robots"))).exists());

        // Saved there: the folder stays, and the next offer is the file used last.
        folderShown = false;
        answerArmName(QStringLiteral("left_follower"));
        answerFileDialog(&folderShown, true);
        QCOMPARE(chooseCalibrationFileToSave(nullptr, QStringLiteral("Save"), follower), suggested);
        QVERIFY(folderShown);
        QVERIFY(QDir(folder).exists());
        const QString renamed = QDir(folder).filePath(QStringLiteral("follower_a.json"));
        QVERIFY(feetech::saveLeRobotCalibration(
            {{QStringLiteral("shoulder_pan"), 1, 0, 0, 100, 4000}}, renamed, nullptr));
        recentfiles::add(recentfiles::Kind::Calibration, renamed);
        QCOMPARE(suggestedCalibrationFile(follower), renamed);
    }

    void theRobotMenuIsEnabledOnceABusIsScanned()
    {
        QVector<sim::FeetechServoSpec> specs {{1, QStringLiteral("STS3215"), 1000000}};
        QString error;
        QVERIFY2(startSimulator(busOptions(specs), &error), qPrintable(error));
        MainWindow window;
        auto *calibrate = window.findChild<QAction *>(QStringLiteral("calibrateArmAction"));
        QVERIFY(calibrate);
        QVERIFY(!calibrate->isEnabled());
        QVERIFY(testsupport::connectAndScan(*window.feetechClient(), m_simulator->linkPath(), 3));
        QTRY_VERIFY(calibrate->isEnabled());
        QVERIFY(window.findChild<QAction *>(QStringLiteral("loadCalibrationAction"))->isEnabled());
        // Modeless, so that the window (the demo's Simulator dock) stays usable; one at a time,
        // and no motor set-up beside it.
        calibrate->trigger();
        QPointer<CalibrationWizard> wizard = window.findChild<CalibrationWizard *>();
        QVERIFY(wizard);
        QVERIFY(wizard->isVisible());
        QCOMPARE(wizard->windowModality(), Qt::NonModal);
        calibrate->trigger();
        QCOMPARE(window.findChildren<CalibrationWizard *>().size(), 1);
        auto *setUp = window.findChild<QAction *>(QStringLiteral("setUpMotorsAction"));
        QVERIFY(setUp && setUp->isEnabled());
        setUp->trigger();
        QVERIFY(!window.findChild<SetupWizard *>());
        auto *banner = window.findChild<QLabel *>(QStringLiteral("problemBanner"));
        QVERIFY(!banner->isHidden());
        QVERIFY2(banner->text().startsWith(QLatin1String("Close the calibration wizard")),
                 qPrintable(banner->text()));
        // The banner's problem came while the wizard was open: it goes with it.
        wizard->close();
        QTRY_VERIFY(wizard.isNull());
        QVERIFY(banner->isHidden());
        // Without the calibration, the set-up opens; the calibration is refused beside it.
        setUp->trigger();
        auto *setUpWizard = window.findChild<SetupWizard *>();
        QVERIFY(setUpWizard && setUpWizard->isVisible());
        calibrate->trigger();
        QVERIFY(!window.findChild<CalibrationWizard *>());
        QVERIFY(banner->text().startsWith(QLatin1String("Close the motor set-up")));
        QTRY_VERIFY_WITH_TIMEOUT(!setUpWizard->flow()->isWorking(), 20000);
        QTest::keyClick(setUpWizard, Qt::Key_Escape);
        QVERIFY(!setUpWizard->isVisible());
        QVERIFY(banner->isHidden());
        window.feetechClient()->disconnectFrom();
        QTRY_VERIFY(!calibrate->isEnabled());
    }
};

QTEST_MAIN(TestCalibrationWizard)
#include "tst_calibrationwizard.moc"
