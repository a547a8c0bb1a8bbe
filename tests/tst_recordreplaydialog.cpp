// The Record and replay dialog, offscreen against two simulated servos a scripted hand turns:
// a recording, its timeline and file, a replay held at the end, and Stop holding the arm.
#include "feetechbus.h"
#include "scriptedhand.h"

#include "mainwindow.h"
#include "recordreplaydialog.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QtTest>

using testsupport::ScriptedHand;

namespace {

constexpr int kGoalAddress = 42;

} // namespace

class TestRecordReplayDialog : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    std::unique_ptr<feetech::BusClient> m_client;

    void startArm()
    {
        QString error;
        QVERIFY2(startSimulator(
                     busOptions(testsupport::servosAt(1000000, {u"STS3215", u"STS3215"})), &error),
                 qPrintable(error));
        m_client = std::make_unique<feetech::BusClient>(testsupport::patientTiming());
        QVERIFY(testsupport::connectAndScan(*m_client, m_simulator->linkPath(), 3));
        QCOMPARE(m_client->servos()->count(), 2);
    }

    // The frames recorded so far, as the dialog says while it records.
    static int recordedFrames(const RecordReplayDialog &dialog)
    {
        const auto *position = dialog.findChild<QLabel *>(QStringLiteral("recordingPosition"));
        const QString text = position->text();
        if (!text.startsWith(QStringLiteral("Recording: ")))
            return 0;
        return text.mid(11).section(QLatin1Char(' '), 0, 0).toInt();
    }

    // Records while the hand turns servo 1 from 1000 to 1800 and servo 2 from 2000 to 2300.
    void record(RecordReplayDialog &dialog)
    {
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.place(2, 2000);
        hand.script(1, {1800});
        hand.script(2, {2300});
        QCOMPARE(dialog.jointList()->count(), 2);
        QCOMPARE(dialog.jointList()->item(0)->checkState(), Qt::Checked);
        QVERIFY(dialog.recordButton()->isEnabled());
        QVERIFY(!dialog.playButton()->isEnabled()); // nothing to play yet
        dialog.recordButton()->click();
        QTRY_VERIFY(dialog.stopButton()->isEnabled()); // once torque is off
        hand.start([&dialog] { return recordedFrames(dialog) > 0; });
        QTRY_VERIFY_WITH_TIMEOUT(hand.done(), 10000);
        // A few frames more with the horns at rest.
        const int done = recordedFrames(dialog);
        QTRY_VERIFY_WITH_TIMEOUT(recordedFrames(dialog) > done + 5, 10000);
        dialog.stopButton()->click();
        QVERIFY(!dialog.recording().isEmpty());
        QCOMPARE(dialog.recording().joints.size(), 2);
        QVERIFY(dialog.playButton()->isEnabled());
        QCOMPARE(dialog.timeline()->maximum(), int(dialog.recording().frames.size()) - 1);
    }

private slots:
    void init() { QSettings().clear(); }

    void cleanup()
    {
        m_client.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aRecordingIsPlayedBackAndHeldAtItsLastFrame()
    {
        startArm();
        RecordReplayDialog dialog(m_client.get());
        dialog.show();
        record(dialog);
        const feetech::MotionRecording recorded = dialog.recording();
        QVERIFY(qAbs(recorded.frames.last().at(0) - 1800) <= 5);
        QVERIFY(qAbs(recorded.frames.last().at(1) - 2300) <= 5);
        // Torque was left off while recording.
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);

        // The timeline shows a frame's positions.
        dialog.timeline()->setValue(0);
        auto *position = dialog.findChild<QLabel *>(QStringLiteral("recordingPosition"));
        QVERIFY2(position->text().contains(QStringLiteral("frame 1 of")),
                 qPrintable(position->text()));

        // Saved and opened again, it is the same recording.
        const QString path = m_dir.filePath(QStringLiteral("dialog.csv"));
        QVERIFY(dialog.saveFile(path));
        QVERIFY(dialog.openFile(path));
        QCOMPARE(dialog.recording().frames, recorded.frames);

        // The horns moved away since: the replay eases back to the first frame, plays, holds.
        ScriptedHand hand(*m_simulator);
        hand.place(1, 2500);
        hand.place(2, 2500);
        dialog.speedBox()->setValue(2.0);
        QSignalSpy finished(&dialog, &RecordReplayDialog::replayFinished);
        dialog.playButton()->click();
        QVERIFY(dialog.stopButton()->isEnabled());
        QVERIFY(!dialog.playButton()->isEnabled());
        QVERIFY(finished.wait(20000));
        const auto result = finished.first().at(0).value<feetech::OperationResult>();
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(dialog.progressBar()->value(), dialog.progressBar()->maximum());
        QCOMPARE(dialog.timeline()->value(), dialog.timeline()->maximum());
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        QCOMPARE(simulatorValue(1, u"goal_position"), recorded.frames.last().at(0));
        QCOMPARE(simulatorValue(2, u"goal_position"), recorded.frames.last().at(1));
        QVERIFY(dialog.playButton()->isEnabled());
    }

    void recordSwitchesTorqueOffSoThatTheJointsCanBeMovedByHand()
    {
        startArm();
        // After teleoperation or a replay, the arm holds itself.
        setSimulatorValue(1, u"torque_enable", 1);
        setSimulatorValue(2, u"torque_enable", 1);
        RecordReplayDialog dialog(m_client.get());
        dialog.show();
        const int recordWidth = dialog.recordButton()->width();
        const QPoint stopAt = dialog.stopButton()->mapTo(&dialog, QPoint());
        record(dialog);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(2, u"torque_enable"), 0);
        // The hand's turns were recorded: the joints were free.
        QVERIFY(qAbs(dialog.recording().frames.last().at(0) - 1800) <= 5);
        // Nothing moved on the dialog between its states.
        QCOMPARE(dialog.recordButton()->width(), recordWidth);
        QCOMPARE(dialog.stopButton()->mapTo(&dialog, QPoint()), stopAt);
    }

    void stopHoldsTheArmWhereItStands()
    {
        startArm();
        RecordReplayDialog dialog(m_client.get());
        dialog.show();
        // A long, slow recording: 10 s from 1000 to 3000 on servo 1.
        QByteArray csv = "time_s,id_1,id_2\n";
        for (int i = 0; i <= 100; ++i)
            csv += QByteArray::number(i * 0.1, 'f', 1) + ',' + QByteArray::number(1000 + 20 * i)
                + ",2000\n";
        QVERIFY(dialog.openFile(writeTestFile(QStringLiteral("slow.csv"), csv)));
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.place(2, 2000);
        QSignalSpy finished(&dialog, &RecordReplayDialog::replayFinished);
        dialog.playButton()->click();
        // Well into the frames, then Stop.
        QTRY_VERIFY_WITH_TIMEOUT(dialog.timeline()->value() >= 10, 10000);
        QVERIFY(dialog.stopButton()->isEnabled());
        dialog.stopButton()->click();
        QVERIFY(finished.wait(10000));
        const auto result = finished.first().at(0).value<feetech::OperationResult>();
        QCOMPARE(result.failure, feetech::OperationFailure::Stopped);
        auto *status = dialog.findChild<QLabel *>(QStringLiteral("recordReplayStatus"));
        QVERIFY2(status->text().contains(QStringLiteral("holds where it stood")),
                 qPrintable(status->text()));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        const int goal = simulatorValue(1, u"goal_position");
        QVERIFY2(goal < 2900, qPrintable(QString::number(goal)));
        // The last goal servo 1 got is the hold's own WRITE, after the replay's SYNC WRITEs.
        std::optional<feetech::Packet> lastGoal;
        for (const feetech::Packet &packet : testsupport::feetechPacketsReceived(logPath())) {
            const bool goalWrite = !packet.parameters.isEmpty()
                && quint8(packet.parameters.at(0)) == kGoalAddress
                && ((packet.code == quint8(feetech::Instruction::Write) && packet.id == 1)
                    || packet.code == quint8(feetech::Instruction::SyncWrite));
            if (goalWrite)
                lastGoal = packet;
        }
        QVERIFY(lastGoal);
        QCOMPARE(lastGoal->code, quint8(feetech::Instruction::Write));
        QTRY_VERIFY(qAbs(simulatorValue(1, u"present_position") - goal) <= 10);
        QCOMPARE(simulatorValue(1, u"goal_position"), goal);
        QVERIFY(!dialog.stopButton()->isEnabled());
    }

    void aJointTheScanDidNotFindIsRefusedBeforeAnythingMoves()
    {
        startArm();
        RecordReplayDialog dialog(m_client.get());
        QVERIFY(dialog.openFile(
            writeTestFile(QStringLiteral("other.csv"), "time_s,id_1,id_7\n0,2000,2000\n")));
        dialog.playButton()->click();
        auto *status = dialog.findChild<QLabel *>(QStringLiteral("recordReplayStatus"));
        QVERIFY2(status->text().contains(QStringLiteral("servo 7")), qPrintable(status->text()));
        QVERIFY(!dialog.stopButton()->isEnabled());
        QCOMPARE(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size(), 0);
        // A file that is no recording is refused, the one shown kept.
        QVERIFY(!dialog.openFile(writeTestFile(QStringLiteral("bad.csv"), "x,y\n")));
        QVERIFY2(status->text().contains(QStringLiteral("time_s")), qPrintable(status->text()));
        QCOMPARE(dialog.recording().joints.size(), 2);
    }

    void theRobotMenuOpensOneNonModalDialogOnAScannedBus()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(1000000, {u"STS3215"})), &error),
                 qPrintable(error));
        MainWindow window;
        auto *action = window.findChild<QAction *>(QStringLiteral("recordReplayAction"));
        QVERIFY(action);
        QVERIFY(!action->isEnabled()); // no bus yet
        QVERIFY(testsupport::connectAndScan(*window.feetechClient(), m_simulator->linkPath(), 3));
        QTRY_VERIFY(action->isEnabled());
        action->trigger();
        auto *dialog = window.findChild<RecordReplayDialog *>();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QVERIFY(!dialog->isModal());
        QCOMPARE(dialog->jointList()->count(), 1);
        action->trigger(); // the same dialog again
        QCOMPARE(window.findChildren<RecordReplayDialog *>().size(), 1);
        window.feetechClient()->disconnectFrom();
        QTRY_VERIFY(!action->isEnabled());
        QVERIFY(!dialog->recordButton()->isEnabled());
    }
};

QTEST_MAIN(TestRecordReplayDialog)
#include "tst_recordreplaydialog.moc"
