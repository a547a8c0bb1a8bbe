// Feetech workspace: the servo tree beside the pages of the servo shown, the scan, Apply with
// its confirmations, the guided flows (change ID and baud, calibrate middle, factory reset) and
// profiles of the servo shown.
#include "feetechworkspace.h"

#include "busclient.h"
#include "controlpage.h"
#include "healthpage.h"
#include "jointtable.h"
#include "memorytablepage.h"
#include "monitorpage.h"
#include "palette.h"
#include "parameterpage.h"
#include "profileactions.h"
#include "robotactions.h"
#include "scandialog.h"
#include "scanmemory.h"
#include "servoparameters.h"
#include "servotree.h"
#include "sharedidcheck.h"
#include "unlockednotice.h"
#include "widgethelpers.h"

#include <QDateTime>
#include <QDir>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>

using widgethelpers::actionButton;

namespace {

// RAM rows of the shown servo are read again this often while the table is on screen.
constexpr int kLiveRefreshMs = 250;

QStringList settingsKeys()
{
    QStringList keys;
    for (const feetech::SettingsGroup &group : feetech::settingsGroups())
        keys += group.keys;
    return keys;
}

} // namespace

FeetechWorkspace::FeetechWorkspace(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("feetechWorkspace"));
    m_scanOptions = scanmemory::rememberedScanOptions();
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *splitter = new QSplitter(Qt::Horizontal, this);
    layout->addWidget(splitter);

    // ---- left: scan controls and the servo tree
    auto *left = new QWidget(splitter);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 6, 0);
    auto *scanRow = new QHBoxLayout;
    m_scan = actionButton(tr("Scan…"), "scanButton",
                          tr("Look for servos on the bus: choose IDs and baud rates"), left);
    m_cancelScan = actionButton(tr("Cancel"), "cancelScanButton", tr("Stop the scan"), left);
    m_cancelScan->hide();
    scanRow->addWidget(m_scan);
    scanRow->addWidget(m_cancelScan);
    scanRow->addStretch(1);
    leftLayout->addLayout(scanRow);
    m_scanProgress = new QProgressBar(left);
    m_scanProgress->setObjectName(QStringLiteral("scanProgress"));
    m_scanProgress->setFormat(tr("%v of %m IDs"));
    m_scanProgress->hide();
    leftLayout->addWidget(m_scanProgress);
    m_scanState = new QLabel(tr("Connect, then scan to find the servos."), left);
    m_scanState->setObjectName(QStringLiteral("scanState"));
    m_scanState->setWordWrap(true);
    m_scanState->setForegroundRole(QPalette::PlaceholderText);
    leftLayout->addWidget(m_scanState);
    m_tree = new ServoTree(client, left);
    leftLayout->addWidget(m_tree, 1);
    // The emergency stop stays in sight whatever page is open; Esc does the same everywhere.
    m_allTorqueOff = actionButton(tr("All torque off  (Esc)"), "allTorqueOffButton",
                                  tr("Switch the torque of every servo on the bus off at once, "
                                     "ahead of anything else (also: Esc, from any page)"),
                                  left);
    m_allTorqueOff->setMinimumHeight(m_allTorqueOff->sizeHint().height() * 2);
    QFont stopFont = m_allTorqueOff->font();
    stopFont.setBold(true);
    stopFont.setPointSizeF(stopFont.pointSizeF() * 1.2);
    m_allTorqueOff->setFont(stopFont);
    m_allTorqueOff->setStyleSheet(
        QStringLiteral("QPushButton { background-color: #c62828; color: white; border: 1px solid "
                       "#8e0000; border-radius: 4px; padding: 4px 12px; }"
                       "QPushButton:hover { background-color: #d84343; }"
                       "QPushButton:pressed { background-color: #8e0000; }"
                       "QPushButton:disabled { background-color: #d9a3a3; color: #f5eaea; }"));
    leftLayout->addWidget(m_allTorqueOff);
    splitter->addWidget(left);

    // ---- right: the selected servo
    auto *right = new QWidget(splitter);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(6, 0, 0, 0);
    m_header = new QLabel(right);
    m_header->setObjectName(QStringLiteral("servoHeader"));
    m_header->setWordWrap(true);
    m_header->setTextInteractionFlags(Qt::TextSelectableByMouse);
    rightLayout->addWidget(m_header);
    m_unlocked = new UnlockedNotice(client, right);
    connect(m_unlocked, &UnlockedNotice::problem, this, &FeetechWorkspace::problem);
    rightLayout->addWidget(m_unlocked);

    auto *actions = new QHBoxLayout;
    m_changeId = actionButton(tr("Change ID…"), "changeIdButton",
                              tr("Give the servo another ID; an ID in use is refused"), right);
    m_changeBaud =
        actionButton(tr("Change baud rate…"), "changeBaudButton",
                     tr("Move the servo to another baud rate and follow it there"), right);
    m_calibrate = actionButton(tr("Calibrate middle…"), "calibrateButton",
                               tr("Make the horn's present position the middle (2048)"), right);
    m_factoryReset = actionButton(tr("Factory reset…"), "factoryResetButton",
                                  tr("Restore factory values (the ID is kept), after saving a "
                                     "backup profile"),
                                  right);
    m_reboot =
        actionButton(tr("Reboot"), "rebootButton",
                     tr("Torque off, restart the servo and wait until it answers again"), right);
    m_clearStatus = actionButton(tr("Clear status"), "clearStatusButton",
                                 tr("Reset the servo's error status (instruction 0x0A)"), right);
    for (QPushButton *button :
         {m_changeId, m_changeBaud, m_calibrate, m_factoryReset, m_reboot, m_clearStatus})
        actions->addWidget(button);
    actions->addStretch(1);
    rightLayout->addLayout(actions);
    m_verified = new QLabel(right);
    m_verified->setObjectName(QStringLiteral("verifiedMark"));
    m_verified->setWordWrap(true);
    m_verified->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_verified->hide();
    rightLayout->addWidget(m_verified);

    m_tabs = new QTabWidget(right);
    m_tabs->setObjectName(QStringLiteral("servoTabs"));
    ParameterPage::Options settingsOptions;
    settingsOptions.objectName = QStringLiteral("feetechSettingsPage");
    settingsOptions.keys = settingsKeys();
    settingsOptions.columns = 1; // beside the servo tree there is room for one
    settingsOptions.intro =
        tr("The settings changed most, in real units. <b>EEPROM</b> values are written with the "
           "lock opened and closed again and survive power-off. Changing the ID or the baud rate "
           "asks first, then follows the servo.");
    settingsOptions.emptyText = tr("No servo chosen. Scan the bus (Scan… at the top left), then "
                                   "choose a servo in the tree: its settings show here.");
    m_settings = new ParameterPage(nullptr, settingsOptions, m_tabs);
    m_tabs->addTab(m_settings, tr("Settings"));

    m_memory = new MemoryTablePage(m_tabs);
    m_tabs->addTab(m_memory, tr("Memory table"));
    m_control = new ControlPage(m_client, m_tabs);
    m_tabs->addTab(m_control, tr("Control"));
    m_monitor = new MonitorPage(m_client, m_tabs);
    m_tabs->addTab(m_monitor, tr("Monitor"));
    m_joints = new JointTable(m_client, m_tabs);
    m_tabs->addTab(m_joints, tr("Joints"));
    m_health = new HealthPage(m_client, m_tabs);
    m_tabs->addTab(m_health, tr("Health"));
    connect(m_health, &HealthPage::problem, this, &FeetechWorkspace::problem);
    connect(m_health, &HealthPage::message, this, &FeetechWorkspace::message);
    rightLayout->addWidget(m_tabs, 1);
    splitter->addWidget(right);
    splitter->setStretchFactor(0, 0);
    splitter->setStretchFactor(1, 1);
    splitter->setSizes({345, 835});

    m_liveTimer = new QTimer(this);
    m_liveTimer->setInterval(kLiveRefreshMs);
    connect(m_liveTimer, &QTimer::timeout, this, &FeetechWorkspace::refreshLive);
    m_liveTimer->start();

    connect(m_scan, &QPushButton::clicked, this, &FeetechWorkspace::openScanDialog);
    connect(m_cancelScan, &QPushButton::clicked, m_client, &feetech::BusClient::cancelScan);
    connect(m_allTorqueOff, &QPushButton::clicked, m_client, &feetech::BusClient::allTorqueOff);
    connect(m_tree, &ServoTree::servoChosen, this, &FeetechWorkspace::showChosenServo);
    connect(m_changeId, &QPushButton::clicked, this, &FeetechWorkspace::changeId);
    connect(m_changeBaud, &QPushButton::clicked, this, &FeetechWorkspace::changeBaud);
    connect(m_calibrate, &QPushButton::clicked, this, &FeetechWorkspace::calibrateMiddle);
    connect(m_factoryReset, &QPushButton::clicked, this, &FeetechWorkspace::factoryReset);
    connect(m_reboot, &QPushButton::clicked, this,
            [this] { run(&feetech::ServoCommands::reboot, tr("Restarting the servo…")); });
    connect(m_clearStatus, &QPushButton::clicked, this,
            [this] { run(&feetech::ServoCommands::clearStatus, tr("Clearing the status…")); });
    connect(m_memory, &MemoryTablePage::problem, this, &FeetechWorkspace::problem);

    const auto readCurrent = [this] {
        if (currentIndex() >= 0)
            m_client->readServo(currentIndex());
    };
    connect(m_settings, &ParameterPage::readRequested, this, readCurrent);
    connect(m_memory, &MemoryTablePage::readRequested, this, readCurrent);
    connect(m_settings, &ParameterPage::applyRequested, this, &FeetechWorkspace::apply);
    connect(m_memory, &MemoryTablePage::applyRequested, this, &FeetechWorkspace::apply);
    connect(m_memory, &MemoryTablePage::revertRequested, this, [this] {
        if (auto *parameters = m_client->servos()->parameters(currentIndex()))
            parameters->revertAll();
    });
    connect(m_settings, &ParameterPage::saveProfileRequested, this,
            &FeetechWorkspace::chooseProfileToSave);
    connect(m_settings, &ParameterPage::loadProfileRequested, this,
            &FeetechWorkspace::chooseProfileToLoad);

    connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
            &FeetechWorkspace::rebuildTree);
    connect(m_client->servos(), &feetech::ServoList::servoUpdated, this, [this](int index) {
        if (index == currentIndex())
            updateHeader();
        updateActions();
    });
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        updateActions();
        updateHeader();
        showScanHint();
    });
    // An unplug empties the list after the link has said so: a scan's outcome ("Scan complete:
    // 6 servo(s) found.") must not outlive the servos it found.
    connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
            &FeetechWorkspace::showScanHint);
    connect(m_client, &feetech::BusClient::busyChanged, this, [this](bool busy) {
        if (!busy || !m_client->isScanning())
            m_settings->setBusy(busy && !m_client->isScanning(), tr("Working…"));
        updateActions();
    });
    // The status bar tells the outcome of every operation, whoever asked for it; the page
    // shows how far an apply chain, a health check or a settings check or fix has got while it
    // is busy.
    connect(m_client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        connect(reply, &feetech::OperationReply::finished, this,
                &FeetechWorkspace::onOperationFinished);
        // The mark speaks of the last change; the next one takes it away until it is verified.
        if (changesServo(reply->operation()))
            m_verified->hide();
        if (reply->operation() == feetech::Operation::Write
            || reply->operation() == feetech::Operation::HealthCheck
            || reply->operation() == feetech::Operation::CheckSettings
            || reply->operation() == feetech::Operation::FixSettings)
            connect(reply, &feetech::OperationReply::progress, m_settings,
                    [this](const feetech::OperationProgress &progress) {
                        m_settings->setProgress(progress.done, progress.total);
                    });
    });
    connect(m_client, &feetech::BusClient::scanProgress, this,
            [this](int done, int total, qint32 baud) {
                m_scanProgress->setRange(0, std::max(total, 1));
                m_scanProgress->setValue(done);
                m_scanState->setText(tr("Scanning at %1…").arg(feetech::baudText(baud)));
            });
    connect(m_client, &feetech::BusClient::scanFinished, this,
            [this](bool completed, const QString &text) {
                m_scanProgress->hide();
                m_cancelScan->hide();
                m_scan->show();
                m_scanOutcome = text;
                m_scanState->setText(text);
                if (!completed)
                    emit problem(text);
                if (!m_current && m_client->servos()->count() > 0)
                    selectServo(m_client->servos()->at(0).info.address());
                updateActions();
            });
    m_robot = new RobotActions(m_client, this);
    connect(m_robot, &RobotActions::problem, this, &FeetechWorkspace::problem);
    connect(m_robot, &RobotActions::message, this, &FeetechWorkspace::message);
    connect(m_tree, &QWidget::customContextMenuRequested, this, [this](const QPoint &at) {
        QMenu menu(this);
        m_robot->addTo(&menu);
        menu.exec(m_tree->viewport()->mapToGlobal(at));
    });
    rebuildTree();
    showServo();
}

int FeetechWorkspace::currentIndex() const
{
    return m_current ? m_client->servos()->indexOf(*m_current) : -1;
}

void FeetechWorkspace::setPortName(const QString &name)
{
    m_tree->setPortName(name);
    rebuildTree();
}

void FeetechWorkspace::selectServo(const feetech::ServoAddress &servo)
{
    m_current = servo;
    {
        const QSignalBlocker quiet(m_tree);
        m_tree->clearSelection(); // this one servo, not those selected before
    }
    rebuildTree();
    showServo();
    readIfNew();
}

void FeetechWorkspace::readIfNew()
{
    // Once, when a servo is chosen: a servo that cannot be read must not be asked forever, and
    // a shared ID, whose answers collide, is not asked at all (Read still asks).
    const int index = currentIndex();
    if (index >= 0 && !m_client->servos()->at(index).read
        && !m_client->servos()->at(index).info.sharedId && !m_client->isBusy())
        m_client->readServo(index);
}

void FeetechWorkspace::showScanHint()
{
    if (m_client->isScanning())
        return;
    const bool listed = m_client->servos()->count() > 0;
    if (!m_client->link()->isConnected())
        m_scanState->setText(listed ? tr("Not connected: the servos listed are those of the last "
                                         "scan. Connect, then scan again.")
                                    : tr("Connect, then scan to find the servos."));
    else if (!listed)
        m_scanState->setText(tr("Press Scan… to find the servos on the bus."));
    else
        m_scanState->setText(m_scanOutcome);
}

void FeetechWorkspace::rebuildTree()
{
    m_tree->rebuild(m_current);
    updateActions();
}

void FeetechWorkspace::showChosenServo(const feetech::ServoAddress &servo)
{
    m_current = servo;
    showServo();
    readIfNew();
}

void FeetechWorkspace::showServo()
{
    const int index = currentIndex();
    if (m_control->servo() != index)
        m_control->setServo(index);
    m_unlocked->showServo(index);
    model::ParameterModel *parameters = m_client->servos()->parameters(index);
    if (m_settings->parameterModel() != parameters) {
        if (m_settings->parameterModel())
            disconnect(m_settings->parameterModel(), nullptr, this, nullptr);
        m_settings->setModel(parameters);
        if (parameters) // Apply and Revert under the table follow the edits
            connect(parameters, &model::ParameterModel::parameterChanged, this,
                    &FeetechWorkspace::updateActions);
    }
    m_memory->showServo(*m_client, index);
    if (!m_current || *m_current != m_verifiedServo)
        m_verified->hide(); // it spoke of another servo
    updateHeader();
    updateActions();
}

QString FeetechWorkspace::servoTitle() const
{
    const int index = currentIndex();
    if (index < 0)
        return {};
    const feetech::ServoInfo &info = m_client->servos()->at(index).info;
    return tr("servo %1 (%2)").arg(info.id).arg(info.model.name);
}

void FeetechWorkspace::updateHeader()
{
    const int index = currentIndex();
    m_memory->setEmptyStateShown(index < 0);
    if (index < 0) {
        m_header->setText(m_client->servos()->count() > 0 ? tr("Choose a servo in the tree.")
                              : m_client->link()->isConnected()
                              ? tr("No servo yet: scan the bus.")
                              : tr("No servo yet: connect to the bus and scan."));
        return;
    }
    const feetech::Servo &servo = m_client->servos()->at(index);
    const feetech::ServoInfo &info = servo.info;
    const QString family =
        info.model.family ? feetech::familyName(*info.model.family) : tr("unknown family");
    QString status = tr("status not read yet");
    if (servo.statusByte) {
        const QStringList bits = feetech::statusBitNames(*servo.statusByte);
        status = bits.isEmpty() ? tr("status OK")
                                : tr("<span style='color:#b3261e'>status: %1</span>")
                                      .arg(bits.join(QStringLiteral(", ")).toHtmlEscaped());
    }
    QString text = tr("<b>ID %1 · %2</b> &nbsp; model %3 · %4 family · firmware %5 · %6 · %7")
                       .arg(info.id)
                       .arg(info.model.name.toHtmlEscaped())
                       .arg(info.modelNumber())
                       .arg(family)
                       .arg(info.firmware())
                       .arg(feetech::baudText(info.baud))
                       .arg(status);
    if (!info.hasTable())
        text += QStringLiteral("<br>")
            + tr("No register table is known for this model, so nothing is guessed: the Memory "
                 "table shows its raw bytes, read-only.");
    if (info.sharedId)
        text += QStringLiteral("<br>") + feetech::sharedIdRefusal(info.id).toHtmlEscaped();
    m_header->setText(text);
}

void FeetechWorkspace::updateActions()
{
    const int index = currentIndex();
    const bool connected = m_client->link()->isConnected();
    const bool idle = !m_client->isBusy();
    // Two servos at one ID would both take a write: nothing is sent to a shared ID.
    const bool shared = index >= 0 && m_client->servos()->at(index).info.sharedId;
    const bool known = index >= 0 && m_client->servos()->at(index).info.hasTable() && !shared;
    const bool ready = connected && idle && index >= 0;
    m_scan->setEnabled(connected && idle);
    m_allTorqueOff->setEnabled(connected); // never held back by work in progress
    m_changeId->setEnabled(ready && known);
    m_changeBaud->setEnabled(ready && known);
    const bool calibration = known
        && feetech::middleCalibration(m_client->servos()->at(index).info)
            != feetech::MiddleCalibration::Unsupported;
    m_calibrate->setEnabled(ready && calibration);
    m_calibrate->setToolTip(calibration || !known
                                ? tr("Make the horn's present position the middle (2048)")
                                : tr("SCS servos have no offset register: not available"));
    m_factoryReset->setEnabled(ready && known);
    m_reboot->setEnabled(ready && !shared);
    m_clearStatus->setEnabled(ready && !shared);
    m_settings->setLinkReady(ready && known);
    model::ParameterModel *parameters = m_client->servos()->parameters(index);
    const bool edits = parameters && parameters->hasEdits();
    m_memory->updateActions(ready, known, edits, idle, connected && idle && known);
}

void FeetechWorkspace::refreshLive()
{
    const int index = currentIndex();
    if (index < 0 || !m_memory->refreshesLive() || !isVisible()
        || m_tabs->currentWidget() != m_memory || !m_client->link()->isConnected()
        || m_client->isBusy() || !m_client->servos()->at(index).read)
        return;
    m_client->refreshRam(index);
}

void FeetechWorkspace::openScanDialog()
{
    ScanDialog dialog(m_scanOptions, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    scanmemory::rememberScanOptions(dialog.options());
    startScan(dialog.options());
}

void FeetechWorkspace::startScan(const feetech::ScanOptions &options)
{
    if (!m_client->link()->isConnected()) {
        emit problem(tr("Connect to the bus before scanning."));
        return;
    }
    if (m_client->share()->isActive()) {
        emit problem(feetech::Refusal(feetech::Refusal::Code::BusShared).describe());
        return;
    }
    m_scanOptions = options;
    m_current.reset();
    m_scan->hide();
    m_cancelScan->show();
    m_scanProgress->setValue(0);
    m_scanProgress->show();
    m_client->scan(options);
    showServo();
}

void FeetechWorkspace::apply()
{
    const int index = currentIndex();
    model::ParameterModel *parameters = m_client->servos()->parameters(index);
    if (!parameters)
        return;
    const auto newId = parameters->pendingValue(QStringLiteral("id"));
    const auto newBaud = parameters->pendingValue(QStringLiteral("baud_rate"));
    const feetech::ServoInfo info = m_client->servos()->at(index).info;
    if (newId || newBaud) {
        QStringList changes;
        if (newId)
            changes.append(tr("its ID from %1 to %2").arg(info.id).arg(*newId));
        if (newBaud)
            changes.append(tr("its baud rate from %1 to %2")
                               .arg(feetech::baudText(info.baud),
                                    feetech::baudText(feetech::baudForCode(int(*newBaud)))));
        const auto answer = QMessageBox::question(
            this, tr("Change how the servo is reached?"),
            tr("This changes %1.<br><br>ServoBench writes it to EEPROM with the lock opened "
               "and closed again, then finds the servo at its new address and confirms it "
               "there. Other programs and robot code must use the new address afterwards.")
                .arg(changes.join(tr(" and "))),
            QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Ok)
            return;
    }
    feetech::Refusal refusal;
    if (!m_client->applyAll(index, &refusal))
        emit problem(tr("Nothing was written: %1").arg(refusal.describe()));
}

void FeetechWorkspace::run(
    feetech::OperationReply *(feetech::ServoCommands::*operation)(int, feetech::Refusal *),
    const QString &what)
{
    feetech::Refusal refusal;
    if (!(m_client->commands()->*operation)(currentIndex(), &refusal))
        emit problem(refusal.describe());
    else
        emit message(what);
}

void FeetechWorkspace::changeId()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    const feetech::ServoInfo info = m_client->servos()->at(index).info;
    QStringList used;
    for (const int id : m_client->servos()->idsInUse())
        used.append(QString::number(id));
    bool ok = false;
    const int newId = QInputDialog::getInt(
        this, tr("Change ID"),
        tr("New ID for %1 (IDs found on this bus: %2).\nAn ID in use is refused.")
            .arg(servoTitle(), used.join(QStringLiteral(", "))),
        info.id, 0, feetech::kMaxServoId, 1, &ok);
    if (!ok || newId == info.id)
        return;
    if (m_client->servos()->idsInUse().contains(newId)) {
        emit problem(tr("ID %1 is already in use on this bus; nothing was written.").arg(newId));
        return;
    }
    feetech::Refusal refusal;
    if (!m_client->changeId(index, newId, &refusal))
        emit problem(refusal.describe());
}

void FeetechWorkspace::changeBaud()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    const feetech::ServoInfo info = m_client->servos()->at(index).info;
    QStringList rates;
    for (const qint32 rate : feetech::baudRates())
        rates.append(QString::number(rate));
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        this, tr("Change baud rate"),
        tr("New baud rate for %1 (now %2). ServoBench follows the servo to the new rate and "
           "confirms it there.")
            .arg(servoTitle(), feetech::baudText(info.baud)),
        rates, int(rates.indexOf(QString::number(info.baud))), false, &ok);
    if (!ok || chosen.toInt() == info.baud)
        return;
    feetech::Refusal refusal;
    if (!m_client->changeBaud(index, chosen.toInt(), &refusal))
        emit problem(refusal.describe());
}

void FeetechWorkspace::calibrateMiddle()
{
    const auto answer = QMessageBox::question(
        this, tr("Calibrate middle"),
        tr("The horn's present position becomes the middle (2048) of %1. Turn the horn to "
           "where the middle should be first; the new offset is stored in EEPROM.")
            .arg(servoTitle()),
        QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Ok)
        run(&feetech::ServoCommands::calibrateMiddle, tr("Calibrating the middle…"));
}

void FeetechWorkspace::factoryReset()
{
    const int index = currentIndex();
    if (index < 0)
        return;
    const feetech::ServoInfo info = m_client->servos()->at(index).info;
    // A backup first, always: a factory reset cannot be undone any other way.
    const QString suggested =
        QStringLiteral("servo-%1-backup-%2.json")
            .arg(info.id)
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss")));
    QMessageBox::information(this, tr("Factory reset"),
                             tr("First save a backup profile of %1; the reset only starts once "
                                "it is saved.")
                                 .arg(servoTitle()));
    const QString path = profileactions::chooseSavePath(this, suggested);
    if (path.isEmpty())
        return;
    if (!saveProfile(path, false)) // what the servo holds, not what is being edited
        return;
    const auto answer = QMessageBox::warning(
        this, tr("Factory reset"),
        tr("Backup saved to %1.<br><br>Restore the factory values of %2? Everything but the ID "
           "returns to what the servo left the factory with, possibly including its baud "
           "rate; ServoBench looks for it at every rate afterwards.")
            .arg(QDir::toNativeSeparators(path).toHtmlEscaped(), servoTitle()),
        QMessageBox::Reset | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer == QMessageBox::Reset)
        run(&feetech::ServoCommands::factoryReset, tr("Restoring factory values…"));
}

void FeetechWorkspace::onOperationFinished(const feetech::OperationResult &result)
{
    using feetech::Operation;
    if (result.control) {
        // Goal and torque writes come many a second: the pages show them; only a failure is
        // worth the status bar, and the servo list has not changed.
        if (!result.ok)
            emit problem(result.message);
        return;
    }
    if (result.ok && m_current
        && (result.operation == Operation::ChangeId || result.operation == Operation::ChangeBaud
            || result.operation == Operation::FactoryReset))
        m_current = result.servo.address();
    if (result.ok)
        emit message(result.message);
    else
        emit problem(result.message);
    // The status bar's message fades; what was written and read back stays said on the page.
    // Under the servo's header: what was written to one servo. The settings check's fixes
    // (several servos at once) say their outcome in their own rows.
    if (result.ok && result.final && changesServo(result.operation)
        && result.operation != Operation::FixSettings) {
        m_verified->setText(tr("✓ Verified: %1").arg(result.message));
        QPalette tinted = m_verified->palette();
        tinted.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Good, tinted));
        m_verified->setPalette(tinted);
        m_verified->show();
        m_verifiedServo = result.servo.address();
    }
    rebuildTree();
    showServo();
}

bool FeetechWorkspace::changesServo(feetech::Operation operation)
{
    // What writes a servo's memory and reads it back (an apply chain, the guided flows, the
    // settings check's fixes); a reboot or a reset confirms it answers, not what it holds.
    using feetech::Operation;
    return operation == Operation::Write || operation == Operation::ChangeId
        || operation == Operation::ChangeBaud || operation == Operation::CalibrateMiddle
        || operation == Operation::FixSettings || operation == Operation::LockEeprom;
}

void FeetechWorkspace::chooseProfileToSave()
{
    const int index = currentIndex();
    if (index < 0) {
        emit problem(tr("Choose a servo first."));
        return;
    }
    const QString path = profileactions::chooseSavePath(
        this, QStringLiteral("servo-%1.json").arg(m_client->servos()->at(index).info.id));
    if (!path.isEmpty() && saveProfile(path))
        emit message(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
}

bool FeetechWorkspace::saveProfile(const QString &path, bool withEdits)
{
    const int index = currentIndex();
    if (index < 0 || !m_client->servos()->at(index).info.hasTable()) {
        emit problem(tr("Only a servo of a known model can be saved as a profile."));
        return false;
    }
    const feetech::ServoInfo &info = m_client->servos()->at(index).info;
    util::FileError error;
    if (!profileactions::save(path, *m_client->servos()->parameters(index),
                              feetech::familyKey(*info.model.family), info.model.name,
                              feetech::profileDefinitions(info.table()), withEdits, &error)) {
        emit problem(error.describe());
        return false;
    }
    return true;
}

void FeetechWorkspace::chooseProfileToLoad()
{
    const QString path = profileactions::chooseLoadPath(this);
    if (!path.isEmpty())
        loadProfile(path);
}

void FeetechWorkspace::loadProfile(const QString &path)
{
    const int index = currentIndex();
    if (index < 0 || !m_client->servos()->at(index).info.hasTable()) {
        emit problem(tr("Choose a servo of a known model first."));
        return;
    }
    if (m_client->isBusy()) {
        emit problem(tr("Wait for the running operation to finish before loading a profile."));
        return;
    }
    const feetech::ServoInfo &info = m_client->servos()->at(index).info;
    QString error;
    const profileactions::LoadOutcome outcome = profileactions::loadAsEdits(
        this, path, feetech::familyKey(*info.model.family),
        feetech::profileDefinitions(info.table()), *m_client->servos()->parameters(index), &error);
    if (outcome == profileactions::LoadOutcome::Failed)
        emit problem(error);
    else if (const QString note = profileactions::outcomeMessage(outcome); !note.isEmpty())
        emit message(note);
}
