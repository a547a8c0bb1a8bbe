// ServoBench's main window: the connection bar and what the connection controller reports, the
// two workspaces, the Doctor panel, the packet log and the status bar.
#include "mainwindow.h"

#include "busclient.h"
#include "calibrationactions.h"
#include "calibrationwizard.h"
#include "connectionbar.h"
#include "connectioncontroller.h"
#include "demoservos.h"
#include "doctorpanel.h"
#include "feetechworkspace.h"
#include "languagemenu.h"
#include "lerobotcalibration.h"
#include "packetlogdock.h"
#include "packetlogmodel.h"
#include "packetwindow.h"
#include "parametermodel.h"
#include "ptkclient.h"
#include "ptkworkspace.h"
#include "recentfiles.h"
#include "recordreplaydialog.h"
#include "replacemotorwizard.h"
#include "robotactions.h"
#include "robottemplate.h"
#include "servolist.h"
#include "setupwizard.h"
#include "sharedialog.h"
#include "shortcutsdialog.h"
#include "simulator.h"
#include "simulatordock.h"
#include "simulatorthread.h"
#include "skippablequestion.h"
#include "telemetryhub.h"
#include "teleopdialog.h"
#include "virtualfeetechbus.h"
#include "welcomepanel.h"
#include "windowmemory.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProcess>
#include <QProgressDialog>
#include <QScreen>
#include <QStackedWidget>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTimer>
#include <QVBoxLayout>

namespace {

constexpr int kRateRefreshMs = 500;
constexpr int kStatusMessageMs = 8000;
constexpr int kLogStripHeight = 110; // the packet log at first: a few rows
// The guard's news stays longer: it says what was done to a servo.
constexpr int kGuardMessageMs = 20000;
constexpr int kDoctorMessageMs = 8000;

QString stateColour(seriallink::ConnectionState state)
{
    switch (state) {
    case seriallink::ConnectionState::Connected:
        return QStringLiteral("#1b7f3b");
    case seriallink::ConnectionState::Connecting:
        return QStringLiteral("#8a6d00");
    case seriallink::ConnectionState::NoReply:
    case seriallink::ConnectionState::Lost:
        return QStringLiteral("#b3261e");
    case seriallink::ConnectionState::Disconnected:
        break;
    }
    return QStringLiteral("#555555");
}

// A LeRobot calibration file of what the demo's simulated leader arm holds (its joints named as
// its template names them), in ServoBench's data folder: the demo teleoperates without a file
// the user never had. Its path; empty and *error when it could not be made.
QString demoLeaderCalibration(sim::DemoServos &demo, QString *error)
{
    sim::SimulatorThread *arm = demo.leaderArmSimulator();
    const auto robot = std::find_if(
        feetech::builtInRobotTemplates().cbegin(), feetech::builtInRobotTemplates().cend(),
        [](const feetech::RobotTemplate &t) { return t.name == u"SO-101 leader arm"; });
    if (!arm || robot == feetech::builtInRobotTemplates().cend()) {
        *error = MainWindow::tr("the simulated leader arm is not running");
        return {};
    }
    QVector<feetech::LeRobotMotor> motors;
    arm->call([&motors, &robot](sim::Simulator &simulator) {
        sim::VirtualFeetechBus *bus = simulator.feetechBus();
        for (int i = 0; bus && i < bus->servoCount(); ++i) {
            const sim::VirtualFeetechServo &servo = bus->servo(i);
            for (const feetech::RobotJoint &joint : robot->joints) {
                if (joint.id == servo.id())
                    motors.append({joint.name, joint.id, 0, servo.value(u"position_offset"),
                                   servo.value(u"min_angle_limit"),
                                   servo.value(u"max_angle_limit")});
            }
        }
    });
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(folder);
    const QString path = QDir(folder).filePath(QStringLiteral("demo-leader-calibration.json"));
    util::FileError failed;
    if (motors.isEmpty() || !feetech::saveLeRobotCalibration(motors, path, &failed)) {
        *error = motors.isEmpty() ? MainWindow::tr("the simulated leader arm has no joints")
                                  : failed.describe();
        return {};
    }
    return path;
}

// The height of the tabs under docks tabbed together, as the main window draws them.
int dockTabBarHeight(const QDockWidget *dock)
{
    QTabBar probe;
    probe.setFont(dock->font());
    probe.setDrawBase(true);
    probe.addTab(dock->windowTitle());
    return probe.sizeHint().height();
}

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_ptk(std::make_unique<ptk::Client>())
    , m_feetech(std::make_unique<feetech::BusClient>())
{
    setWindowTitle(tr("ServoBench"));
    setObjectName(QStringLiteral("mainWindow"));
    // 1280x820 where there is room; on a 1366x768 screen what is left under the desktop's
    // panels and the title bar, so the status bar stays on the screen.
    const QRect available = screen()->availableGeometry();
    resize(std::min(1280, available.width() - 16), std::min(820, available.height() - 48));

    m_connectionBar = new ConnectionBar(this);
    addToolBar(Qt::TopToolBarArea, m_connectionBar);
    connect(m_connectionBar, &ConnectionBar::connectRequested, this, &MainWindow::connectRequested);
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this,
            [this] { m_connection->disconnectFrom(); });

    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(8, 8, 8, 0);
    m_problem = new QLabel(central);
    m_problem->setObjectName(QStringLiteral("problemBanner"));
    m_problem->setWordWrap(true);
    m_problem->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problem->setStyleSheet(QStringLiteral("QLabel { background: #fde7e4; color: #7a1d14; "
                                            "border: 1px solid #e3a59c; border-radius: 4px; "
                                            "padding: 6px 10px; }"));
    m_problem->hide();
    layout->addWidget(m_problem);

    m_pages = new QStackedWidget(central);
    m_ptkWorkspace = new PtkWorkspace(m_ptk.get(), m_pages);
    m_pages->addWidget(m_ptkWorkspace);
    m_feetechWorkspace = new FeetechWorkspace(m_feetech.get(), m_pages);
    m_pages->addWidget(m_feetechWorkspace);
    // While nothing is connected: the ports, the simulated servos and the wiring.
    m_welcome = new WelcomePanel(m_pages);
    m_pages->addWidget(m_welcome);
    m_pages->setCurrentWidget(m_welcome);
    connect(m_welcome, &WelcomePanel::connectRequested, this, [this](const QString &port) {
        // The page stays while Auto probes a port (nothing is open yet): one thing at a time.
        if (m_connection->isDetecting()) {
            showProblem(tr("Wait until the port being probed answers, or Disconnect."));
            return;
        }
        connectToPort(port);
    });
    // One port chosen, shown in both places: Connect is offered in both by the same rule.
    connect(m_connectionBar, &ConnectionBar::portChanged, m_welcome, &WelcomePanel::showChosenPort);
    connect(m_connectionBar, &ConnectionBar::portChanged, this, [this](const QString &port) {
        if (!m_protocolBeforeSimulated || port.isEmpty()
            || ConnectionController::simulatedProtocol(port))
            return;
        m_connectionBar->setProtocol(*std::exchange(m_protocolBeforeSimulated, std::nullopt));
    });
    connect(m_welcome, &WelcomePanel::portChosen, m_connectionBar, &ConnectionBar::setPort);
    m_welcome->showChosenPort(m_connectionBar->port());
    layout->addWidget(m_pages);
    setCentralWidget(central);
    connect(m_connectionBar, &ConnectionBar::protocolChanged, this,
            [this](ConnectionBar::Protocol protocol) {
                m_connection->setFeetechActive(protocol == ConnectionBar::Protocol::Feetech);
            });
    connect(m_ptkWorkspace, &PtkWorkspace::problem, this, &MainWindow::showProblem);
    connect(m_ptkWorkspace, &PtkWorkspace::actionStarted, m_problem, &QWidget::hide);
    connect(m_ptkWorkspace, &PtkWorkspace::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, kStatusMessageMs); });
    connect(m_feetechWorkspace, &FeetechWorkspace::problem, this, &MainWindow::showProblem);
    connect(m_feetechWorkspace, &FeetechWorkspace::message, this, [this](const QString &text) {
        m_problem->hide();
        statusBar()->showMessage(text, kStatusMessageMs);
    });

    m_packetLog = new PacketLogDock(this);
    addDockWidget(Qt::BottomDockWidgetArea, m_packetLog);
    // A strip at first: the pages above (the Monitor's charts) get the height.
    resizeDocks({m_packetLog}, {kLogStripHeight}, Qt::Vertical);

    createMenus();
    createDoctor();
    // After the workspaces and the Doctor panel: they hear of a finished scan first.
    m_connection = std::make_unique<ConnectionController>(m_ptk.get(), m_feetech.get());
    followConnection();
    connect(m_feetech.get(), &feetech::BusClient::statusChanged, this,
            [this] { updateFeetechBusActions(); });
    // Whatever page moves the servos, the guard's warnings and actions show here.
    connect(m_feetech->guard(), &feetech::BusGuard::event, this,
            [this](const feetech::GuardEvent &event) {
                statusBar()->showMessage(event.message, kGuardMessageMs);
            });
    // A shared bus's alerts: whichever page is open (the packet log has them too).
    connect(m_feetech->share(), &feetech::ShareService::alertRaised, this,
            [this](const share::ShareAlert &alert) {
                statusBar()->showMessage(
                    tr("Shared bus, servo %1: %2").arg(alert.id).arg(alert.message),
                    kGuardMessageMs);
            });
    connect(m_feetech->share(), &feetech::ShareService::stateChanged, this,
            [this](feetech::ShareService::State state) {
                if (state == feetech::ShareService::State::Sharing)
                    statusBar()->showMessage(
                        tr("Sharing the bus: the other program opens %1.")
                            .arg(QDir::toNativeSeparators(m_feetech->share()->linkPath())),
                        kStatusMessageMs);
                else if (state == feetech::ShareService::State::Off)
                    statusBar()->showMessage(tr("The bus is not shared."), kStatusMessageMs);
            });
    connect(m_feetech->share(), &feetech::ShareService::startFailed, this,
            [this](const QString &why) { statusBar()->showMessage(why, kStatusMessageMs); });

    m_connectionState = new QLabel(tr("Not connected"), this);
    m_connectionState->setObjectName(QStringLiteral("connectionState"));
    m_pollRate = new QLabel(this);
    m_pollRate->setObjectName(QStringLiteral("pollRate"));
    m_counters = new QLabel(this);
    m_counters->setObjectName(QStringLiteral("linkCounters"));
    // Permanent, so that a passing message never hides whether the servo is connected.
    statusBar()->addPermanentWidget(m_connectionState);
    statusBar()->addPermanentWidget(m_pollRate);
    statusBar()->addPermanentWidget(m_counters);
    onCountersChanged({});

    // Either family's link is shown the same way: status bar, counters, packet log.
    for (seriallink::LinkMirror *link : {m_ptk->link(), m_feetech->link()}) {
        connect(link, &seriallink::LinkMirror::statusChanged, this, &MainWindow::onStatusChanged);
        connect(link, &seriallink::LinkMirror::countersChanged, this,
                &MainWindow::onCountersChanged);
        connect(link, &seriallink::LinkMirror::packetLogged, m_packetLog, &PacketLogDock::append);
    }
    // A stream's misses are said beside the link's counters: a servo that stops answering in a
    // SYNC READ is a missed sample, not a timed-out request, and the line must not say "0".
    connect(m_feetech->telemetry(), &feetech::TelemetryHub::statsChanged, this,
            [this](const feetech::TelemetryStats &stats) {
                m_streamMissed = stats.missed;
                onCountersChanged(m_lastCounters);
            });

    m_rateTimer = new QTimer(this);
    m_rateTimer->setInterval(kRateRefreshMs);
    connect(m_rateTimer, &QTimer::timeout, this, &MainWindow::updatePollRate);
    m_rateTimer->start();
    updatePollRate();

    m_memory = std::make_unique<WindowMemory>(*this, *m_connectionBar);
    m_memory->restore();
}

ParameterPage *MainWindow::ptkPage() const
{
    return m_ptkWorkspace->page();
}

MainWindow::~MainWindow()
{
    // The pages talk to the clients until they are gone, and the clients are members: the
    // pages go first (QWidget would delete them only after the members).
    delete m_pages;
    // It looks at the demo's simulators, which are members too.
    delete m_simulatorDock;
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *load = file->addAction(tr("&Load profile…"), this, &MainWindow::chooseProfileToLoad);
    load->setShortcut(QKeySequence::Open);
    QAction *save = file->addAction(tr("&Save profile…"), this, &MainWindow::chooseProfileToSave);
    save->setShortcut(QKeySequence::Save);
    QMenu *recent = file->addMenu(tr("&Recent profiles"));
    recent->setObjectName(QStringLiteral("recentProfilesMenu"));
    connect(recent, &QMenu::aboutToShow, this, [this, recent] { fillRecentProfiles(recent); });
    file->addSeparator();
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setObjectName(QStringLiteral("quitAction"));

    QMenu *link = menuBar()->addMenu(tr("&Link"));
    QAction *polling = link->addAction(tr("&Poll the servo"));
    polling->setObjectName(QStringLiteral("pollingAction"));
    polling->setCheckable(true);
    polling->setChecked(true);
    polling->setToolTip(tr("Keep reading the eight queries so the values stay live"));
    connect(polling, &QAction::toggled, this, [this](bool on) { m_ptk->setPolling(on); });
    m_ptkActions.append(polling);
    QAction *fast = link->addAction(tr("&Fast polling (queries back to back)"));
    fast->setObjectName(QStringLiteral("fastPollingAction"));
    fast->setCheckable(true);
    connect(fast, &QAction::toggled, this, [this](bool on) {
        m_ptk->setPollInterval(int(ptk::SessionTiming().pollInterval.count()), on);
    });
    m_ptkActions.append(fast);
    link->addSeparator();
    QAction *scan = link->addAction(tr("&Scan the Feetech bus…"));
    scan->setObjectName(QStringLiteral("scanAction"));
    scan->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_F5));
    connect(scan, &QAction::triggered, this, [this] {
        if (!m_connection->isFeetechActive()
            && m_ptk->status().state != seriallink::ConnectionState::Disconnected) {
            showProblem(tr("Disconnect from the PTK servo before scanning a Feetech bus."));
            return;
        }
        m_connectionBar->setProtocol(ConnectionBar::Protocol::Feetech);
        m_feetechWorkspace->openScanDialog();
    });

    QAction *packets = link->addAction(tr("Pac&ket window…"), this, [this] {
        auto *window = findChild<PacketWindow *>();
        if (!window)
            window = new PacketWindow(m_feetech.get(), m_ptk.get(), this);
        window->show();
        window->raise();
        window->activateWindow();
    });
    packets->setObjectName(QStringLiteral("packetWindowAction"));
    packets->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));

    // Another program (LeRobot, a script) on the same servos, through ServoBench.
    m_shareBus = link->addAction(tr("Share this &bus…"));
    m_shareBus->setObjectName(QStringLiteral("shareBusAction"));
    m_shareBus->setToolTip(tr("Give another program a port of its own on this Feetech bus and "
                              "watch its traffic"));
    m_shareBus->setEnabled(false);
    connect(m_shareBus, &QAction::triggered, this, [this] {
        auto *dialog = findChild<ShareDialog *>();
        if (!dialog)
            dialog = new ShareDialog(m_feetech.get(), this);
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });

    // The emergency stop of the Feetech bus. Esc reaches it from every page of the window; a
    // dialog that is open keeps Esc for itself (and a modal one blocks the bus work anyway).
    m_allTorqueOff = link->addAction(tr("All &torque off"));
    m_allTorqueOff->setObjectName(QStringLiteral("allTorqueOffAction"));
    m_allTorqueOff->setShortcut(QKeySequence(Qt::Key_Escape));
    m_allTorqueOff->setShortcutContext(Qt::WindowShortcut);
    m_allTorqueOff->setToolTip(tr("Switch the torque of every servo on the Feetech bus off"));
    m_allTorqueOff->setEnabled(false);
    connect(m_allTorqueOff, &QAction::triggered, this, [this] {
        if (!m_connection->isFeetechActive() || !m_feetech->link()->isConnected())
            return;
        statusBar()->showMessage(tr("Torque off: sent to every servo…"));
        m_feetech->allTorqueOff();
    });

    // &Robot: work on a whole arm. Set up motors finds each servo itself, so it needs only an
    // open Feetech port, no scan.
    QMenu *robot = menuBar()->addMenu(tr("&Robot"));
    robot->setObjectName(QStringLiteral("robotMenu"));
    QAction *setUpMotors = robot->addAction(tr("Set up &motors…"));
    setUpMotors->setObjectName(QStringLiteral("setUpMotorsAction"));
    setUpMotors->setEnabled(false);
    connect(m_feetech.get(), &feetech::BusClient::statusChanged, setUpMotors,
            [this, setUpMotors] { setUpMotors->setEnabled(m_feetech->link()->isConnected()); });
    // A set-up changes the IDs and settings of the servos a calibration records and writes.
    const auto calibrating = [this] {
        auto *calibration = findChild<CalibrationWizard *>();
        if (!calibration || !calibration->isVisible())
            return false;
        showProblem(tr("Close the calibration wizard before setting up motors: a set-up changes "
                       "the servos' IDs and settings."));
        calibration->raise();
        calibration->activateWindow();
        return true;
    };
    connect(setUpMotors, &QAction::triggered, this, [this, calibrating] {
        if (calibrating())
            return;
        auto *wizard = findChild<SetupWizard *>();
        if (!wizard)
            wizard = new SetupWizard(m_feetech.get(), this);
        showWizard(wizard);
    });
    // Replacing one joint's motor: its set-up needs an open port only, as Set up motors; the
    // wizard scans the arm itself before calibrating the joint.
    QAction *replaceMotor = robot->addAction(tr("Re&place a motor…"));
    replaceMotor->setObjectName(QStringLiteral("replaceMotorAction"));
    replaceMotor->setToolTip(tr("Set up a new servo as one joint of an arm and calibrate that "
                                "joint alone into the arm's LeRobot file"));
    replaceMotor->setEnabled(false);
    connect(m_feetech.get(), &feetech::BusClient::statusChanged, replaceMotor,
            [this, replaceMotor] { replaceMotor->setEnabled(m_feetech->link()->isConnected()); });
    connect(replaceMotor, &QAction::triggered, this, [this, calibrating] {
        auto *wizard = findChild<ReplaceMotorWizard *>();
        // Its own calibration of the new joint is part of it.
        if ((!wizard || !wizard->isVisible()) && calibrating())
            return;
        if (!wizard)
            wizard = new ReplaceMotorWizard(m_feetech.get(), this);
        showWizard(wizard);
    });

    m_feetechWorkspace->robotActions()->addTo(robot);

    // Calibrating the arm, and its LeRobot calibration files: they need a scanned bus.
    robot->addSeparator();
    auto *calibration = new CalibrationActions(robot, m_feetech.get(), this);
    connect(calibration, &CalibrationActions::problem, this, &MainWindow::showProblem);
    connect(calibration, &CalibrationActions::wizardOpening, this, &MainWindow::followWizard);
    connect(calibration, &CalibrationActions::message, this, [this](const QString &text) {
        m_problem->hide();
        statusBar()->showMessage(text, kStatusMessageMs);
    });

    // Recording an arm moved by hand and playing it back: a scanned bus, the dialog non-modal.
    QAction *recordReplay = robot->addAction(tr("Record and &replay…"));
    recordReplay->setObjectName(QStringLiteral("recordReplayAction"));
    recordReplay->setToolTip(tr("Record joints moved by hand and play the motion back"));
    const auto updateRecordReplay = [this, recordReplay] {
        recordReplay->setEnabled(m_feetech->link()->isConnected()
                                 && m_feetech->servos()->count() > 0);
    };
    connect(m_feetech.get(), &feetech::BusClient::statusChanged, recordReplay, updateRecordReplay);
    connect(m_feetech->servos(), &feetech::ServoList::servosChanged, recordReplay,
            updateRecordReplay);
    updateRecordReplay();
    connect(recordReplay, &QAction::triggered, this, [this] {
        auto *dialog = findChild<RecordReplayDialog *>();
        if (!dialog)
            dialog = new RecordReplayDialog(m_feetech.get(), this);
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });

    // A leader arm on a second adapter drives the arm on this bus: a scanned bus, non-modal.
    QAction *teleoperate = robot->addAction(tr("&Teleoperate…"));
    teleoperate->setObjectName(QStringLiteral("teleoperateAction"));
    teleoperate->setToolTip(tr("Move this arm with a leader arm on another port"));
    const auto updateTeleoperate = [this, teleoperate] {
        teleoperate->setEnabled(m_feetech->link()->isConnected()
                                && m_feetech->servos()->count() > 0);
    };
    connect(m_feetech.get(), &feetech::BusClient::statusChanged, teleoperate, updateTeleoperate);
    connect(m_feetech->servos(), &feetech::ServoList::servosChanged, teleoperate,
            updateTeleoperate);
    updateTeleoperate();
    connect(teleoperate, &QAction::triggered, this, [this] {
        auto *dialog = findChild<TeleopDialog *>();
        if (!dialog)
            dialog = new TeleopDialog(m_feetech.get(), this);
        // On the demo's simulated arm, the demo offers a simulated leader arm too.
        std::function<QString(QString *)> simulatedLeader;
        if (m_connection->simulator() && m_connection->demo()) {
            simulatedLeader = [demo = m_connection->demo()](QString *error) {
                sim::SimRefusal why;
                const QString port = demo->leaderArmPort(&why);
                if (why && error)
                    *error = why.describe();
                return port;
            };
        }
        // Its calibration file, made of what the simulated leader holds, for a demo run that
        // has none.
        std::function<QString(QString *)> leaderCalibration;
        if (simulatedLeader) {
            leaderCalibration = [demo = m_connection->demo()](QString *error) {
                return demoLeaderCalibration(*demo, error);
            };
        }
        if (dialog->teleoperation()->state() == feetech::Teleoperation::State::Idle)
            dialog->setSimulatedLeader(simulatedLeader, leaderCalibration);
        dialog->show();
        dialog->raise();
        dialog->activateWindow();
    });

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    m_viewMenu->addAction(m_packetLog->toggleViewAction());
    m_viewMenu->addAction(m_connectionBar->toggleViewAction());
    QAction *resetLayoutAction =
        m_viewMenu->addAction(tr("&Reset layout"), this, &MainWindow::resetLayout);
    resetLayoutAction->setObjectName(QStringLiteral("resetLayoutAction"));
    // Questions such as Identify's can be told not to ask again: this brings them back.
    QAction *askAgain = m_viewMenu->addAction(tr("Ask skipped &questions again"), this, [this] {
        SkippableQuestion::askAllAgain();
        statusBar()->showMessage(tr("ServoBench asks again before anything moves."),
                                 kStatusMessageMs);
    });
    askAgain->setObjectName(QStringLiteral("askAgainAction"));
    askAgain->setToolTip(tr("The questions you ticked \"Don't ask again\" on are asked again"));
    connect(m_viewMenu, &QMenu::aboutToShow, askAgain,
            [askAgain] { askAgain->setEnabled(SkippableQuestion::anySkipped()); });
    m_viewMenu->addSeparator();
    auto *language = new LanguageMenu(this);
    m_viewMenu->addMenu(language);
    connect(language, &LanguageMenu::restartRequested, this, &MainWindow::restart);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *shortcuts = help->addAction(tr("&Keyboard shortcuts"), this, [this] {
        auto *dialog = new ShortcutsDialog(menuBar(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    shortcuts->setObjectName(QStringLiteral("shortcutsAction"));
    shortcuts->setShortcut(QKeySequence::HelpContents);
    QAction *about = help->addAction(tr("&About ServoBench"), this, &MainWindow::showAbout);
    about->setObjectName(QStringLiteral("aboutAction"));
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::showAbout()
{
    QMessageBox::about(
        this, tr("About ServoBench"),
        tr("<p><b>ServoBench %1</b></p>"
           "<p>Programs and monitors PTK RC servos and Feetech serial-bus "
           "servos on Linux, Windows and macOS.</p>"
           "<p>Built with Qt %2, running on Qt %3.</p>"
           "<p>Free software under the GNU General Public License, version 3 or "
           "(at your option) any later version; it comes with no warranty.</p>")
                .arg(QCoreApplication::applicationVersion(), QStringLiteral(QT_VERSION_STR),
                     QString::fromLatin1(qVersion()))
            + tr("<p>Home: <a href=\"%1\">%1</a></p>").arg(QStringLiteral(SERVOBENCH_HOMEPAGE)));
}

void MainWindow::startDemo()
{
    m_connectionBar->setPort(ConnectionBar::kSimulatedPtkPort);
    connectRequested();
}

void MainWindow::startFeetechDemo()
{
    m_connectionBar->setPort(ConnectionBar::kSimulatedFeetechPort);
    connectRequested();
    m_connection->scanOnceConnected();
}

void MainWindow::startArmDemo()
{
    m_connectionBar->setPort(ConnectionBar::kSimulatedArmPort);
    connectRequested();
    m_connection->scanOnceConnected();
}

void MainWindow::showSimulator(sim::SimulatorThread *simulator)
{
    if (!simulator) {
        if (m_simulatorDock) {
            m_simulatorDock->setSimulator(nullptr);
            m_simulatorDock->hide();
            m_simulatorDock->toggleViewAction()->setEnabled(false);
        }
        return;
    }
    if (!m_simulatorDock) {
        m_simulatorDock = new SimulatorDock(this);
        addDockWidget(Qt::BottomDockWidgetArea, m_simulatorDock);
        // A tab beside the packet log: the pages above keep their height.
        tabifyDockWidget(m_packetLog, m_simulatorDock);
        // The group's height holds the dock's tabs under it as well.
        resizeDocks({m_simulatorDock},
                    {m_simulatorDock->startingHeight() + dockTabBarHeight(m_simulatorDock)},
                    Qt::Vertical);
        m_viewMenu->addAction(m_simulatorDock->toggleViewAction());
        connect(m_simulatorDock, &SimulatorDock::message, this,
                [this](const QString &text) { statusBar()->showMessage(text, kStatusMessageMs); });
    }
    m_simulatorDock->setSimulator(simulator);
    m_simulatorDock->toggleViewAction()->setEnabled(true);
    m_simulatorDock->show();
    m_simulatorDock->raise();
}

void MainWindow::showProtocol(bool feetech)
{
    // The welcome page stays while nothing is open; the workspace shows once a port opens.
    if (m_pages->currentWidget() != m_welcome)
        m_pages->setCurrentWidget(feetech ? static_cast<QWidget *>(m_feetechWorkspace)
                                          : static_cast<QWidget *>(m_ptkWorkspace));
    for (QAction *action : std::as_const(m_ptkActions))
        action->setEnabled(!feetech);
    m_pollRate->setVisible(!feetech);
    updateFeetechBusActions();
}

void MainWindow::updateFeetechBusActions()
{
    m_allTorqueOff->setEnabled(m_connection->isFeetechActive() && m_feetech->link()->isConnected());
    m_shareBus->setEnabled(m_connection->isFeetechActive() && m_feetech->link()->isConnected());
}

void MainWindow::connectToPort(const QString &port)
{
    m_connectionBar->setPort(port);
    connectRequested();
}

void MainWindow::connectRequested()
{
    m_problem->hide();
    const QString port = m_connectionBar->port();
    if (const auto spoken = ConnectionController::simulatedProtocol(port)) {
        // A simulated servo speaks one protocol: the bar shows it, at its usual rate. A demo is
        // no connection to remember, and the protocol chosen for real ports comes back.
        if (!m_protocolBeforeSimulated)
            m_protocolBeforeSimulated = m_connectionBar->protocol();
        m_connectionBar->setProtocol(*spoken);
    } else if (!port.isEmpty()) {
        m_memory->rememberConnection();
    }
    ConnectionController::Request request;
    request.port = port;
    request.protocol = m_connectionBar->protocol();
    request.baud = m_connectionBar->baud();
    request.echo = m_connectionBar->echoMode();
    m_connection->connectTo(request);
}

void MainWindow::onStatusChanged(const seriallink::ConnectionStatus &status)
{
    using seriallink::ConnectionState;
    const QString portShown = m_connection->portShown();
    const bool feetechActive = m_connection->isFeetechActive();
    QString text;
    switch (status.state) {
    case ConnectionState::Disconnected:
        text = tr("Not connected");
        break;
    case ConnectionState::Connecting:
        text = tr("Connecting to %1…").arg(portShown);
        break;
    case ConnectionState::Connected:
        text = feetechActive ? tr("Open: %1").arg(portShown)
                             : tr("Connected: %1 at %2 baud").arg(portShown).arg(status.baud);
        break;
    case ConnectionState::NoReply:
        text = tr("No reply on %1").arg(portShown);
        break;
    case ConnectionState::Lost:
        text = tr("Disconnected: %1 went away, waiting for it to return").arg(portShown);
        break;
    }
    m_connectionState->setText(text);
    m_connectionState->setToolTip(status.message);
    m_connectionState->setStyleSheet(
        QStringLiteral("QLabel { color: %1; font-weight: 600; }").arg(stateColour(status.state)));
    const bool active = status.state != ConnectionState::Disconnected;
    m_connectionBar->setSessionActive(active);
    const bool nothingOpen = m_ptk->status().state == ConnectionState::Disconnected
        && m_feetech->link()->status().state == ConnectionState::Disconnected;
    if (nothingOpen)
        m_pages->setCurrentWidget(m_welcome);
    else if (m_pages->currentWidget() == m_welcome)
        m_pages->setCurrentWidget(feetechActive ? static_cast<QWidget *>(m_feetechWorkspace)
                                                : static_cast<QWidget *>(m_ptkWorkspace));
    // One line of explanation in the banner; never a dialog, so an unplugged cable cannot
    // bury the user in message boxes.
    if (status.state == ConnectionState::Connected || status.state == ConnectionState::Connecting)
        m_problem->hide();
    else if (!status.message.isEmpty())
        showProblem(status.message);
}

void MainWindow::onCountersChanged(const seriallink::LinkCounters &counters)
{
    m_lastCounters = counters;
    QString text = tr("sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · "
                      "discarded %6 B")
                       .arg(counters.framesSent)
                       .arg(counters.repliesOk)
                       .arg(counters.checksumErrors)
                       .arg(counters.timeouts)
                       .arg(counters.retries)
                       .arg(counters.discardedBytes);
    if (m_streamMissed > 0)
        text += tr(" · stream missed %1").arg(m_streamMissed);
    m_counters->setText(text);
}

void MainWindow::updatePollRate()
{
    if (!m_ptk->isConnected()) {
        m_pollRate->clear();
        return;
    }
    m_pollRate->setText(tr("%1 queries/s").arg(m_ptk->pollRate(), 0, 'f', 1));
}

void MainWindow::showProblem(const QString &message)
{
    ++m_problemsShown;
    m_problem->setText(message);
    m_problem->show();
}

void MainWindow::showWizard(QDialog *wizard)
{
    followWizard(wizard);
    wizard->show();
    wizard->raise();
    wizard->activateWindow();
}

void MainWindow::followWizard(QDialog *wizard)
{
    static const char *const kProblemsAtOpen = "servobenchProblemsAtOpen";
    if (wizard->isVisible())
        return; // open already: what it showed since it opened still goes when it closes
    const bool followed = wizard->property(kProblemsAtOpen).isValid();
    wizard->setProperty(kProblemsAtOpen, m_problemsShown);
    if (followed)
        return;
    // finished comes from every way a dialog closes: Close, Cancel, Escape, the title bar.
    connect(wizard, &QDialog::finished, this, [this, wizard] {
        if (m_problemsShown > wizard->property(kProblemsAtOpen).toULongLong())
            m_problem->hide();
    });
}

void MainWindow::chooseProfileToSave()
{
    if (m_connection->isFeetechActive()) {
        m_feetechWorkspace->chooseProfileToSave();
        return;
    }
    m_ptkWorkspace->chooseProfileToSave();
}

bool MainWindow::saveProfile(const QString &path)
{
    return m_ptkWorkspace->saveProfile(path);
}

void MainWindow::chooseProfileToLoad()
{
    if (m_connection->isFeetechActive()) {
        m_feetechWorkspace->chooseProfileToLoad();
        return;
    }
    m_ptkWorkspace->chooseProfileToLoad();
}

void MainWindow::loadProfile(const QString &path)
{
    m_ptkWorkspace->loadProfile(path);
}

void MainWindow::restart()
{
    // Closed as Quit closes it (unapplied changes are asked about), then started again with
    // the same arguments.
    if (close())
        QProcess::startDetached(QCoreApplication::applicationFilePath(),
                                QCoreApplication::arguments().mid(1));
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    bool edits = m_ptk->model()->hasEdits();
    for (int i = 0; i < m_feetech->servos()->count(); ++i)
        edits = edits || m_feetech->servos()->parameters(i)->hasEdits();
    if (edits) {
        const auto answer = QMessageBox::question(
            this, tr("Unapplied changes"),
            tr("Some changes have not been written to the servos. Quit anyway?"),
            QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard) {
            event->ignore();
            return;
        }
    }
    m_memory->rememberLayout();
    event->accept();
}

void MainWindow::followConnection()
{
    ConnectionController *connection = m_connection.get();
    connect(connection, &ConnectionController::problem, this, &MainWindow::showProblem);
    connect(connection, &ConnectionController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, kStatusMessageMs); });
    connect(connection, &ConnectionController::sessionActiveChanged, m_connectionBar,
            &ConnectionBar::setSessionActive);
    connect(connection, &ConnectionController::detected, m_connectionBar,
            &ConnectionBar::showDetected);
    connect(connection, &ConnectionController::feetechActiveChanged, this,
            &MainWindow::showProtocol);
    connect(connection, &ConnectionController::simulatorChanged, this, &MainWindow::showSimulator);
    connect(connection, &ConnectionController::feetechPortNamed, m_feetechWorkspace,
            &FeetechWorkspace::setPortName);
    connect(connection, &ConnectionController::scanWanted, m_feetechWorkspace,
            &FeetechWorkspace::startScan);
    connect(connection, &ConnectionController::detectionStarted, this, &MainWindow::showDetection);
    connect(connection, &ConnectionController::detectionFinished, this, &MainWindow::endDetection);

    connection->setExpectedServos([this](const QString &port) { return m_doctor->expected(port); });
    connection->setDoctorShown([this] { return m_doctor->isVisible(); });
    connection->setLastScanOptions([this] { return m_feetechWorkspace->scanOptions(); });
    connect(connection, &ConnectionController::doctorChecking, m_doctor,
            &DoctorPanel::showChecking);
    connect(connection, &ConnectionController::doctorFindings, m_doctor,
            &DoctorPanel::showFindings);
    connect(connection, &ConnectionController::doctorWanted, this, &MainWindow::openDoctor);
    connect(m_doctor, &DoctorPanel::rescanRequested, connection,
            &ConnectionController::rescanForDoctor);
}

void MainWindow::createDoctor()
{
    m_doctor = new DoctorPanel(m_feetech.get(), this);
    addDockWidget(Qt::BottomDockWidgetArea, m_doctor);
    // A tab beside the packet log however it opens (View > Doctor too): the pages above keep
    // their height, and the window its least height.
    tabifyDockWidget(m_packetLog, m_doctor);
    m_doctor->hide();
    m_viewMenu->addAction(m_doctor->toggleViewAction());
    // Opened from the View menu, its tab comes to the front.
    connect(m_doctor->toggleViewAction(), &QAction::triggered, m_doctor, [this](bool shown) {
        if (shown)
            m_doctor->raise();
    });
    connect(m_doctor, &DoctorPanel::problem, this, &MainWindow::showProblem);
    connect(m_doctor, &DoctorPanel::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, kDoctorMessageMs); });
}

void MainWindow::openDoctor()
{
    if (!tabifiedDockWidgets(m_packetLog).contains(m_doctor))
        tabifyDockWidget(m_packetLog, m_doctor); // the pages above keep their height
    m_doctor->show();
    m_doctor->raise();
}

void MainWindow::showDetection(const QString &port)
{
    m_connectionState->setText(tr("Looking for servos on %1…").arg(port));
    m_probeProgress = new QProgressDialog(tr("Looking for servos on %1…").arg(port), tr("Cancel"),
                                          0, feetech::PortProbe::stepCount(), this);
    m_probeProgress->setObjectName(QStringLiteral("probeProgress"));
    m_probeProgress->setWindowTitle(tr("Auto-detection"));
    // Not modal: the window stays usable (and its Disconnect stops the probe too).
    m_probeProgress->setWindowModality(Qt::NonModal);
    m_probeProgress->setMinimumDuration(0);
    m_probeProgress->setAutoClose(false);
    m_probeProgress->setAutoReset(false);
    m_probeProgress->setValue(0);
    connect(m_probeProgress, &QProgressDialog::canceled, m_connection.get(),
            &ConnectionController::cancelDetection);
    connect(m_connection->portProbe(), &feetech::PortProbe::progress, m_probeProgress,
            [this](int done, int, const QString &step) {
                m_probeProgress->setValue(done);
                if (!step.isEmpty())
                    m_probeProgress->setLabelText(step);
            });
}

void MainWindow::endDetection()
{
    if (m_probeProgress) {
        m_probeProgress->deleteLater();
        m_probeProgress = nullptr;
    }
    m_connectionState->setText(tr("Not connected"));
}

void MainWindow::fillRecentProfiles(QMenu *menu)
{
    menu->clear();
    const QStringList files = recentfiles::list(recentfiles::Kind::Profile);
    for (const QString &path : files) {
        menu->addAction(QDir::toNativeSeparators(path), this, [this, path] {
            recentfiles::add(recentfiles::Kind::Profile, path);
            if (m_connection->isFeetechActive())
                m_feetechWorkspace->loadProfile(path);
            else
                m_ptkWorkspace->loadProfile(path);
        });
    }
    if (files.isEmpty())
        menu->addAction(tr("No profile opened or saved yet"))->setEnabled(false);
}

void MainWindow::resetLayout()
{
    m_memory->resetLayout();
    m_packetLog->show();
    m_connectionBar->show();
}
