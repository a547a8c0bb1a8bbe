// ServoBench's main window: connection bar, the PTK and Feetech workspaces, the packet log, the
// Doctor panel and the status bar.
#pragma once

#include "connectioncontroller.h"
#include "linktypes.h"

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
class QDialog;
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
}
namespace sim {
class SimulatorThread;
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
    WelcomePanel *welcomePanel() const { return m_welcome; }
    PtkWorkspace *ptkWorkspace() const { return m_ptkWorkspace; }
    ParameterPage *ptkPage() const;
    PacketLogDock *packetLog() const { return m_packetLog; }
    // Null until a simulated Feetech bus or arm was connected to.
    SimulatorDock *simulatorDock() const { return m_simulatorDock; }
    DoctorPanel *doctorPanel() const { return m_doctor; }
    // What decides how to connect: the port and protocol, Auto's probe, the demo, the doctor.
    ConnectionController *connection() const { return m_connection.get(); }

    // The PTK workspace's, for the command line and tests.
    void loadProfile(const QString &path);
    bool saveProfile(const QString &path);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void createMenus();
    void createDoctor();
    // The window shows what the connection controller reports.
    void followConnection();
    void showAbout();
    // Closes the window as Quit does and, once it is closed, starts ServoBench again.
    void restart();
    void resetLayout();
    void fillRecentProfiles(QMenu *menu);
    void connectRequested();
    void onStatusChanged(const seriallink::ConnectionStatus &status);
    void onCountersChanged(const seriallink::LinkCounters &counters);
    void chooseProfileToSave();
    void chooseProfileToLoad();
    void showProblem(const QString &message);
    // Shows `wizard` (made or reopened); the problems the banner shows while it is open (its
    // own operations' failures, which it shows itself too) go when it closes, however it closes.
    void showWizard(QDialog *wizard);
    void followWizard(QDialog *wizard);
    void showProtocol(bool feetech);
    void updateFeetechBusActions(); // enabled while a Feetech bus is connected
    void updatePollRate();
    // Auto's probe runs: its progress in a dialog whose Cancel stops it.
    void showDetection(const QString &port);
    void endDetection();
    void openDoctor();
    // The demo's bus or arm in the Simulator dock; the dock is hidden for anything else (null).
    void showSimulator(sim::SimulatorThread *simulator);

    // Before the clients: it stops the demo's simulated servos once their ports are closed.
    std::unique_ptr<ConnectionController> m_connection;
    std::unique_ptr<ptk::Client> m_ptk;
    std::unique_ptr<feetech::BusClient> m_feetech;
    ConnectionBar *m_connectionBar = nullptr;
    PtkWorkspace *m_ptkWorkspace = nullptr;
    FeetechWorkspace *m_feetechWorkspace = nullptr;
    QAction *m_allTorqueOff = nullptr; // Esc: torque off on the whole Feetech bus
    QAction *m_shareBus = nullptr; // Link > Share this bus…
    QStackedWidget *m_pages = nullptr;
    QList<QAction *> m_ptkActions; // Link menu entries that only mean something for PTK
    PacketLogDock *m_packetLog = nullptr;
    SimulatorDock *m_simulatorDock = nullptr;
    QMenu *m_viewMenu = nullptr;
    QLabel *m_problem = nullptr; // a banner above the page: why the last action failed
    quint64 m_problemsShown = 0; // how many the banner has shown, to tell which came when
    QLabel *m_connectionState = nullptr;
    QLabel *m_pollRate = nullptr;
    QLabel *m_counters = nullptr;
    QTimer *m_rateTimer = nullptr;
    DoctorPanel *m_doctor = nullptr;
    QProgressDialog *m_probeProgress = nullptr;
    WelcomePanel *m_welcome = nullptr;
    std::unique_ptr<WindowMemory> m_memory;
    seriallink::LinkCounters m_lastCounters; // as the status bar shows them
    qint64 m_streamMissed = 0; // samples the Feetech stream missed (its servos' silences)
    // The protocol chosen before a simulated bus set its own: back once a system port is chosen.
    std::optional<ConnectionController::Protocol> m_protocolBeforeSimulated;
};
