// ServoBench's main window, Auto and the doctor: the port probe on Connect, the workspace of
// what answered, and the Doctor panel after a scan that came back short.
#include "mainwindow.h"

#include "busclient.h"
#include "busdoctor.h"
#include "connectionbar.h"
#include "doctorcheck.h"
#include "doctorpanel.h"
#include "feetechworkspace.h"
#include "packetlogdock.h"
#include "ptkclient.h"

#include <QAction>
#include <QLabel>
#include <QMenu>
#include <QProgressDialog>
#include <QStatusBar>

#include <algorithm>

namespace {

constexpr int kDoctorMessageMs = 8000;

// Whether `expected` misses a servo: none found at its ID (at its rate, when it has one).
bool missesAServo(const QVector<feetech::ExpectedServo> &expected,
                  const QVector<feetech::ServoInfo> &found)
{
    return std::any_of(expected.cbegin(), expected.cend(), [&](const feetech::ExpectedServo &want) {
        return std::none_of(found.cbegin(), found.cend(), [&](const feetech::ServoInfo &servo) {
            return servo.id == want.id && (want.baud == 0 || servo.baud == want.baud);
        });
    });
}

} // namespace

void MainWindow::createDoctor()
{
    m_doctor = new DoctorPanel(m_feetech.get(), this);
    addDockWidget(Qt::BottomDockWidgetArea, m_doctor);
    m_doctor->hide(); // a tab beside the packet log once it first opens
    m_viewMenu->addAction(m_doctor->toggleViewAction());
    connect(m_doctor, &DoctorPanel::problem, this, &MainWindow::showProblem);
    connect(m_doctor, &DoctorPanel::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, kDoctorMessageMs); });
    connect(m_doctor, &DoctorPanel::rescanRequested, this, &MainWindow::rescanForDoctor);

    m_doctorCheck = new feetech::DoctorCheck(m_feetech.get(), this);
    connect(m_doctorCheck, &feetech::DoctorCheck::finished, this,
            [this](const QVector<feetech::DoctorFinding> &findings) {
                m_doctor->showFindings(m_portShown, findings);
                if (!findings.isEmpty())
                    openDoctor();
            });
    connect(m_feetech.get(), &feetech::BusClient::scanFinished, this,
            [this](bool completed) { onFeetechScanFinished(completed); });
}

void MainWindow::openDoctor()
{
    if (!tabifiedDockWidgets(m_packetLog).contains(m_doctor))
        tabifyDockWidget(m_packetLog, m_doctor); // the pages above keep their height
    m_doctor->show();
    m_doctor->raise();
}

void MainWindow::onFeetechScanFinished(bool completed)
{
    if (!completed || m_doctorCheck->isRunning())
        return;
    QVector<feetech::ServoInfo> found;
    for (int i = 0; i < m_feetech->servoCount(); ++i)
        found.append(m_feetech->servo(i).info);
    const QVector<feetech::ExpectedServo> expected = m_doctor->expected(m_portPath);
    const bool cameBackShort = found.isEmpty() || missesAServo(expected, found);
    if (!cameBackShort)
        feetech::rememberServos(m_portPath, found);
    if (!cameBackShort && !m_doctor->isVisible())
        return;
    feetech::BusObservation seen;
    if (m_probe) {
        seen.probe = *m_probe;
    } else {
        seen.probed = false;
        seen.probe.port = m_portShown;
    }
    seen.scanned = true;
    seen.scannedBauds = m_feetechWorkspace->scanOptions().bauds;
    m_doctor->showChecking(m_portShown);
    if (cameBackShort)
        openDoctor();
    m_doctorCheck->start(seen, expected);
}

void MainWindow::rescanForDoctor()
{
    if (m_feetechActive && m_feetech->isConnected()) {
        // A probe only hears who answers a broadcast: on an open bus, the scan says more.
        feetech::ScanOptions options = m_feetechWorkspace->scanOptions();
        if (m_probe)
            options.bauds = m_probe->answeringBauds();
        m_feetechWorkspace->startScan(options);
        return;
    }
    if (m_ptk->status().state != seriallink::ConnectionState::Disconnected
        || m_feetech->status().state != seriallink::ConnectionState::Disconnected)
        return; // a PTK servo, or a link still opening: nothing to re-scan
    if (m_portPath.isEmpty()) {
        showProblem(tr("Choose a serial port first."));
        return;
    }
    detectAndConnect(m_portPath);
}

void MainWindow::detectAndConnect(const QString &port)
{
    if (m_probeThread)
        return;
    m_probe.reset();
    m_portPath = port;
    m_connectionBar->setSessionActive(true); // its Disconnect stops the probe
    m_connectionState->setText(tr("Looking for servos on %1…").arg(m_portShown));
    m_probeThread = std::make_unique<seriallink::SessionThread<feetech::PortProbe>>(
        QStringLiteral("port probe"), feetech::ProbeTiming {});
    m_probeProgress = new QProgressDialog(tr("Looking for servos on %1…").arg(m_portShown),
                                          tr("Cancel"), 0, feetech::PortProbe::stepCount(), this);
    m_probeProgress->setObjectName(QStringLiteral("probeProgress"));
    m_probeProgress->setWindowTitle(tr("Auto-detection"));
    // Not modal: the window stays usable (and its Disconnect stops the probe too).
    m_probeProgress->setWindowModality(Qt::NonModal);
    m_probeProgress->setMinimumDuration(0);
    m_probeProgress->setAutoClose(false);
    m_probeProgress->setAutoReset(false);
    m_probeProgress->setValue(0);
    connect(m_probeProgress, &QProgressDialog::canceled, this, &MainWindow::cancelDetection);
    feetech::PortProbe *probe = m_probeThread->session();
    connect(probe, &feetech::PortProbe::progress, m_probeProgress,
            [this](int done, int, const QString &step) {
                m_probeProgress->setValue(done);
                if (!step.isEmpty())
                    m_probeProgress->setLabelText(step);
            });
    connect(probe, &feetech::PortProbe::finished, this, &MainWindow::onProbeFinished);
    m_probeThread->run([port](feetech::PortProbe &worker) { worker.start(port); });
}

void MainWindow::cancelDetection()
{
    if (m_probeThread)
        m_probeThread->run([](feetech::PortProbe &worker) { worker.cancel(); });
}

void MainWindow::onProbeFinished(const feetech::PortProbeReport &report)
{
    m_probeThread.reset(); // the probe has closed the port: the workspace may open it
    if (m_probeProgress) {
        m_probeProgress->deleteLater();
        m_probeProgress = nullptr;
    }
    m_connectionBar->setSessionActive(false);
    m_connectionState->setText(tr("Not connected"));
    if (report.cancelled) {
        statusBar()->showMessage(tr("Auto-detection cancelled; nothing was connected."),
                                 kDoctorMessageMs);
        return;
    }
    const seriallink::EchoMode echo =
        report.echo ? seriallink::EchoMode::On : seriallink::EchoMode::Off;
    const QVector<qint32> bauds = report.answeringBauds();
    if (report.ptk || !bauds.isEmpty()) {
        const qint32 baud = report.ptk ? 115200 : bauds.first();
        m_connectionBar->showDetected(baud, echo);
        m_connectionBar->setSessionActive(true);
        showProtocol(!report.ptk);
        if (report.ptk) {
            statusBar()->showMessage(tr("A PTK servo answers at 115,200 bps."), kDoctorMessageMs);
            m_ptk->connectTo(report.port, baud, echo);
            return;
        }
        m_probe = report;
        m_feetechWorkspace->setPortName(m_portShown);
        m_feetech->connectTo(report.port, baud, echo);
        feetech::ScanOptions options;
        options.bauds = bauds;
        options.skipSilentRates = false; // the probe heard something at each of them
        scanOnceConnected(options);
        return;
    }
    // Nothing answered: the doctor says why, from what the probe heard.
    feetech::BusObservation seen;
    seen.probe = report;
    m_doctor->showFindings(m_portShown,
                           feetech::diagnoseBus(seen, m_doctor->expected(report.port)));
    openDoctor();
    showProblem(tr("Nothing answers on %1: the Doctor panel says what to check.").arg(m_portShown));
}
