// Connecting to servos: the request resolved to a port and a protocol, Auto's probe in a worker
// thread and what it found opened and scanned, and the doctor run after a short scan or when
// nothing answered.
#include "connectioncontroller.h"

#include "busclient.h"
#include "demoservos.h"
#include "doctorcheck.h"
#include "ptkclient.h"

#include <algorithm>

namespace {

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

ConnectionController::ConnectionController(ptk::Client *ptk, feetech::BusClient *feetech,
                                           QObject *parent)
    : QObject(parent)
    , m_ptk(ptk)
    , m_feetech(feetech)
    , m_expectedServos(&feetech::rememberedServos)
    , m_doctorShown([] { return false; })
    , m_lastScanOptions([] { return feetech::ScanOptions {}; })
{
    m_doctorCheck = new feetech::DoctorCheck(m_feetech, this);
    connect(m_doctorCheck, &feetech::DoctorCheck::finished, this,
            [this](const QVector<feetech::DoctorFinding> &findings) {
                emit doctorFindings(m_portShown, findings);
                if (!findings.isEmpty())
                    emit doctorWanted();
            });
    connect(m_feetech, &feetech::BusClient::scanFinished, this,
            [this](bool completed) { onFeetechScanFinished(completed); });
}

ConnectionController::~ConnectionController() = default;

std::optional<ConnectionController::Protocol>
ConnectionController::simulatedProtocol(const QString &port)
{
    if (port == QLatin1String(kSimulatedPtkPort))
        return Protocol::Ptk;
    if (port == QLatin1String(kSimulatedFeetechPort) || port == QLatin1String(kSimulatedArmPort))
        return Protocol::Feetech;
    return std::nullopt;
}

void ConnectionController::setExpectedServos(ExpectedServos expected)
{
    m_expectedServos = std::move(expected);
}

void ConnectionController::setDoctorShown(std::function<bool()> shown)
{
    m_doctorShown = std::move(shown);
}

void ConnectionController::setLastScanOptions(std::function<feetech::ScanOptions()> options)
{
    m_lastScanOptions = std::move(options);
}

feetech::PortProbe *ConnectionController::portProbe() const
{
    return m_probeThread ? m_probeThread->session() : nullptr;
}

void ConnectionController::setFeetechActive(bool feetech)
{
    m_feetechActive = feetech;
    emit feetechActiveChanged(feetech);
}

void ConnectionController::connectTo(const Request &request)
{
    QString port = request.port;
    m_portShown = port;
    if (port.isEmpty()) {
        emit problem(tr("Choose a serial port first."));
        return;
    }
    Protocol protocol = request.protocol;
    const bool arm = port == QLatin1String(kSimulatedArmPort);
    const bool feetechBus = arm || port == QLatin1String(kSimulatedFeetechPort);
    if (const auto spoken = simulatedProtocol(port)) {
        protocol = *spoken;
        if (!m_demo)
            m_demo = std::make_unique<sim::DemoServos>();
        sim::SimRefusal why;
        port = arm       ? m_demo->armPort(&why)
            : feetechBus ? m_demo->feetechPort(&why)
                         : m_demo->ptkPort(&why);
        if (port.isEmpty()) {
            emit problem(tr("The simulated servos could not start: %1").arg(why.describe()));
            return;
        }
        m_portShown = arm ? tr("simulated SO-101 arm")
            : feetechBus  ? tr("simulated Feetech bus")
                          : tr("simulated PTK servo");
    }
    // The Simulator dock goes with a simulated Feetech bus; a PTK servo has nothing to plug.
    m_simulator = !feetechBus ? nullptr : arm ? m_demo->armSimulator() : m_demo->feetechSimulator();
    emit simulatorChanged(m_simulator);
    m_portPath = port;
    m_probe.reset();
    if (protocol == Protocol::Auto) {
        detectAndConnect(port);
        return;
    }
    if (request.baud <= 0) {
        emit problem(tr("Enter a baud rate."));
        return;
    }
    emit sessionActiveChanged(true);
    if (protocol == Protocol::Feetech) {
        emit feetechPortNamed(m_portShown);
        m_feetech->connectTo(port, request.baud, request.echo);
    } else {
        m_ptk->connectTo(port, request.baud, request.echo);
    }
}

void ConnectionController::disconnectFrom()
{
    if (m_probeThread) {
        cancelDetection();
        return;
    }
    if (m_feetechActive)
        m_feetech->disconnectFrom();
    else
        m_ptk->disconnectFrom();
}

void ConnectionController::scanOnceConnected(const feetech::ScanOptions &options)
{
    // Scan as soon as the port is open, so the tree fills by itself.
    auto *once = new QObject(this);
    connect(m_feetech, &feetech::BusClient::statusChanged, once,
            [this, once, options](const seriallink::ConnectionStatus &status) {
                if (status.state == seriallink::ConnectionState::Disconnected) {
                    once->deleteLater(); // the port never opened: no scan later
                    return;
                }
                if (status.state != seriallink::ConnectionState::Connected)
                    return;
                emit scanWanted(options);
                once->deleteLater();
            });
}

void ConnectionController::onFeetechScanFinished(bool completed)
{
    if (!completed || m_doctorCheck->isRunning())
        return;
    QVector<feetech::ServoInfo> found;
    for (int i = 0; i < m_feetech->servos()->count(); ++i)
        found.append(m_feetech->servos()->at(i).info);
    const QVector<feetech::ExpectedServo> expected = m_expectedServos(m_portPath);
    const bool cameBackShort = found.isEmpty() || missesAServo(expected, found);
    if (!cameBackShort)
        feetech::rememberServos(m_portPath, found);
    if (!cameBackShort && !m_doctorShown())
        return;
    feetech::BusObservation seen;
    if (m_probe) {
        seen.probe = *m_probe;
    } else {
        seen.probed = false;
        seen.probe.port = m_portShown;
    }
    seen.scanned = true;
    seen.scannedBauds = m_lastScanOptions().bauds;
    emit doctorChecking(m_portShown);
    if (cameBackShort)
        emit doctorWanted();
    m_doctorCheck->start(seen, expected);
}

void ConnectionController::rescanForDoctor()
{
    if (m_feetechActive && m_feetech->link()->isConnected()) {
        // A probe only hears who answers a broadcast: on an open bus, the scan says more.
        feetech::ScanOptions options = m_lastScanOptions();
        if (m_probe)
            options.bauds = m_probe->answeringBauds();
        emit scanWanted(options);
        return;
    }
    if (m_ptk->status().state != seriallink::ConnectionState::Disconnected
        || m_feetech->link()->status().state != seriallink::ConnectionState::Disconnected)
        return; // a PTK servo, or a link still opening: nothing to re-scan
    if (m_portPath.isEmpty()) {
        emit problem(tr("Choose a serial port first."));
        return;
    }
    detectAndConnect(m_portPath);
}

void ConnectionController::detectAndConnect(const QString &port)
{
    if (m_probeThread)
        return;
    m_probe.reset();
    m_portPath = port;
    emit sessionActiveChanged(true); // Disconnect stops the probe
    m_probeThread = std::make_unique<seriallink::SessionThread<feetech::PortProbe>>(
        QStringLiteral("port probe"), feetech::ProbeTiming {});
    connect(m_probeThread->session(), &feetech::PortProbe::finished, this,
            &ConnectionController::onProbeFinished);
    emit detectionStarted(m_portShown);
    m_probeThread->run([port](feetech::PortProbe &worker) { worker.start(port); });
}

void ConnectionController::cancelDetection()
{
    if (m_probeThread)
        m_probeThread->run([](feetech::PortProbe &worker) { worker.cancel(); });
}

void ConnectionController::onProbeFinished(const feetech::PortProbeReport &report)
{
    m_probeThread.reset(); // the probe has closed the port: a client may open it
    emit detectionFinished();
    emit sessionActiveChanged(false);
    if (report.cancelled) {
        emit message(tr("Auto-detection cancelled; nothing was connected."));
        return;
    }
    const seriallink::EchoMode echo =
        report.echo ? seriallink::EchoMode::On : seriallink::EchoMode::Off;
    const QVector<qint32> bauds = report.answeringBauds();
    if (report.ptk || !bauds.isEmpty()) {
        const qint32 baud = report.ptk ? 115200 : bauds.first();
        emit detected(baud, echo);
        emit sessionActiveChanged(true);
        setFeetechActive(!report.ptk);
        if (report.ptk) {
            emit message(tr("A PTK servo answers at 115,200 bps."));
            m_ptk->connectTo(report.port, baud, echo);
            return;
        }
        m_probe = report;
        emit feetechPortNamed(m_portShown);
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
    emit doctorFindings(m_portShown, feetech::diagnoseBus(seen, m_expectedServos(report.port)));
    emit doctorWanted();
    emit problem(
        tr("Nothing answers on %1: the Doctor panel says what to check.").arg(m_portShown));
}
