// Feetech workspace: the servo tree, the Settings and Memory table pages and the tabs; the
// operations on a servo are in feetechworkspaceoperations.cpp.
#include "feetechworkspace.h"

#include "busclient.h"
#include "controlpage.h"
#include "healthpage.h"
#include "jointtable.h"
#include "monitorpage.h"
#include "palette.h"
#include "parameterpage.h"
#include "profileactions.h"
#include "registertablemodel.h"
#include "robotactions.h"
#include "scandialog.h"
#include "scanmemory.h"
#include "servoparameters.h"
#include "sharedidcheck.h"
#include "unlockednotice.h"
#include "widgethelpers.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QSet>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>

#include <algorithm>

using widgethelpers::actionButton;

namespace {

// RAM rows of the shown servo are read again this often while the table is on screen.
constexpr int kLiveRefreshMs = 250;

enum TreeColumn { ServoColumn, ModelColumn, FamilyColumn, FirmwareColumn, TreeColumns };
constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kBaudRole = Qt::UserRole + 2;

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
    m_tree = new QTreeWidget(left);
    m_tree->setObjectName(QStringLiteral("servoTree"));
    m_tree->setColumnCount(TreeColumns);
    m_tree->setHeaderLabels({tr("Servo"), tr("Model"), tr("Family"), tr("Firmware")});
    m_tree->setRootIsDecorated(true);
    m_tree->setUniformRowHeights(true);
    m_tree->header()->setStretchLastSection(false);
    m_tree->setIndentation(m_tree->fontMetrics().horizontalAdvance(u'm') * 3 / 2);
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection); // the robot actions take many
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
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

    auto *memory = new QWidget(m_tabs);
    memory->setObjectName(QStringLiteral("memoryTablePage"));
    auto *memoryLayout = new QVBoxLayout(memory);
    auto *memoryTop = new QHBoxLayout;
    m_filterEdit = new QLineEdit(memory);
    m_filterEdit->setObjectName(QStringLiteral("registerFilter"));
    m_filterEdit->setPlaceholderText(tr("Filter registers"));
    m_filterEdit->setClearButtonEnabled(true);
    m_live = new QCheckBox(tr("Refresh RAM live"), memory);
    m_live->setObjectName(QStringLiteral("liveCheck"));
    m_live->setChecked(true);
    m_live->setToolTip(tr("Read the RAM registers (present position, load, voltage…) "
                          "several times a second while this table is shown"));
    memoryTop->addWidget(m_filterEdit, 1);
    memoryTop->addWidget(m_live);
    memoryLayout->addLayout(memoryTop);
    m_memoryEmpty = new QLabel(tr("No servo chosen: scan the bus, then choose a servo in the "
                                  "tree; every register of its memory table shows here."),
                               memory);
    m_memoryEmpty->setObjectName(QStringLiteral("memoryEmptyState"));
    m_memoryEmpty->setWordWrap(true);
    m_memoryEmpty->setForegroundRole(QPalette::PlaceholderText);
    memoryLayout->addWidget(m_memoryEmpty);
    m_registers = new RegisterTableModel(this);
    m_filter = new QSortFilterProxyModel(this);
    m_filter->setSourceModel(m_registers);
    m_filter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_filter->setFilterKeyColumn(-1);
    m_table = new QTableView(memory);
    m_table->setObjectName(QStringLiteral("memoryTable"));
    m_table->setModel(m_filter);
    m_table->setAlternatingRowColors(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::AnyKeyPressed);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(RegisterTableModel::LabelColumn,
                                                      QHeaderView::Stretch);
    memoryLayout->addWidget(m_table, 1);
    auto *memoryButtons = new QHBoxLayout;
    m_tableRead =
        actionButton(tr("Read"), "tableReadButton", tr("Read every register of the servo"), memory);
    m_tableRevert = actionButton(tr("Revert"), "tableRevertButton", tr("Drop every edit"), memory);
    m_tableApply = actionButton(tr("Apply"), "tableApplyButton",
                                tr("Write the edited registers, then read them back"), memory);
    QFont bold = m_tableApply->font();
    bold.setBold(true);
    m_tableApply->setFont(bold);
    memoryButtons->addStretch(1);
    memoryButtons->addWidget(m_tableRead);
    memoryButtons->addWidget(m_tableRevert);
    memoryButtons->addWidget(m_tableApply);
    memoryLayout->addLayout(memoryButtons);
    m_tabs->addTab(memory, tr("Memory table"));
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
    connect(m_tree, &QTreeWidget::itemSelectionChanged, this,
            &FeetechWorkspace::onSelectionChanged);
    connect(m_changeId, &QPushButton::clicked, this, &FeetechWorkspace::changeId);
    connect(m_changeBaud, &QPushButton::clicked, this, &FeetechWorkspace::changeBaud);
    connect(m_calibrate, &QPushButton::clicked, this, &FeetechWorkspace::calibrateMiddle);
    connect(m_factoryReset, &QPushButton::clicked, this, &FeetechWorkspace::factoryReset);
    connect(m_reboot, &QPushButton::clicked, this,
            [this] { run(&feetech::BusClient::reboot, tr("Restarting the servo…")); });
    connect(m_clearStatus, &QPushButton::clicked, this,
            [this] { run(&feetech::BusClient::clearStatus, tr("Clearing the status…")); });
    connect(m_filterEdit, &QLineEdit::textChanged, m_filter,
            &QSortFilterProxyModel::setFilterFixedString);
    connect(m_registers, &RegisterTableModel::editRefused, this, &FeetechWorkspace::problem);

    const auto readCurrent = [this] {
        if (currentIndex() >= 0)
            m_client->readServo(currentIndex());
    };
    connect(m_settings, &ParameterPage::readRequested, this, readCurrent);
    connect(m_tableRead, &QPushButton::clicked, this, readCurrent);
    connect(m_settings, &ParameterPage::applyRequested, this, &FeetechWorkspace::apply);
    connect(m_tableApply, &QPushButton::clicked, this, &FeetechWorkspace::apply);
    connect(m_tableRevert, &QPushButton::clicked, this, [this] {
        if (auto *parameters = m_client->parameters(currentIndex()))
            parameters->revertAll();
    });
    connect(m_settings, &ParameterPage::saveProfileRequested, this,
            &FeetechWorkspace::chooseProfileToSave);
    connect(m_settings, &ParameterPage::loadProfileRequested, this,
            &FeetechWorkspace::chooseProfileToLoad);

    connect(m_client, &feetech::BusClient::servosChanged, this, &FeetechWorkspace::rebuildTree);
    connect(m_client, &feetech::BusClient::servoUpdated, this, [this](int index) {
        if (index == currentIndex())
            updateHeader();
        updateActions();
    });
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        updateActions();
        updateHeader();
        if (m_client->servoCount() == 0 && !m_client->isScanning())
            m_scanState->setText(m_client->isConnected()
                                     ? tr("Press Scan… to find the servos on the bus.")
                                     : tr("Connect, then scan to find the servos."));
    });
    connect(m_client, &feetech::BusClient::busyChanged, this, [this](bool busy) {
        if (!busy || !m_client->isScanning())
            m_settings->setBusy(busy && !m_client->isScanning(), tr("Working…"));
        updateActions();
    });
    connect(m_client, &feetech::BusClient::progress, m_settings, &ParameterPage::setProgress);
    // The status bar tells the outcome of every operation, whoever asked for it.
    connect(m_client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        connect(reply, &feetech::OperationReply::finished, this,
                &FeetechWorkspace::onOperationFinished);
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
                m_scanState->setText(text);
                if (!completed)
                    emit problem(text);
                if (!m_current && m_client->servoCount() > 0)
                    selectServo(m_client->servo(0).info.id, m_client->servo(0).info.baud);
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
    return m_current ? m_client->indexOf(m_current->first, m_current->second) : -1;
}

void FeetechWorkspace::setPortName(const QString &name)
{
    m_portName = name;
    rebuildTree();
}

void FeetechWorkspace::selectServo(quint8 id, qint32 baud)
{
    m_current = std::make_pair(id, baud);
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
    if (index >= 0 && !m_client->servo(index).read && !m_client->servo(index).info.sharedId
        && !m_client->isBusy())
        m_client->readServo(index);
}

void FeetechWorkspace::rebuildTree()
{
    const QSignalBlocker quiet(m_tree);
    // Servos selected for the robot actions stay selected across a rebuild (one comes after
    // every operation, a batch's included).
    QSet<std::pair<quint8, qint32>> wasSelected;
    for (const int index : selectedServos())
        wasSelected.insert({m_client->servo(index).info.id, m_client->servo(index).info.baud});
    m_tree->clear();
    if (m_client->servoCount() == 0) {
        updateActions();
        return;
    }
    auto *port = new QTreeWidgetItem(m_tree, {m_portName.isEmpty() ? tr("Bus") : m_portName});
    QTreeWidgetItem *baudItem = nullptr;
    qint32 baud = 0;
    QTreeWidgetItem *selected = nullptr;
    QList<QTreeWidgetItem *> alsoSelected;
    for (int i = 0; i < m_client->servoCount(); ++i) {
        const feetech::ServoInfo &info = m_client->servo(i).info;
        if (!baudItem || info.baud != baud) {
            baud = info.baud;
            baudItem = new QTreeWidgetItem(port, {feetech::baudText(baud)});
        }
        const QString family =
            info.model.family ? feetech::familyName(*info.model.family) : tr("unknown");
        const QString idText =
            info.sharedId ? tr("ID %1 (shared!)").arg(info.id) : tr("ID %1").arg(info.id);
        auto *item =
            new QTreeWidgetItem(baudItem, {idText, info.model.name, family, info.firmware()});
        const std::optional<quint8> status = m_client->servo(i).statusByte;
        const QStringList errors = status ? feetech::statusBitNames(*status) : QStringList();
        QStringList warnings;
        if (info.sharedId)
            warnings.append(tr("Two or more servos answer at ID %1: their replies come back "
                               "garbled. Nothing is written to this ID while it is shared; "
                               "connect them one at a time and give each its own ID.")
                                .arg(info.id));
        if (!errors.isEmpty())
            warnings.append(tr("It answers with error bits: %1 (the Doctor says why).")
                                .arg(errors.join(QStringLiteral(", "))));
        if (!warnings.isEmpty()) {
            item->setIcon(ServoColumn, style()->standardIcon(QStyle::SP_MessageBoxWarning));
            item->setToolTip(ServoColumn, warnings.join(u'\n'));
            item->setForeground(ServoColumn,
                                palette::toneColor(palette::Tone::Error, m_tree->palette()));
        }
        item->setData(ServoColumn, kIdRole, info.id);
        item->setData(ServoColumn, kBaudRole, info.baud);
        item->setToolTip(ModelColumn,
                         tr("Model number %1 (major %2, minor %3)")
                             .arg(info.modelNumber())
                             .arg(info.modelMajor)
                             .arg(info.modelMinor));
        if (!info.hasTable())
            item->setToolTip(FamilyColumn,
                             tr("No register table is known for this model: its "
                                "memory is shown as raw bytes, read-only."));
        if (m_current && m_current->first == info.id && m_current->second == info.baud)
            selected = item;
        else if (wasSelected.contains({info.id, info.baud}))
            alsoSelected.append(item);
    }
    m_tree->expandAll();
    for (int column = 0; column < TreeColumns; ++column)
        m_tree->resizeColumnToContents(column);
    if (selected)
        m_tree->setCurrentItem(selected);
    for (QTreeWidgetItem *item : std::as_const(alsoSelected))
        item->setSelected(true);
    updateActions();
}

QVector<int> FeetechWorkspace::selectedServos() const
{
    QVector<int> indexes;
    for (QTreeWidgetItemIterator it(m_tree, QTreeWidgetItemIterator::Selected); *it; ++it) {
        const QVariant id = (*it)->data(ServoColumn, kIdRole);
        if (!id.isValid())
            continue;
        const int index = m_client->indexOf(quint8(id.toUInt()),
                                            qint32((*it)->data(ServoColumn, kBaudRole).toInt()));
        if (index >= 0)
            indexes.append(index);
    }
    return indexes;
}

void FeetechWorkspace::onSelectionChanged()
{
    // The pages show the servo clicked last (the tree's current item) while it is selected,
    // else the first servo selected.
    const QTreeWidgetItem *item = m_tree->currentItem();
    if (!item || !item->isSelected() || !item->data(ServoColumn, kIdRole).isValid()) {
        item = nullptr;
        for (QTreeWidgetItem *selected : m_tree->selectedItems()) {
            if (selected->data(ServoColumn, kIdRole).isValid()) {
                item = selected;
                break;
            }
        }
    }
    if (!item)
        return;
    m_current = std::make_pair(quint8(item->data(ServoColumn, kIdRole).toUInt()),
                               qint32(item->data(ServoColumn, kBaudRole).toInt()));
    showServo();
    readIfNew();
}

void FeetechWorkspace::showServo()
{
    const int index = currentIndex();
    if (m_control->servo() != index)
        m_control->setServo(index);
    m_unlocked->showServo(index);
    model::ParameterModel *parameters = m_client->parameters(index);
    if (m_settings->parameterModel() != parameters) {
        if (m_settings->parameterModel())
            disconnect(m_settings->parameterModel(), nullptr, this, nullptr);
        m_settings->setModel(parameters);
        if (parameters) // Apply and Revert under the table follow the edits
            connect(parameters, &model::ParameterModel::parameterChanged, this,
                    &FeetechWorkspace::updateActions);
    }
    m_registers->setServo(index >= 0 ? &m_client->servo(index).info.table() : nullptr, parameters);
    m_table->resizeColumnsToContents();
    // Bit lists can be long: the value column keeps a reading width (the tooltip and a wider
    // window show the rest) so the register names keep theirs.
    m_table->setColumnWidth(RegisterTableModel::ValueColumn,
                            std::min(m_table->columnWidth(RegisterTableModel::ValueColumn),
                                     m_table->fontMetrics().horizontalAdvance(u'm') * 15));
    int stateWidth = 0;
    for (const model::State state :
         {model::State::Edited, model::State::Writing, model::State::Verified,
          model::State::Mismatch, model::State::Failed, model::State::Unknown})
        stateWidth = std::max(
            stateWidth,
            m_table->fontMetrics().horizontalAdvance(model::ParameterModel::stateName(state)));
    m_table->setColumnWidth(RegisterTableModel::StateColumn, stateWidth + 16);
    updateHeader();
    updateActions();
}

QString FeetechWorkspace::servoTitle() const
{
    const int index = currentIndex();
    if (index < 0)
        return {};
    const feetech::ServoInfo &info = m_client->servo(index).info;
    return tr("servo %1 (%2)").arg(info.id).arg(info.model.name);
}

void FeetechWorkspace::updateHeader()
{
    const int index = currentIndex();
    m_memoryEmpty->setVisible(index < 0);
    if (index < 0) {
        m_header->setText(m_client->servoCount() > 0 ? tr("Choose a servo in the tree.")
                              : m_client->isConnected()
                              ? tr("No servo yet: scan the bus.")
                              : tr("No servo yet: connect to the bus and scan."));
        return;
    }
    const feetech::Servo &servo = m_client->servo(index);
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
    const bool connected = m_client->isConnected();
    const bool idle = !m_client->isBusy();
    // Two servos at one ID would both take a write: nothing is sent to a shared ID.
    const bool shared = index >= 0 && m_client->servo(index).info.sharedId;
    const bool known = index >= 0 && m_client->servo(index).info.hasTable() && !shared;
    const bool ready = connected && idle && index >= 0;
    m_scan->setEnabled(connected && idle);
    m_allTorqueOff->setEnabled(connected); // never held back by work in progress
    m_changeId->setEnabled(ready && known);
    m_changeBaud->setEnabled(ready && known);
    const bool calibration = known
        && feetech::middleCalibration(m_client->servo(index).info)
            != feetech::MiddleCalibration::Unsupported;
    m_calibrate->setEnabled(ready && calibration);
    m_calibrate->setToolTip(calibration || !known
                                ? tr("Make the horn's present position the middle (2048)")
                                : tr("SCS servos have no offset register: not available"));
    m_factoryReset->setEnabled(ready && known);
    m_reboot->setEnabled(ready && !shared);
    m_clearStatus->setEnabled(ready && !shared);
    m_settings->setLinkReady(ready && known);
    model::ParameterModel *parameters = m_client->parameters(index);
    const bool edits = parameters && parameters->hasEdits();
    m_tableRead->setEnabled(ready);
    m_tableApply->setEnabled(ready && known && edits);
    m_tableRevert->setEnabled(idle && edits);
    m_registers->setEditable(connected && idle && known);
}

void FeetechWorkspace::refreshLive()
{
    const int index = currentIndex();
    if (index < 0 || !m_live->isChecked() || !isVisible() || m_tabs->currentIndex() != 1
        || !m_client->isConnected() || m_client->isBusy() || !m_client->servo(index).read)
        return;
    m_client->refreshRam(index);
}
