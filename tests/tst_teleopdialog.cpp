// Robot > Teleoperate…, offscreen, against two simulated arms: the follower on the dialog's bus
// client follows the leader's joint the hand turned, the bars show both, Stop holds, and
// mismatched files are refused with the reason shown.
#include "teleoparms.h"

#include "mainwindow.h"
#include "teleopdialog.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QtTest>

class TestTeleopDialog : public testsupport::TeleopArmsTest
{
    Q_OBJECT

private:
    void fill(TeleopDialog &dialog, const QString &leaderFile)
    {
        dialog.leaderPortBox()->setEditText(m_leader->linkPath());
        dialog.followerFileEdit()->setText(followerFile());
        dialog.leaderFileEdit()->setText(leaderFile);
        dialog.maxSpeedBox()->setValue(180);
    }

private slots:
    void init() { QSettings().clear(); }
    void cleanup() { stopArms(); }

    void theFollowerFollowsTheLeaderAndStopHoldsIt()
    {
        startArms();
        const qint32 standing = simulatorValue(2, u"present_position");
        QVERIFY(turnLeader(2, standing + 600));
        TeleopDialog dialog(m_client.get());
        dialog.show();
        fill(dialog, leaderFile());
        QVERIFY(dialog.startButton()->isEnabled());
        QVERIFY(!dialog.stopButton()->isEnabled());
        dialog.startButton()->click();
        QVERIFY2(!dialog.startButton()->isEnabled(), qPrintable(dialog.statusLabel()->text()));
        QVERIFY(dialog.stopButton()->isEnabled());
        QVERIFY(!dialog.leaderPortBox()->isEnabled());

        QTRY_VERIFY_WITH_TIMEOUT(qAbs(simulatorValue(2, u"goal_position") - (standing + 600)) <= 20,
                                 15000);
        QCOMPARE(simulatorValue(2, u"torque_enable"), 1);
        // Both bars of shoulder_lift show the same place in LeRobot's units (tenths), and it is
        // where the leader was turned to.
        QProgressBar *leader = dialog.leaderBar(1);
        QProgressBar *follower = dialog.followerBar(1);
        QVERIFY(leader && follower);
        QCOMPARE(leader->objectName(), QStringLiteral("teleopLeader_shoulder_lift"));
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(leader->value() - follower->value()) <= 10, 10000);
        QVERIFY(leader->value() > leader->minimum());
        QTRY_VERIFY_WITH_TIMEOUT(
            dialog.loopLabel()->text().contains(QStringLiteral("cycles a second")), 5000);

        dialog.stopButton()->click();
        QTRY_VERIFY_WITH_TIMEOUT(dialog.startButton()->isEnabled(), 10000);
        QVERIFY(!dialog.stopButton()->isEnabled());
        QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("holds where it is")),
                 qPrintable(dialog.statusLabel()->text()));
        QCOMPARE(simulatorValue(2, u"torque_enable"), 1);
        // The goal stays where the servo was when stopped; it settles there (a servo on its way
        // needs a moment to brake).
        const qint32 held = simulatorValue(2, u"goal_position");
        QTRY_VERIFY_WITH_TIMEOUT(qAbs(simulatorValue(2, u"present_position") - held) <= 30, 5000);
        QCOMPARE(simulatorValue(2, u"goal_position"), held);
    }

    void closingTheDialogHoldsTheFollower()
    {
        startArms();
        TeleopDialog dialog(m_client.get());
        dialog.show();
        fill(dialog, leaderFile());
        dialog.startButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(dialog.teleoperation()->state(),
                                  feetech::Teleoperation::State::Running, 15000);
        dialog.close();
        QTRY_COMPARE_WITH_TIMEOUT(dialog.teleoperation()->state(),
                                  feetech::Teleoperation::State::Idle, 10000);
        QCOMPARE(dialog.teleoperation()->problem(), feetech::Teleoperation::Problem::None);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
    }

    void theDemosSimulatedLeaderIsOfferedChosenAndUsed()
    {
        startArms();
        TeleopDialog dialog(m_client.get());
        dialog.show();
        int started = 0;
        dialog.setSimulatedLeader([this, &started](QString *) {
            ++started;
            return m_leader->linkPath();
        });
        QCOMPARE(dialog.leaderPortBox()->currentData().toString(),
                 QString::fromLatin1(TeleopDialog::kSimulatedLeader));
        dialog.followerFileEdit()->setText(followerFile());
        dialog.leaderFileEdit()->setText(leaderFile());
        dialog.startButton()->click();
        QCOMPARE(started, 1);
        QTRY_COMPARE_WITH_TIMEOUT(dialog.teleoperation()->state(),
                                  feetech::Teleoperation::State::Running, 15000);
        dialog.stopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(dialog.teleoperation()->state(),
                                  feetech::Teleoperation::State::Idle, 10000);
        QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("holds where it is")),
                 qPrintable(dialog.statusLabel()->text()));
    }

    // The demo's leader has no file of its own: with none chosen, the one its simulator makes of
    // what the arm holds is used, not a refusal.
    void theSimulatedLeaderWithNoFileUsesTheOneItsSimulatorMakes()
    {
        startArms();
        TeleopDialog dialog(m_client.get());
        dialog.show();
        int made = 0;
        dialog.setSimulatedLeader([this](QString *) { return m_leader->linkPath(); },
                                  [this, &made](QString *) {
                                      ++made;
                                      return leaderFile();
                                  });
        dialog.followerFileEdit()->setText(followerFile());
        dialog.leaderFileEdit()->clear();
        dialog.startButton()->click();
        QCOMPARE(made, 1);
        QCOMPARE(QDir::fromNativeSeparators(dialog.leaderFileEdit()->text()), leaderFile());
        QTRY_COMPARE_WITH_TIMEOUT(dialog.teleoperation()->state(),
                                  feetech::Teleoperation::State::Running, 15000);
        dialog.stopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(dialog.teleoperation()->state(),
                                  feetech::Teleoperation::State::Idle, 10000);
    }

    void mismatchedFilesAreRefusedWithTheReasonShown()
    {
        startArms();
        TeleopDialog dialog(m_client.get());
        dialog.show();
        const QString fewer = writeTestFile(
            QStringLiteral("fewer.json"),
            QByteArray(R"({"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": 0,
                           "range_min": 0, "range_max": 4095}})"));
        fill(dialog, fewer);
        dialog.startButton()->click();
        QVERIFY(dialog.startButton()->isEnabled());
        QVERIFY(!dialog.stopButton()->isEnabled());
        QVERIFY2(dialog.statusLabel()->text().contains(QStringLiteral("gripper")),
                 qPrintable(dialog.statusLabel()->text()));
        QCOMPARE(dialog.teleoperation()->problem(),
                 feetech::Teleoperation::Problem::DifferentJoints);
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncWrite)
                    .isEmpty());
    }

    void theRobotMenuOpensOneNonModalDialogOnAScannedBus()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(1000000, {u"STS3215"})), &error),
                 qPrintable(error));
        MainWindow window;
        auto *action = window.findChild<QAction *>(QStringLiteral("teleoperateAction"));
        QVERIFY(action);
        QVERIFY(!action->isEnabled()); // no bus yet
        QVERIFY(testsupport::connectAndScan(*window.feetechClient(), m_simulator->linkPath(), 3));
        QTRY_VERIFY(action->isEnabled());
        action->trigger();
        auto *dialog = window.findChild<TeleopDialog *>();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QVERIFY(!dialog->isModal());
        // Not on the demo's servos: no simulated leader is offered.
        QCOMPARE(
            dialog->leaderPortBox()->findData(QString::fromLatin1(TeleopDialog::kSimulatedLeader)),
            -1);
        action->trigger(); // the same dialog again
        QCOMPARE(window.findChildren<TeleopDialog *>().size(), 1);
        window.feetechClient()->disconnectFrom();
        QTRY_VERIFY(!action->isEnabled());
    }
};

QTEST_MAIN(TestTeleopDialog)
#include "tst_teleopdialog.moc"
