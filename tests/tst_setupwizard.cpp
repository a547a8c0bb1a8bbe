// GUI tests of the motor set-up wizard against the simulated bus over a pty: a whole arm set up
// one servo at a time, resuming, stopping, every failure shown with nothing written, the menu.
#include "pluggedbus.h"

#include "connectionbar.h"
#include "mainwindow.h"
#include "setupwizard.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QTreeWidget>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;

const QString kArm = QStringLiteral("SO-101 follower arm");

} // namespace

class TestSetupWizard : public testsupport::PluggedBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;
    std::unique_ptr<SetupWizard> m_wizard;
    feetech::RobotTemplate m_robot = testsupport::builtInRobot(kArm);

    // A wizard on the connected client with the arm chosen, shown, its first check ended.
    void openWizard()
    {
        m_wizard = std::make_unique<SetupWizard>(m_client.get());
        const int arm = m_wizard->robotChoice()->findText(kArm);
        QVERIFY(arm >= 0);
        m_wizard->robotChoice()->setCurrentIndex(arm);
        m_wizard->show();
        QTRY_VERIFY_WITH_TIMEOUT(!m_wizard->flow()->isWorking(), 20000);
        QCOMPARE(m_wizard->flow()->robot().name, kArm);
    }

    // Clicks `button` (which must be enabled) and waits for the work it starts to end.
    void clickAndWait(QPushButton *button)
    {
        QVERIFY(button->isEnabled());
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(m_wizard->flow()->isWorking());
        QTRY_VERIFY_WITH_TIMEOUT(!m_wizard->flow()->isWorking(), 30000);
    }

    QString outcome() const { return m_wizard->outcome()->text(); }
    QString status(int joint) const { return m_wizard->jointList()->topLevelItem(joint)->text(3); }

    // Plugs a servo that was set up as `joint` before (its ID, rate and EEPROM settings).
    void plugSetUp(const feetech::RobotJoint &joint)
    {
        QVERIFY(plug(quint8(joint.id), joint.model, m_robot.baud));
        QVERIFY(withServo(quint8(joint.id), m_robot.baud, [&](sim::VirtualFeetechServo &servo) {
            for (auto it = joint.settings.cbegin(); it != joint.settings.cend(); ++it)
                servo.setValue(it.key(), it.value());
        }));
    }

private slots:
    void init()
    {
        QSettings().clear(); // nothing remembered from an earlier case
        QString error;
        QVERIFY2(startEmptyBus(&error), qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>();
        m_client->connectTo(m_simulator->linkPath(), k1M, seriallink::EchoMode::Off);
        QTRY_VERIFY_WITH_TIMEOUT(m_client->link()->isConnected(), 10000);
    }

    void cleanup()
    {
        m_wizard.reset();
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aWholeArmIsSetUpOneFactoryServoAtATime()
    {
        openWizard();
        QCOMPARE(m_wizard->flow()->currentJoint(), 0);
        QCOMPARE(status(0), QStringLiteral("Current"));
        // Factory servos come at 1 Mbps; one set to another rate must be found too.
        const QVector<qint32> factoryRates {k1M, 115200, 500000, k1M, k1M, 57600};
        for (int i = 0; i < m_robot.joints.size(); ++i) {
            const feetech::RobotJoint &joint = m_robot.joints.at(i);
            QCOMPARE(m_wizard->flow()->currentJoint(), i);
            QVERIFY2(m_wizard->instruction()->text().startsWith(
                         QStringLiteral("Connect only the <b>%1</b> servo (ID will be %2) and "
                                        "press <i>Find</i>.")
                             .arg(joint.name)
                             .arg(joint.id)),
                     qPrintable(m_wizard->instruction()->text()));
            unplugAll(); // as LeRobot asks: the servo set up last is unplugged
            QVERIFY(plug(1, QStringLiteral("STS3215"), factoryRates.at(i)));
            QVERIFY(!m_wizard->setUpButton()->isEnabled());
            clickAndWait(m_wizard->findButton());
            QVERIFY2(outcome().contains(QLatin1String("Found one servo:")), qPrintable(outcome()));
            QVERIFY(outcome().contains(feetech::baudText(factoryRates.at(i))));
            QVERIFY(pluggedServos().first().id == 1); // a find writes nothing
            clickAndWait(m_wizard->setUpButton());
            QVERIFY2(m_wizard->flow()->jointState(i) == feetech::MotorSetupFlow::JointState::Done,
                     qPrintable(outcome()));
            QCOMPARE(status(i), QStringLiteral("Done"));
            QVERIFY(outcome().contains(joint.name + QStringLiteral(" is set up")));
            verifySetUp(0, m_robot, joint);
            powerCycle();
            verifySetUp(0, m_robot, joint, Settings::EepromOnly);
        }
        QCOMPARE(m_wizard->flow()->currentJoint(), -1);
        QVERIFY(outcome().contains(QLatin1String("Every joint is set up.")));
        QVERIFY(!m_wizard->findButton()->isEnabled());
    }

    void reopeningShowsTheJointsAlreadySetUpAsDone()
    {
        openWizard();
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        clickAndWait(m_wizard->findButton());
        clickAndWait(m_wizard->setUpButton());
        QCOMPARE(m_wizard->flow()->jointState(0), feetech::MotorSetupFlow::JointState::Done);
        m_wizard.reset(); // closed, its state gone
        // Servos set up before (say with servoctl), and one at elbow_flex's ID straight from
        // the factory.
        plugSetUp(m_robot.joints.at(1));
        QVERIFY(plug(3, QStringLiteral("STS3215"), k1M));
        openWizard();
        QCOMPARE(m_wizard->flow()->jointState(0), feetech::MotorSetupFlow::JointState::Done);
        QCOMPARE(m_wizard->flow()->jointState(1), feetech::MotorSetupFlow::JointState::Done);
        QCOMPARE(m_wizard->flow()->jointState(2), feetech::MotorSetupFlow::JointState::ToDo);
        QVERIFY2(status(2).contains(QLatin1String("ID 3 answers, but ")), qPrintable(status(2)));
        QCOMPARE(m_wizard->flow()->currentJoint(), 2);
        QVERIFY(m_wizard->instruction()->text().contains(QLatin1String("<b>elbow_flex</b>")));
        QVERIFY(outcome().contains(QLatin1String("2 of 6 joint(s) set up")));
    }

    void checkTheBusCallsDoneOnlyTheJointsAnsweringNow()
    {
        openWizard();
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        clickAndWait(m_wizard->findButton());
        clickAndWait(m_wizard->setUpButton());
        QCOMPARE(status(0), QStringLiteral("Done"));
        unplugAll();
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M)); // a factory servo alone
        clickAndWait(m_wizard->checkButton());
        QVERIFY2(outcome().contains(QLatin1String("0 of 6 joint(s) set up")),
                 qPrintable(outcome()));
        for (int joint = 0; joint < m_robot.joints.size(); ++joint)
            QCOMPARE(m_wizard->flow()->jointState(joint),
                     feetech::MotorSetupFlow::JointState::ToDo);
        QVERIFY2(status(0).contains(QLatin1String("ID 1 answers, but ")), qPrintable(status(0)));
        QCOMPARE(m_wizard->flow()->currentJoint(), 1);
        // That long status is read whole: its row is as tall as its wrapped lines.
        auto *list = m_wizard->findChild<QTreeWidget *>(QStringLiteral("jointList"));
        QVERIFY(list);
        const int statusColumn = 3;
        // As narrow as a small screen (or a longer sentence in another language) makes it.
        list->header()->setStretchLastSection(false);
        list->setColumnWidth(statusColumn, 140);
        QCoreApplication::processEvents();
        const int width = list->columnWidth(statusColumn);
        const int lines = list->fontMetrics()
                              .boundingRect(QRect(0, 0, width, 10000), Qt::TextWordWrap, status(0))
                              .height()
            / list->fontMetrics().lineSpacing();
        QVERIFY2(lines > 1, qPrintable(QString::number(lines)));
        QVERIFY2(list->visualItemRect(list->topLevelItem(0)).height()
                     >= lines * list->fontMetrics().lineSpacing(),
                 qPrintable(QStringLiteral("%1 lines in %2 px")
                                .arg(lines)
                                .arg(list->visualItemRect(list->topLevelItem(0)).height())));
    }

    void theRobotOfferedFirstIsTheOneEveryWizardOffers()
    {
        // The calibration wizard and Apply template offer the same: the SO-101 follower.
        const QVector<feetech::RobotTemplate> templates = feetech::availableRobotTemplates();
        QVERIFY(feetech::defaultRobotTemplateIn(templates));
        QCOMPARE(feetech::defaultRobotTemplateIn(templates)->name, kArm);
        m_wizard = std::make_unique<SetupWizard>(m_client.get());
        QCOMPARE(m_wizard->flow()->robot().name, kArm);
        QCOMPARE(m_wizard->robotChoice()->currentText(), kArm);
        m_wizard->show();
        QTRY_VERIFY_WITH_TIMEOUT(!m_wizard->flow()->isWorking(), 20000);
        QCOMPARE(m_wizard->flow()->robot().name, kArm);
    }

    void aStopBetweenStepsWritesNothingMoreAndLeavesTheJointToDo()
    {
        openWizard();
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        clickAndWait(m_wizard->findButton());
        const quint64 revision = pluggedServos().first().revision;
        QTest::mouseClick(m_wizard->setUpButton(), Qt::LeftButton);
        QVERIFY(m_wizard->stopButton()->isEnabled());
        QTest::mouseClick(m_wizard->stopButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!m_wizard->flow()->isWorking(), 30000);
        QVERIFY2(outcome().contains(QLatin1String("Stopped")), qPrintable(outcome()));
        QCOMPARE(m_wizard->flow()->jointState(0), feetech::MotorSetupFlow::JointState::ToDo);
        QCOMPARE(pluggedServos().first().revision, revision);
        QVERIFY(m_wizard->findButton()->isEnabled()); // and it can go on
    }

    void everyWrongBusIsShownInPlainWordsWithNothingWritten_data()
    {
        QTest::addColumn<QVector<sim::FeetechServoSpec>>("servos");
        QTest::addColumn<QString>("message");
        const QString sts = QStringLiteral("STS3215");
        QTest::newRow("no servo") << QVector<sim::FeetechServoSpec> {}
                                  << QStringLiteral("No servo answers at any rate: check the power "
                                                    "and the cable, and connect the next servo.");
        QTest::newRow("two IDs") << QVector<sim::FeetechServoSpec> {{1, sts, k1M}, {2, sts, k1M}}
                                 << QStringLiteral("connect one servo at a time.");
        QTest::newRow("one ID twice")
            << QVector<sim::FeetechServoSpec> {{1, sts, k1M}, {1, sts, k1M}}
            << QStringLiteral("Two servos answer at ID 1; connect them one at a time.");
        QTest::newRow("two rates")
            << QVector<sim::FeetechServoSpec> {{1, sts, k1M}, {1, sts, 500000}}
            << QStringLiteral("2 servos answer (ID 1 at 1 Mbps, ID 1 at 500");
        QTest::newRow("another model")
            << QVector<sim::FeetechServoSpec> {{1, QStringLiteral("SCS15"), k1M}}
            << QStringLiteral("model SCS15, but shoulder_pan needs model STS3215.");
    }

    void everyWrongBusIsShownInPlainWordsWithNothingWritten()
    {
        QFETCH(QVector<sim::FeetechServoSpec>, servos);
        QFETCH(QString, message);
        openWizard();
        for (const sim::FeetechServoSpec &servo : std::as_const(servos))
            QVERIFY(plug(servo.id, servo.model, servo.baud));
        const QVector<testsupport::PluggedServo> before = pluggedServos();
        clickAndWait(m_wizard->findButton());
        QVERIFY2(outcome().contains(message.toHtmlEscaped()), qPrintable(outcome()));
        QVERIFY(outcome().contains(QLatin1String("othing was written")));
        QCOMPARE(m_wizard->flow()->jointState(0), feetech::MotorSetupFlow::JointState::Failed);
        QVERIFY(status(0).contains(message));
        QVERIFY(!m_wizard->setUpButton()->isEnabled());
        const QVector<testsupport::PluggedServo> after = pluggedServos();
        for (int i = 0; i < before.size(); ++i) {
            QCOMPARE(after.at(i).revision, before.at(i).revision);
            QCOMPARE(after.at(i).eeprom, before.at(i).eeprom);
        }
        QVERIFY(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).isEmpty());
    }

    void theRobotMenuOpensTheWizardOnceAFeetechPortIsOpen()
    {
        m_client.reset(); // the window has a client of its own
        MainWindow window;
        QMenu *robot = window.menuBar()->findChild<QMenu *>(QStringLiteral("robotMenu"));
        QVERIFY(robot);
        QAction *setUp = robot->findChild<QAction *>(QStringLiteral("setUpMotorsAction"));
        QVERIFY(setUp);
        QCOMPARE(setUp->text(), QStringLiteral("Set up &motors…"));
        QVERIFY(!setUp->isEnabled());
        window.connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        window.connectToPort(m_simulator->linkPath());
        QTRY_VERIFY_WITH_TIMEOUT(setUp->isEnabled(), 10000);
        setUp->trigger();
        auto *wizard = window.findChild<SetupWizard *>();
        QVERIFY(wizard);
        QVERIFY(wizard->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->flow()->isWorking(), 20000); // its check of the bus
        QVERIFY(wizard->findButton()->isEnabled());
        // Its failures reach the window's banner too, and go when it closes, however it closes.
        auto *banner = window.findChild<QLabel *>(QStringLiteral("problemBanner"));
        QVERIFY(banner);
        const auto failAFind = [&] {
            QTest::mouseClick(wizard->findButton(), Qt::LeftButton);
            QTRY_VERIFY_WITH_TIMEOUT(!wizard->flow()->isWorking(), 30000);
            QVERIFY(!banner->isHidden());
            QVERIFY2(banner->text().startsWith(QLatin1String("No servo answers")),
                     qPrintable(banner->text()));
        };
        failAFind();
        auto *buttons = wizard->findChild<QDialogButtonBox *>();
        QVERIFY(buttons);
        QTest::mouseClick(buttons->button(QDialogButtonBox::Close), Qt::LeftButton);
        QVERIFY(!wizard->isVisible());
        QVERIFY(banner->isHidden());
        setUp->trigger();
        QCOMPARE(window.findChild<SetupWizard *>(), wizard); // the same one, reopened
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->flow()->isWorking(), 20000);
        failAFind();
        QTest::keyClick(wizard, Qt::Key_Escape);
        QVERIFY(banner->isHidden());
        setUp->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(!wizard->flow()->isWorking(), 20000);
        failAFind();
        wizard->close(); // the title bar's close
        QVERIFY(banner->isHidden());
    }
};

QTEST_MAIN(TestSetupWizard)
#include "tst_setupwizard.moc"
