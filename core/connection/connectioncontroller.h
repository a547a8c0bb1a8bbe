// Connecting to servos, without widgets: which port and protocol (PTK, Feetech, or Auto, which
// probes the port first and opens what answered), the demo's simulated buses, which of the two
// clients is the active one, and the doctor that checks a scan that came back short.
#pragma once

#include "busdoctor.h"
#include "bustypes.h"
#include "linktypes.h"
#include "portprobe.h"
#include "sessionthread.h"
#include "simulatorthread.h"

#include <QObject>

#include <functional>
#include <memory>
#include <optional>

namespace ptk {
class Client;
}
namespace feetech {
class BusClient;
class DoctorCheck;
} // namespace feetech
namespace sim {
class DemoServos;
}

class ConnectionController : public QObject
{
    Q_OBJECT

public:
    // The ports that name the in-process simulated servos rather than a system port.
    static constexpr char kSimulatedPtkPort[] = "simulated:ptk";
    static constexpr char kSimulatedFeetechPort[] = "simulated:feetech";
    static constexpr char kSimulatedArmPort[] = "simulated:so101"; // an SO-101 arm, set up

    // Auto: the port is probed and the workspace of what answers opens.
    enum class Protocol { Ptk, Feetech, Auto };

    struct Request
    {
        QString port; // a system path or one of the simulated ports
        Protocol protocol = Protocol::Auto;
        qint32 baud = 0; // Auto finds it
        seriallink::EchoMode echo = seriallink::EchoMode::Off;
    };

    // The servos the doctor expects on a port: by default those last found there.
    using ExpectedServos = std::function<QVector<feetech::ExpectedServo>(const QString &port)>;

    // Connects the two clients, which outlive it.
    ConnectionController(ptk::Client *ptk, feetech::BusClient *feetech, QObject *parent = nullptr);
    ~ConnectionController() override;

    // The protocol a simulated port speaks; none for a system port.
    static std::optional<Protocol> simulatedProtocol(const QString &port);

    // Opens the request's port (a simulated one starts its servos first), or probes it for Auto.
    // What goes wrong is told through `problem`.
    void connectTo(const Request &request);
    // Stops the probe of Auto, or closes the active client.
    void disconnectFrom();
    // Once the Feetech bus is open, asks for a scan with `options` (scanWanted).
    void scanOnceConnected(const feetech::ScanOptions &options = {});
    // The doctor's Re-scan: an open Feetech bus is scanned again at the rates the probe heard;
    // a port that is not open is probed again.
    void rescanForDoctor();
    void cancelDetection();

    // The workspace shown: the protocol chosen, or what Auto found.
    void setFeetechActive(bool feetech);
    bool isFeetechActive() const { return m_feetechActive; }
    bool isDetecting() const { return m_probeThread != nullptr; }
    // The probe of Auto while it runs (it lives in its own thread); null otherwise.
    feetech::PortProbe *portProbe() const;
    // What the user connected to, as they chose it ("simulated Feetech bus" for the demo's).
    QString portShown() const { return m_portShown; }
    // The port actually opened (a simulated bus's port inside the program, by its name).
    QString portPath() const { return m_portPath; }
    // What the probe of Auto heard; none for a protocol chosen by hand.
    const std::optional<feetech::PortProbeReport> &probeReport() const { return m_probe; }
    // The running simulator of the demo's Feetech bus or arm; null for anything else.
    sim::SimulatorThread *simulator() const { return m_simulator; }
    // The demo's simulators, null until a simulated port was first opened: more of them (a
    // leader arm for the simulated arm) start from here.
    sim::DemoServos *demo() const { return m_demo.get(); }

    // What the doctor needs from whoever shows it: the servos it expects on a port, whether it
    // is shown (a full scan is checked only then), and the options of the last scan.
    void setExpectedServos(ExpectedServos expected);
    void setDoctorShown(std::function<bool()> shown);
    void setLastScanOptions(std::function<feetech::ScanOptions()> options);

signals:
    void problem(const QString &message);
    void message(const QString &text);
    // A connection is open, opening or being detected: Disconnect is what the user can do.
    void sessionActiveChanged(bool active);
    // The demo's simulated Feetech bus or arm is the one connected to, or (null) none is.
    void simulatorChanged(sim::SimulatorThread *simulator);
    void feetechActiveChanged(bool feetech);
    // The Feetech bus opens on this port, as the user knows it.
    void feetechPortNamed(const QString &name);
    void detectionStarted(const QString &port);
    void detectionFinished();
    // The rate and echo Auto found and opened the port with.
    void detected(qint32 baud, seriallink::EchoMode echo);
    void scanWanted(const feetech::ScanOptions &options);
    void doctorChecking(const QString &port);
    void doctorFindings(const QString &port, const QVector<feetech::DoctorFinding> &findings);
    // The doctor has something to say: its panel should be in view.
    void doctorWanted();

private:
    void detectAndConnect(const QString &port);
    void onProbeFinished(const feetech::PortProbeReport &report);
    void onFeetechScanFinished(bool completed);

    std::unique_ptr<sim::DemoServos> m_demo; // started on first use
    ptk::Client *m_ptk = nullptr;
    feetech::BusClient *m_feetech = nullptr;
    feetech::DoctorCheck *m_doctorCheck = nullptr;
    std::unique_ptr<seriallink::SessionThread<feetech::PortProbe>> m_probeThread;
    std::optional<feetech::PortProbeReport> m_probe;
    sim::SimulatorThread *m_simulator = nullptr;
    bool m_feetechActive = false;
    QString m_portShown;
    QString m_portPath;
    ExpectedServos m_expectedServos;
    std::function<bool()> m_doctorShown;
    std::function<feetech::ScanOptions()> m_lastScanOptions;
};
