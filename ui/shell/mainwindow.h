// ServoBench's main window: connection bar, the PTK and Feetech workspaces, the packet log and
// the status bar.
#pragma once

#include "bustypes.h"
#include "linktypes.h"
#include "portprobe.h"
#include "sessionthread.h"

#include <QMainWindow>

#include <memory>
#include <optional>

class ConnectionBar;
class DoctorPanel;
class QProgressDialog;
class FeetechWorkspace;
class QStackedWidget;
class PacketLogDock;
class ParameterPage;
class PtkWorkspace;
class QAction;
class QMenu;
class QLabel;
class QTimer;
class SimulatorDock;
class WelcomePanel;
class WindowMemory;

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

class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // Connects to the in-process simulated PTK servo (servobench --demo).
    void startDemo();
    // Connects to the in-process simulated Feetech bus and scans it (--demo-feetech).
    void startFeetechDemo();
    // Connects to an in-process simulated SO-101 arm and scans it (--demo-robot).
    void startArmDemo();
    void connectToPort(const QString &port);

    ptk::Client *ptkClient() const { return m_ptk.get(); }
    feetech::BusClient *feetechClient() const { return m_feetech.get(); }
    FeetechWorkspace *feetechWorkspace() const { return m_feetechWorkspace; }
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    PtkWorkspace *ptkWorkspace() const { return m_ptkWorkspace; }
    ParameterPage *ptkPage() const;
    PacketLogDock *packetLog() const { return m_packetLog; }
    // Null until a simulated Feetech bus or arm was connected to.
    SimulatorDock *simulatorDock() const { return m_simulatorDock; }
    DoctorPanel *doctorPanel() const { return m_doctor; }
    bool isDetecting() const { return m_probeThread != nullptr; }

    // The PTK workspace's, for the command line and tests.
    void loadProfile(const QString &path);
    bool saveProfile(const QString &path);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createMenus();
    void showAbout();
    // Closes the window as Quit does and, once it is closed, starts ServoBench again.
    void restart();
    void resetLayout();
    void fillRecentProfiles(QMenu *menu);
    void connectRequested();
    void disconnectRequested();
    void onStatusChanged(const seriallink::ConnectionStatus &status);
    void onCountersChanged(const seriallink::LinkCounters &counters);
    void chooseProfileToSave();
    void chooseProfileToLoad();
    void showProblem(const QString &message);
    void showProtocol(bool feetech);
    void updateTorqueOffAction(); // enabled while a Feetech bus is connected
    void updatePollRate();
    void scanOnceConnected(const feetech::ScanOptions &options = {});
    // Auto (mainwindowdoctor.cpp): probe the port in a worker thread, then open the workspace
    // of what answered at the rate and echo it found, and scan the Feetech rates that answered.
    void detectAndConnect(const QString &port);
    void cancelDetection();
    void onProbeFinished(const feetech::PortProbeReport &report);
    // The doctor: after a scan that came back short (or while the panel is open), each servo
    // is read and the findings listed in the Doctor panel, which opens by itself.
    void createDoctor();
    void onFeetechScanFinished(bool completed);
    void rescanForDoctor();
    void openDoctor();
    void showSimulatorDock(bool arm); // the demo's bus or arm; hidden for anything else

    std::unique_ptr<sim::DemoServos> m_demo;
    std::unique_ptr<ptk::Client> m_ptk;
    std::unique_ptr<feetech::BusClient> m_feetech;
    ConnectionBar *m_connectionBar = nullptr;
    PtkWorkspace *m_ptkWorkspace = nullptr;
    FeetechWorkspace *m_feetechWorkspace = nullptr;
    QAction *m_allTorqueOff = nullptr; // Esc: torque off on the whole Feetech bus
    QStackedWidget *m_pages = nullptr;
    QList<QAction *> m_ptkActions; // Link menu entries that only mean something for PTK
    bool m_feetechActive = false;
    PacketLogDock *m_packetLog = nullptr;
    SimulatorDock *m_simulatorDock = nullptr;
    QMenu *m_viewMenu = nullptr;
    QLabel *m_problem = nullptr; // a banner above the page: why the last action failed
    QLabel *m_connectionState = nullptr;
    QLabel *m_pollRate = nullptr;
    QLabel *m_counters = nullptr;
    QTimer *m_rateTimer = nullptr;
    QString m_portShown; // what the user connected to, as they chose it
    QString m_portPath; // the port actually opened (a simulated bus's pty)
    DoctorPanel *m_doctor = nullptr;
    feetech::DoctorCheck *m_doctorCheck = nullptr;
    std::unique_ptr<seriallink::SessionThread<feetech::PortProbe>> m_probeThread;
    QProgressDialog *m_probeProgress = nullptr;
    // What the probe of the Auto connection heard; none for a protocol chosen by hand.
    std::optional<feetech::PortProbeReport> m_probe;
    WelcomePanel *m_welcome = nullptr;
    std::unique_ptr<WindowMemory> m_memory;
};
