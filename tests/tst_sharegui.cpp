// Tests of sharing the bus from the window: Link > Share this bus…, its dialog, the alerts in the
// status bar and the packet log, and the packet log's recordings.
#include "feetechwindow.h"
#include "programport.h"

#include "busclient.h"
#include "controlpage.h"
#include "feetechpacket.h"
#include "feetechworkspace.h"
#include "hex.h"
#include "monitorpage.h"
#include "packetlogdock.h"
#include "packetlogmodel.h"
#include "registertable.h"
#include "sharedialog.h"
#include "sharerecordingwindow.h"
#include "telemetryplot.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardItemModel>
#include <QStatusBar>
#include <QtTest>

using feetech::ShareService;
using testsupport::ProgramPort;

namespace {

constexpr qint32 k1M = 1000000;

// The rows of `log` that show the other program's frames, and those with an error.
int programRows(seriallink::PacketLogModel &log)
{
    log.flush();
    int rows = 0;
    for (int row = 0; row < log.rowCount(); ++row) {
        if (log.entry(row).summary.startsWith(QLatin1String("Other program")))
            ++rows;
    }
    return rows;
}

int errorRowsContaining(seriallink::PacketLogModel &log, const QString &text)
{
    log.flush();
    int rows = 0;
    for (int row = 0; row < log.rowCount(); ++row) {
        if (log.entry(row).error.contains(text))
            ++rows;
    }
    return rows;
}

} // namespace

class TestShareGui : public testsupport::FeetechWindowTest
{
    Q_OBJECT

private:
    QString sharePath() const { return m_dir.filePath(QStringLiteral("program")); }

    QAction *shareAction() const
    {
        return m_window->findChild<QAction *>(QStringLiteral("shareBusAction"));
    }

    // Link > Share this bus…: its dialog.
    ShareDialog *openShareDialog()
    {
        shareAction()->trigger();
        return m_window->findChild<ShareDialog *>();
    }

    // Starts the share from `dialog` at sharePath(), recording to `recording`: whether it shares
    // within 10 s.
    bool startSharing(ShareDialog &dialog, const QString &recording = {})
    {
        dialog.pathEdit()->setText(sharePath());
        dialog.recordEdit()->setText(recording);
        dialog.startStopButton()->click();
        return QTest::qWaitFor(
            [&] { return client()->share()->state() == ShareService::State::Sharing; }, 10000);
    }

    void connectWithoutScan()
    {
        m_window->connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_VERIFY_WITH_TIMEOUT(client()->link()->isConnected(), 10000);
    }

private slots:
    void init() { openWindowOnBus(); }
    void cleanup()
    {
        closeWindow();
        QFile::remove(logPath());
    }

    void theMenuEntryWaitsForAConnectedFeetechBus()
    {
        QVERIFY(shareAction());
        QVERIFY(!shareAction()->isEnabled());
        connectWithoutScan();
        QTRY_VERIFY(shareAction()->isEnabled());
        ShareDialog *dialog = openShareDialog();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QVERIFY(!dialog->isModal());
        QCOMPARE(dialog->pathEdit()->text(),
                 QDir::toNativeSeparators(ShareService::defaultLinkPath()));
        QVERIFY(!dialog->watchBox()->isChecked());
        QVERIFY(dialog->startStopButton()->isEnabled());
        // Asked again, the same dialog comes back.
        QCOMPARE(openShareDialog(), dialog);

        m_window->feetechClient()->disconnectFrom();
        QTRY_VERIFY(!shareAction()->isEnabled());
        QTRY_VERIFY(!dialog->startStopButton()->isEnabled());
    }

    void theDialogSharesShowsWhatPassesAndStops()
    {
        connectWithoutScan();
        ShareDialog *dialog = openShareDialog();
        QVERIFY(startSharing(*dialog));
        QVERIFY(dialog->stateLabel()->text().contains(QDir::toNativeSeparators(sharePath())));
        QVERIFY(!dialog->pathEdit()->isEnabled()); // what it shares at stays until it stops
        dialog->copyButton()->click();
        QCOMPARE(QApplication::clipboard()->text(), sharePath());

        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QVERIFY(program.readModel(2));
        // Its servos go into the servo tree's list; its frames into the packet log.
        QTRY_COMPARE_WITH_TIMEOUT(client()->servos()->count(), 2, 5000);
        seriallink::PacketLogModel &log = *m_window->packetLog()->model();
        QTRY_COMPARE_WITH_TIMEOUT(programRows(log), 4, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(
            dialog->countersLabel()->text().contains(QLatin1String("program: 2 frame")), 5000);

        // The program sets phase bit 4 (multi-turn): the alert shows in the dialog, the status
        // bar and the packet log.
        const feetech::Register *phase =
            feetech::RegisterTable::forFamily(feetech::Family::Sts).find(u"phase");
        QVERIFY(phase);
        QCOMPARE(
            program.ask(feetech::write(1, quint8(phase->address), QByteArray(1, '\x10')), 1).size(),
            1);
        QTRY_COMPARE_WITH_TIMEOUT(dialog->alertList()->count(), 1, 5000);
        QVERIFY(dialog->alertList()->item(0)->text().contains(QLatin1String("phase bit 4")));
        QVERIFY(m_window->statusBar()->currentMessage().contains(QLatin1String("phase bit 4")));
        QTRY_COMPARE_WITH_TIMEOUT(errorRowsContaining(log, QStringLiteral("phase bit 4")), 1, 5000);
        program.close();

        // While shared, the scan waits: the window says why.
        QVERIFY(!client()->scan({}));
        dialog->startStopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(client()->share()->state(), ShareService::State::Off, 10000);
        QVERIFY(dialog->pathEdit()->isEnabled());
        QVERIFY(dialog->startStopButton()->text().contains(QLatin1String("Start")));
        QVERIFY(!QFileInfo::exists(sharePath()));
    }

    // While shared, the Control page says why it neither reads nor moves a servo, and offers
    // nothing that cannot work.
    void theControlPageSaysWhyItWaitsWhileTheBusIsShared()
    {
        connectAndScanUpTo(3);
        ShareDialog *dialog = openShareDialog();
        QVERIFY(startSharing(*dialog));
        ControlPage *control = m_window->feetechWorkspace()->controlPage();
        control->setServo(0);
        auto *hint = control->findChild<QLabel *>(QStringLiteral("controlHint"));
        QVERIFY(hint);
        QTRY_VERIFY(!hint->isHidden());
        QVERIFY2(hint->text().contains(QLatin1String("shared with another program")),
                 qPrintable(hint->text()));
        QVERIFY(!control->findChild<QSlider *>(QStringLiteral("goalSlider"))->isEnabled());
        QString error;
        QVERIFY(!control->moveTo(2000, &error));
        // Sharing stopped: the page controls the servo again.
        dialog->startStopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(client()->share()->state(), ShareService::State::Off, 10000);
        QTRY_VERIFY(hint->isHidden());
        QVERIFY(control->findChild<QSlider *>(QStringLiteral("goalSlider"))->isEnabled());
    }

    void theMonitorPlotsTheProgramsReads()
    {
        connectWithoutScan();
        ShareDialog *dialog = openShareDialog();
        QVERIFY(startSharing(*dialog));
        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        QVERIFY(program.readModel(1));
        QTRY_COMPARE_WITH_TIMEOUT(client()->servos()->count(), 1, 5000);

        MonitorPage *monitor = workspace()->monitorPage();
        monitor->setSelectedServos({0});
        QString error;
        QVERIFY2(monitor->start(&error), qPrintable(error));
        QLabel *status = monitor->findChild<QLabel *>(QStringLiteral("monitorStatus"));
        QVERIFY(status->text().contains(QLatin1String("other program")));
        const feetech::Block block = testsupport::stsFeedbackBlock();
        for (int i = 0; i < 3; ++i)
            QCOMPARE(
                program.ask(feetech::syncRead(quint8(block.address), quint8(block.size), {1}), 1)
                    .size(),
                1);
        QTRY_VERIFY_WITH_TIMEOUT(
            monitor->plot()->bufferedPointCount(1, feetech::Quantity::Position, k1M) >= 3, 5000);
        // Only the program's requests reached the servos.
        QCOMPARE(testsupport::feetechFramesReceived(logPath()), program.requests());
        monitor->stop();
        program.close();
    }

    void thePacketLogOpensTheRecordingOfAShare()
    {
        connectWithoutScan();
        const QString recording = m_dir.filePath(QStringLiteral("share.txt"));
        ShareDialog *dialog = openShareDialog();
        QVERIFY(startSharing(*dialog, recording));
        ProgramPort program;
        QVERIFY(program.open(sharePath()));
        const QVector<QByteArray> answer =
            program.ask(feetech::read(1, ProgramPort::kModelAddress, 2), 1);
        QCOMPARE(answer.size(), 1);
        program.close();
        dialog->startStopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(client()->share()->state(), ShareService::State::Off, 10000);

        QString error;
        ShareRecordingWindow *window = m_window->packetLog()->openRecording(recording, &error);
        QVERIFY2(window, qPrintable(error));
        QVERIFY(window->isVisible());
        QStandardItemModel *rows = window->model();
        QCOMPARE(rows->rowCount(), 2);
        QCOMPARE(rows->item(0, ShareRecordingWindow::FromColumn)->text(),
                 ShareRecordingWindow::directionText(share::FrameDirection::FromProgram));
        QCOMPARE(rows->item(0, ShareRecordingWindow::BytesColumn)->text(),
                 util::toHex(program.requests().first()));
        QVERIFY(rows->item(0, ShareRecordingWindow::MeaningColumn)
                    ->text()
                    .contains(QLatin1String("READ")));
        QCOMPARE(rows->item(1, ShareRecordingWindow::FromColumn)->text(),
                 ShareRecordingWindow::directionText(share::FrameDirection::ToProgram));
        QCOMPARE(rows->item(1, ShareRecordingWindow::BytesColumn)->text(),
                 util::toHex(answer.first()));
        QVERIFY(rows->item(1, ShareRecordingWindow::ErrorColumn)->text().isEmpty());
    }

    void aFileThatIsNoRecordingIsRefusedWithItsReason()
    {
        const QString path = writeTestFile(QStringLiteral("notes.txt"), "just some notes\n");
        QString error;
        QVERIFY(!m_window->packetLog()->openRecording(path, &error));
        QVERIFY(error.contains(QLatin1String("notes.txt")));
        QVERIFY(!m_window->findChild<ShareRecordingWindow *>());
    }
};

QTEST_MAIN(TestShareGui)
#include "tst_sharegui.moc"
