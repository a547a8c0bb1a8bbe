// ServoBench's main window: wires the PTK client to the page, the packet log and the status bar.
#include "mainwindow.h"

#include "connectionbar.h"
#include "link/packetlogmodel.h"
#include "packetlogdock.h"
#include "profile/profile.h"
#include "profilediffdialog.h"
#include "ptk/ptkclient.h"
#include "ptkpage.h"
#include "sim/demoservos.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>
#include <QVBoxLayout>

namespace {

const QString kPtkFamily = QStringLiteral("ptk");
constexpr int kRateRefreshMs = 500;
constexpr int kStatusMessageMs = 8000;

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

} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_ptk(std::make_unique<ptk::Client>())
{
    setWindowTitle(tr("ServoBench"));
    setObjectName(QStringLiteral("mainWindow"));
    resize(1180, 820);

    m_connectionBar = new ConnectionBar(this);
    addToolBar(Qt::TopToolBarArea, m_connectionBar);
    connect(m_connectionBar, &ConnectionBar::connectRequested, this, &MainWindow::connectRequested);
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this,
            &MainWindow::disconnectRequested);

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

    m_ptkPage = new PtkPage(m_ptk->model(), central);
    layout->addWidget(m_ptkPage);
    setCentralWidget(central);

    m_packetLog = new PacketLogDock(this);
    addDockWidget(Qt::BottomDockWidgetArea, m_packetLog);

    createMenus();

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

    connect(m_ptk.get(), &ptk::Client::statusChanged, this, &MainWindow::onStatusChanged);
    connect(m_ptk.get(), &ptk::Client::countersChanged, this, &MainWindow::onCountersChanged);
    connect(m_ptk.get(), &ptk::Client::packetLogged, m_packetLog, &PacketLogDock::append);
    connect(m_ptk.get(), &ptk::Client::applyProgress, m_ptkPage, &PtkPage::setProgress);
    connect(m_ptk.get(), &ptk::Client::applyFinished, this, &MainWindow::onApplyFinished);
    connect(m_ptk.get(), &ptk::Client::readFinished, this, [this](bool ok, const QString &why) {
        if (ok)
            statusBar()->showMessage(tr("Read all parameters"), kStatusMessageMs);
        else
            showProblem(tr("Read failed: %1").arg(why));
    });
    connect(m_ptkPage, &PtkPage::readRequested, this, [this] {
        m_problem->hide();
        m_ptk->readAll();
    });
    connect(m_ptkPage, &PtkPage::applyRequested, this, &MainWindow::apply);
    connect(m_ptkPage, &PtkPage::saveProfileRequested, this, &MainWindow::chooseProfileToSave);
    connect(m_ptkPage, &PtkPage::loadProfileRequested, this, &MainWindow::chooseProfileToLoad);

    m_rateTimer = new QTimer(this);
    m_rateTimer->setInterval(kRateRefreshMs);
    connect(m_rateTimer, &QTimer::timeout, this, &MainWindow::updatePollRate);
    m_rateTimer->start();
    updatePollRate();
}

MainWindow::~MainWindow() = default;

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *load = file->addAction(tr("&Load profile…"), this, &MainWindow::chooseProfileToLoad);
    load->setShortcut(QKeySequence::Open);
    QAction *save = file->addAction(tr("&Save profile…"), this, &MainWindow::chooseProfileToSave);
    save->setShortcut(QKeySequence::Save);
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
    QAction *fast = link->addAction(tr("&Fast polling (queries back to back)"));
    fast->setObjectName(QStringLiteral("fastPollingAction"));
    fast->setCheckable(true);
    connect(fast, &QAction::toggled, this, [this](bool on) {
        m_ptk->setPollInterval(int(ptk::SessionTiming().pollInterval.count()), on);
    });

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_packetLog->toggleViewAction());
    view->addAction(m_connectionBar->toggleViewAction());

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *about = help->addAction(tr("&About ServoBench"), this, &MainWindow::showAbout);
    about->setObjectName(QStringLiteral("aboutAction"));
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About ServoBench"),
                       tr("<p><b>ServoBench %1</b></p>"
                          "<p>Programs and monitors PTK RC servos and Feetech serial-bus "
                          "servos on Linux, Windows and macOS.</p>")
                           .arg(QCoreApplication::applicationVersion()));
}

void MainWindow::startDemo()
{
    m_connectionBar->setPort(ConnectionBar::kSimulatedPtkPort);
    connectRequested();
}

void MainWindow::connectToPort(const QString &port)
{
    m_connectionBar->setPort(port);
    connectRequested();
}

void MainWindow::connectRequested()
{
    m_problem->hide();
    QString port = m_connectionBar->port();
    m_portShown = port;
    if (port.isEmpty()) {
        showProblem(tr("Choose a serial port first."));
        return;
    }
    if (port == ConnectionBar::kSimulatedPtkPort) {
        if (!m_demo)
            m_demo = std::make_unique<sim::DemoServos>();
        QString error;
        port = m_demo->ptkPort(&error);
        if (port.isEmpty()) {
            showProblem(tr("The simulated servo could not start: %1").arg(error));
            return;
        }
        m_portShown = tr("simulated PTK servo");
    }
    const qint32 baud = m_connectionBar->baud();
    if (baud <= 0) {
        showProblem(tr("Enter a baud rate."));
        return;
    }
    m_connectionBar->setSessionActive(true);
    m_ptk->connectTo(port, baud, m_connectionBar->echoMode());
}

void MainWindow::disconnectRequested()
{
    m_ptk->disconnectFrom();
}

void MainWindow::onStatusChanged(const seriallink::ConnectionStatus &status)
{
    using seriallink::ConnectionState;
    QString text;
    switch (status.state) {
    case ConnectionState::Disconnected:
        text = tr("Not connected");
        break;
    case ConnectionState::Connecting:
        text = tr("Connecting to %1…").arg(m_portShown);
        break;
    case ConnectionState::Connected:
        text = tr("Connected: %1 at %2 baud").arg(m_portShown).arg(status.baud);
        break;
    case ConnectionState::NoReply:
        text = tr("No reply on %1").arg(m_portShown);
        break;
    case ConnectionState::Lost:
        text = tr("Disconnected: %1 went away, waiting for it to return").arg(m_portShown);
        break;
    }
    m_connectionState->setText(text);
    m_connectionState->setToolTip(status.message);
    m_connectionState->setStyleSheet(
        QStringLiteral("QLabel { color: %1; font-weight: 600; }").arg(stateColour(status.state)));
    const bool active = status.state != ConnectionState::Disconnected;
    m_connectionBar->setSessionActive(active);
    m_ptkPage->setLinkReady(status.state == ConnectionState::Connected);
    // One line of explanation in the banner; never a dialog, so an unplugged cable cannot
    // bury the user in message boxes.
    if (status.state == ConnectionState::Connected || status.state == ConnectionState::Connecting)
        m_problem->hide();
    else if (!status.message.isEmpty())
        showProblem(status.message);
    if (!m_ptk->isBusy() && m_ptkPage->isBusy())
        m_ptkPage->setBusy(false);
}

void MainWindow::onCountersChanged(const seriallink::LinkCounters &counters)
{
    m_counters->setText(tr("sent %1 · ok %2 · checksum errors %3 · timeouts %4 · retries %5 · "
                           "discarded %6 B")
                            .arg(counters.framesSent)
                            .arg(counters.repliesOk)
                            .arg(counters.checksumErrors)
                            .arg(counters.timeouts)
                            .arg(counters.retries)
                            .arg(counters.discardedBytes));
}

void MainWindow::updatePollRate()
{
    if (!m_ptk->isConnected()) {
        m_pollRate->clear();
        return;
    }
    m_pollRate->setText(tr("%1 queries/s").arg(m_ptk->pollRate(), 0, 'f', 1));
}

void MainWindow::apply()
{
    m_problem->hide();
    QString error;
    if (!m_ptk->apply(&error)) {
        showProblem(tr("Nothing was written: %1").arg(error));
        return;
    }
    m_ptkPage->setBusy(true, tr("Writing N1…N12, then reading back…"));
}

void MainWindow::onApplyFinished(bool ok, const QString &message)
{
    m_ptkPage->setBusy(false);
    bool mismatch = false;
    for (const model::Definition &definition : m_ptk->model()->definitions())
        mismatch = mismatch || m_ptk->model()->state(definition.key) == model::State::Mismatch;
    if (!ok)
        showProblem(message);
    else if (mismatch)
        showProblem(tr("The servo did not take every value: the fields marked Mismatch hold "
                       "something else than was written."));
    else
        statusBar()->showMessage(tr("Written and verified"), kStatusMessageMs);
}

void MainWindow::showProblem(const QString &message)
{
    m_problem->setText(message);
    m_problem->show();
}

void MainWindow::chooseProfileToSave()
{
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getSaveFileName(this, tr("Save profile"),
                                                      folder + QStringLiteral("/ptk-servo.json"),
                                                      tr("ServoBench profiles (*.json)"));
    if (!path.isEmpty())
        saveProfile(path);
}

bool MainWindow::saveProfile(const QString &path)
{
    // What the form shows: the servo's values with any edits not yet applied.
    const profile::Profile saved = profile::fromModel(*m_ptk->model(), kPtkFamily, {}, true);
    if (saved.values.size() != m_ptk->model()->definitions().size()) {
        showProblem(tr("Read the servo before saving a profile: not every value is known."));
        return false;
    }
    QString error;
    if (!profile::save(path, saved, m_ptk->model()->definitions(), &error)) {
        showProblem(error);
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), kStatusMessageMs);
    return true;
}

void MainWindow::chooseProfileToLoad()
{
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getOpenFileName(this, tr("Load profile"), folder,
                                                      tr("ServoBench profiles (*.json)"));
    if (!path.isEmpty())
        loadProfile(path);
}

void MainWindow::loadProfile(const QString &path)
{
    if (m_ptk->isBusy()) {
        showProblem(tr("Wait for the running read or Apply to finish before loading a profile."));
        return;
    }
    QString error;
    const auto loaded = profile::load(path, kPtkFamily, m_ptk->model()->definitions(), &error);
    if (!loaded) {
        showProblem(tr("The profile was not loaded: %1").arg(error));
        return;
    }
    const QVector<profile::DiffRow> rows = profile::diff(*loaded, *m_ptk->model());
    if (rows.isEmpty()) {
        statusBar()->showMessage(tr("The servo already holds every value of this profile"),
                                 kStatusMessageMs);
        return;
    }
    ProfileDiffDialog dialog(QDir::toNativeSeparators(path), rows, *m_ptk->model(), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    for (const profile::DiffRow &row : rows)
        m_ptk->model()->edit(row.key, row.file);
    statusBar()->showMessage(tr("Profile loaded as edits: review them, then Apply"),
                             kStatusMessageMs);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_ptk->model()->hasEdits()) {
        const auto answer = QMessageBox::question(
            this, tr("Unapplied changes"),
            tr("Some changes have not been written to the servo. Quit anyway?"),
            QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Discard) {
            event->ignore();
            return;
        }
    }
    event->accept();
}
