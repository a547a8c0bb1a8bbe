// GUI tests of the motor replacement wizard against a simulated SO-101 arm over a pty: the new
// servo of joint 3 set up alone, the arm put back, the joint calibrated by a scripted hand into
// the arm's file (its other joints and drive_mode kept), and each refusal.
#include "pluggedbus.h"
#include "scriptedhand.h"

#include "calibrationwizard.h"
#include "connectionbar.h"
#include "lerobotcalibration.h"
#include "mainwindow.h"
#include "replacemotorwizard.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QtTest>

using testsupport::ScriptedHand;

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kElbow = 2; // the template's third joint: elbow_flex, ID 3
constexpr quint8 kElbowId = 3;

const QString kArm = QStringLiteral("SO-101 follower arm");

// The arm's file as a calibration left it: the elbow inverted in LeRobot (drive_mode 1).
const QVector<feetech::LeRobotMotor> kArmFile {
    {QStringLiteral("shoulder_pan"), 1, 0, -120, 800, 3300},
    {QStringLiteral("shoulder_lift"), 2, 0, 310, 700, 3400},
    {QStringLiteral("elbow_flex"), 3, 1, 515, 900, 3100},
    {QStringLiteral("wrist_flex"), 4, 0, -42, 850, 3200},
    {QStringLiteral("wrist_roll"), 5, 0, 7, 0, 4095},
    {QStringLiteral("gripper"), 6, 0, 1000, 2000, 3400},
};

} // namespace

class TestReplaceMotorWizard : public testsupport::PluggedBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<ReplaceMotorWizard> m_wizard;
    feetech::RobotTemplate m_robot = testsupport::builtInRobot(kArm);
    QString m_file;

    QString status() const { return m_wizard->status()->text(); }

    static void click(QWidget *parent, const char *name)
    {
        auto *button = parent->findChild<QPushButton *>(QLatin1String(name));
        QVERIFY2(button, name);
        QVERIFY2(button->isEnabled(), name);
        button->click();
    }

    // The wizard on the connected client, the elbow and `file` chosen.
    void openWizard(const QString &file)
    {
        m_wizard = std::make_unique<ReplaceMotorWizard>(m_client.get());
        const int arm = m_wizard->robotChoice()->findText(kArm);
        QVERIFY(arm >= 0);
        m_wizard->robotChoice()->setCurrentIndex(arm);
        m_wizard->jointChoice()->setCurrentIndex(kElbow);
        m_wizard->fileEdit()->setText(file);
        m_wizard->show();
    }

    // Clicks the wizard's `name` and waits for the set-up work it starts to end.
    void clickAndWait(const char *name)
    {
        click(m_wizard.get(), name);
        QVERIFY(m_wizard->flow()->isWorking());
        QTRY_VERIFY_WITH_TIMEOUT(!m_wizard->flow()->isWorking(), 30000);
    }

    // A factory-new servo alone on the bus, found and set up as the elbow.
    void setUpNewElbow()
    {
        openWizard(m_file);
        click(m_wizard.get(), "replaceNextButton");
        QCOMPARE(m_wizard->page(), ReplaceMotorWizard::Page::SetUp);
        QVERIFY(plug(1, QStringLiteral("STS3215"), testsupport::kFactoryBaud));
        clickAndWait("replaceFindButton");
        QVERIFY2(status().contains(QLatin1String("Found one servo:")), qPrintable(status()));
        QCOMPARE(pluggedServos().first().id, quint8(1)); // a find writes nothing
        clickAndWait("replaceSetUpButton");
        QCOMPARE(m_wizard->page(), ReplaceMotorWizard::Page::Reassemble);
        verifySetUp(0, m_robot, m_robot.joints.at(kElbow));
    }

    // The arm's other five servos plugged back in around the new one.
    void reassembleArm()
    {
        for (const feetech::RobotJoint &joint : std::as_const(m_robot.joints)) {
            if (joint.id != kElbowId)
                QVERIFY(plug(quint8(joint.id), joint.model, m_robot.baud));
        }
    }

private slots:
    void init()
    {
        QSettings().clear(); // nothing remembered from an earlier case
        QString error;
        QVERIFY2(startEmptyBus(&error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
        m_client->connectTo(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->link()->isConnected(), 10000);
        m_file = m_dir.filePath(QStringLiteral("follower.json"));
        util::FileError fileError;
        QVERIFY2(feetech::saveLeRobotCalibration(kArmFile, m_file, &fileError),
                 qPrintable(fileError.describe()));
    }

    void cleanup()
    {
        if (m_wizard && m_wizard->calibrationWizard())
            delete m_wizard->calibrationWizard();
        m_wizard.reset();
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void theNewServoIsSetUpAndItsJointAloneCalibratedIntoTheArmsFile()
    {
        setUpNewElbow();
        reassembleArm();
        QMap<quint8, quint64> revisions; // the other servos' EEPROM writes so far
        for (const testsupport::PluggedServo &servo : pluggedServos())
            revisions.insert(servo.id, servo.revision);

        ScriptedHand hand(*m_simulator);
        hand.place(kElbowId, 2000);
        hand.script(kElbowId, {1200, 2800, 2100});
        click(m_wizard.get(), "replaceScanButton");
        QTRY_VERIFY_WITH_TIMEOUT(m_wizard->calibrationWizard(), 20000);
        QCOMPARE(m_client->servos()->count(), 6);
        CalibrationWizard &calibration = *m_wizard->calibrationWizard();
        QVERIFY(calibration.isVisible());
        // Not modal, as Calibrate arm is not: the Simulator dock (or anything else in the
        // window) can still turn the new joint while it records.
        QCOMPARE(calibration.windowModality(), Qt::NonModal);
        QVERIFY(!QApplication::activeModalWidget());
        QCOMPARE(calibration.updatedFile(), m_file);

        // Only the elbow is ticked and shown, named as the file names it, and it stays so.
        auto *table =
            calibration.findChild<QTableWidget *>(QStringLiteral("calibrationJointTable"));
        QCOMPARE(table->rowCount(), 6);
        for (int row = 0; row < table->rowCount(); ++row) {
            const bool elbow = table->item(row, 1)->text() == QString::number(kElbowId);
            QCOMPARE(table->item(row, 0)->checkState(), elbow ? Qt::Checked : Qt::Unchecked);
            QCOMPARE(table->isRowHidden(row), !elbow);
            if (elbow) {
                QCOMPARE(table->item(row, 3)->text(), QStringLiteral("elbow_flex"));
                QVERIFY(!(table->item(row, 0)->flags() & Qt::ItemIsUserCheckable));
                QVERIFY(!(table->item(row, 3)->flags() & Qt::ItemIsEditable));
            }
        }

        click(&calibration, "calibrationNextButton");
        QCOMPARE(calibration.page(), CalibrationWizard::Page::Warning);
        hand.start([&calibration] {
            return calibration.page() == CalibrationWizard::Page::Recording
                && calibration.recordings().first().range.hasSamples();
        });
        click(&calibration, "torqueOffStartButton");
        QTRY_COMPARE_WITH_TIMEOUT(calibration.page(), CalibrationWizard::Page::Recording, 10000);
        QCOMPARE(calibration.recordings().size(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 30000);
        QTRY_COMPARE(calibration.recordings().first().range.minimum(), 1200);
        QTRY_COMPARE(calibration.recordings().first().range.maximum(), 2800);
        QTRY_COMPARE(calibration.recordings().first().range.present(), 2100);
        click(&calibration, "finishRecordingButton");
        QCOMPARE(calibration.results().size(), 1);
        const feetech::JointCalibration result = calibration.results().first();
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        QCOMPARE(result.offset, 2000 - 2048);

        QSignalSpy written(&calibration, &CalibrationWizard::writingFinished);
        click(&calibration, "writeCalibrationButton");
        QVERIFY(written.wait(20000));
        QCOMPARE(written.first().at(0).toBool(), true);
        QCOMPARE(simulatorValue(kElbowId, u"position_offset"), result.offset);
        QCOMPARE(simulatorValue(kElbowId, u"min_angle_limit"), result.minimumLimit);
        QCOMPARE(simulatorValue(kElbowId, u"max_angle_limit"), result.maximumLimit);
        for (const testsupport::PluggedServo &servo : pluggedServos()) {
            if (servo.id != kElbowId)
                QCOMPARE(servo.revision, revisions.value(servo.id)); // nothing written to them
        }

        // Save updates the arm's file in place: no file dialog, the other joints as they were.
        auto *save = calibration.findChild<QPushButton *>(QStringLiteral("saveLeRobotFileButton"));
        QVERIFY(save);
        QVERIFY2(save->text().contains(QLatin1String("follower.json")), qPrintable(save->text()));
        save->click();
        util::FileError error;
        const auto saved = feetech::loadLeRobotCalibration(m_file, &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->size(), kArmFile.size());
        for (int i = 0; i < kArmFile.size(); ++i) {
            const feetech::LeRobotMotor &before = kArmFile.at(i);
            const feetech::LeRobotMotor &after = saved->at(i);
            QCOMPARE(after.name, before.name);
            QCOMPARE(after.id, before.id);
            QCOMPARE(after.driveMode, before.driveMode);
            if (after.id != kElbowId) {
                QCOMPARE(after.homingOffset, before.homingOffset);
                QCOMPARE(after.rangeMin, before.rangeMin);
                QCOMPARE(after.rangeMax, before.rangeMax);
            }
        }
        const feetech::LeRobotMotor *elbow = feetech::leRobotMotorWithId(*saved, kElbowId);
        QCOMPARE(elbow->homingOffset, result.offset);
        QCOMPARE(elbow->rangeMin, result.minimumLimit);
        QCOMPARE(elbow->rangeMax, result.maximumLimit);
        QCOMPARE(elbow->driveMode, 1);
        QVERIFY(!m_client->telemetry()->isStreaming());
    }

    void aFileThatCannotTakeTheJointIsRefusedBeforeAnythingIsWritten()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), testsupport::kFactoryBaud));
        QVector<feetech::LeRobotMotor> withoutElbow = kArmFile;
        withoutElbow.removeAt(kElbow);
        const QString other = m_dir.filePath(QStringLiteral("other.json"));
        util::FileError error;
        QVERIFY(feetech::saveLeRobotCalibration(withoutElbow, other, &error));
        openWizard(other);
        click(m_wizard.get(), "replaceNextButton");
        QCOMPARE(m_wizard->page(), ReplaceMotorWizard::Page::Choice);
        QVERIFY2(status().contains(QLatin1String("has no joint with ID 3")), qPrintable(status()));

        m_wizard->fileEdit()->clear();
        click(m_wizard.get(), "replaceNextButton");
        QVERIFY2(status().startsWith(QLatin1String("Choose the arm's LeRobot calibration file")),
                 qPrintable(status()));

        m_wizard->fileEdit()->setText(m_dir.filePath(QStringLiteral("missing.json")));
        click(m_wizard.get(), "replaceNextButton");
        QVERIFY2(status().contains(QLatin1String("missing.json")), qPrintable(status()));

        m_wizard->fileEdit()->setText(writeTestFile(QStringLiteral("broken.json"), "{\"elbow"));
        click(m_wizard.get(), "replaceNextButton");
        QVERIFY2(status().contains(QLatin1String("broken.json")), qPrintable(status()));
        QCOMPARE(m_wizard->page(), ReplaceMotorWizard::Page::Choice);
        QCOMPARE(pluggedServos().first().revision, quint64(0)); // nothing written
        QCOMPARE(pluggedServos().first().id, quint8(1));
    }

    void aServoThatDoesNotAnswerIsSaidAndNothingWritten()
    {
        openWizard(m_file);
        click(m_wizard.get(), "replaceNextButton");
        QCOMPARE(m_wizard->page(), ReplaceMotorWizard::Page::SetUp);
        // No servo plugged in: the find says so, Set up stays off.
        clickAndWait("replaceFindButton");
        QVERIFY2(status().contains(QLatin1String("Nothing was written to any servo.")),
                 qPrintable(status()));
        QVERIFY(
            !m_wizard->findChild<QPushButton *>(QStringLiteral("replaceSetUpButton"))->isEnabled());
        // Two servos (the arm left connected): not one to set up.
        QVERIFY(plug(1, QStringLiteral("STS3215"), testsupport::kFactoryBaud));
        QVERIFY(plug(2, QStringLiteral("STS3215"), m_robot.baud));
        clickAndWait("replaceFindButton");
        QVERIFY2(status().contains(QLatin1String("Nothing was written to any servo.")),
                 qPrintable(status()));
        for (const testsupport::PluggedServo &servo : pluggedServos())
            QCOMPARE(servo.revision, quint64(0));
        QCOMPARE(m_wizard->page(), ReplaceMotorWizard::Page::SetUp);
        // The port closed (the adapter pulled out): said, and nothing can be started.
        m_client->disconnectFrom();
        QTRY_VERIFY2_WITH_TIMEOUT(status().contains(QLatin1String("port is closed")),
                                  qPrintable(status()), 10000);
        QVERIFY(
            !m_wizard->findChild<QPushButton *>(QStringLiteral("replaceFindButton"))->isEnabled());
    }

    void theArmScannedWithoutTheNewServoIsSaid()
    {
        setUpNewElbow();
        unplugAll();
        reassembleArm(); // the new servo's cable forgotten
        click(m_wizard.get(), "replaceScanButton");
        QTRY_VERIFY2_WITH_TIMEOUT(status().contains(QLatin1String("does not answer at ID 3")),
                                  qPrintable(status()), 20000);
        QVERIFY(!m_wizard->calibrationWizard());
        QVERIFY(!m_wizard->findChild<QPushButton *>(QStringLiteral("replaceCalibrateButton"))
                     ->isEnabled());
        // Plugged in, a second scan finds it and the calibration opens.
        QVERIFY(plug(kElbowId, QStringLiteral("STS3215"), m_robot.baud));
        click(m_wizard.get(), "replaceScanButton");
        QTRY_VERIFY_WITH_TIMEOUT(m_wizard->calibrationWizard(), 20000);
    }

    void theRobotMenuOpensTheWizardOnceAPortIsOpen()
    {
        m_client.reset(); // the window opens the port itself
        MainWindow window;
        QMenu *robot = window.menuBar()->findChild<QMenu *>(QStringLiteral("robotMenu"));
        QVERIFY(robot);
        auto *action = robot->findChild<QAction *>(QStringLiteral("replaceMotorAction"));
        QVERIFY(action);
        QVERIFY(!action->isEnabled());
        window.connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        window.connectToPort(m_simulator->linkPath());
        QTRY_VERIFY_WITH_TIMEOUT(action->isEnabled(), 10000);
        action->trigger();
        auto *wizard = window.findChild<ReplaceMotorWizard *>();
        QVERIFY(wizard);
        QVERIFY(wizard->isVisible());
        QCOMPARE(wizard->page(), ReplaceMotorWizard::Page::Choice);
        QVERIFY(wizard->findChild<QPushButton *>(QStringLiteral("replaceNextButton"))->isEnabled());
        action->trigger(); // the same wizard again
        QCOMPARE(window.findChildren<ReplaceMotorWizard *>().size(), 1);
    }
};

QTEST_MAIN(TestReplaceMotorWizard)
#include "tst_replacemotorwizard.moc"
