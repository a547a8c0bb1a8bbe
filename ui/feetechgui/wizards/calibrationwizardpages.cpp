// The calibration wizard's pages, and how scanned servos become named joints.
#include "calibrationwizard.h"

#include "busclient.h"
#include "palette.h"
#include "rangebar.h"
#include "recentfiles.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace {

enum JointColumn { CalibrateColumn, IdColumn, ModelColumn, NameColumn, FullTurnColumn };
enum ResultColumn { JointColumn, OffsetColumn, MinimumColumn, MaximumColumn, StatusColumn };

QLabel *wrappedLabel(const QString &text, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setWordWrap(true);
    return label;
}

QTableWidgetItem *checkItem(bool checked)
{
    auto *item = new QTableWidgetItem;
    item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
    item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
    return item;
}

QTableWidgetItem *fixedItem(const QString &text)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled);
    return item;
}

} // namespace

QVector<ArmJoint> armJoints(const feetech::BusClient &client, const feetech::RobotTemplate *robot)
{
    QVector<ArmJoint> joints;
    for (int index = 0; index < client.servoCount(); ++index) {
        const feetech::ServoInfo &info = client.servo(index).info;
        ArmJoint joint;
        joint.index = index;
        joint.joint.id = info.id;
        joint.joint.model = info.model.name;
        joint.joint.name = QStringLiteral("id_%1").arg(info.id);
        if (robot) {
            for (const feetech::RobotJoint &known : robot->joints) {
                if (known.id == info.id) {
                    joint.joint.name = known.name;
                    joint.joint.fullTurn = known.fullTurn;
                }
            }
        }
        joints.append(joint);
    }
    return joints;
}

int defaultRobotTemplate(const QVector<feetech::RobotTemplate> &templates)
{
    for (int i = 0; i < templates.size(); ++i) {
        if (templates.at(i).name == QLatin1String("SO-101 follower arm"))
            return i;
    }
    return templates.isEmpty() ? -1 : 0;
}

QString defaultCalibrationFolder(const feetech::RobotTemplate *robot)
{
    const QString root = feetech::leRobotCalibrationFolder();
    if (robot) {
        for (const QString &folder : feetech::leRobotArmFolders(robot->name)) {
            if (QDir(root).exists(folder))
                return QDir(root).filePath(folder);
        }
    }
    const QStringList recent = recentfiles::list(recentfiles::Kind::Calibration);
    if (!recent.isEmpty())
        return QFileInfo(recent.first()).absolutePath();
    return QDir(root).exists() ? root : QDir::homePath();
}

QWidget *CalibrationWizard::buildJointsPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(wrappedLabel(
        tr("Choose the joints to calibrate. ServoBench records how far each joint turns, then "
           "sets its position offset so that the middle of that range reads 2048, and its angle "
           "limits to the range: no joint's range crosses the encoder's 0/4095 seam."),
        page));
    auto *form = new QFormLayout;
    m_template = new QComboBox(page);
    m_template->setObjectName(QStringLiteral("robotTemplateCombo"));
    for (const feetech::RobotTemplate &robot : std::as_const(m_templates))
        m_template->addItem(feetech::robotDisplayName(robot.name));
    m_template->addItem(tr("No template (joints named by ID)"));
    m_template->setCurrentIndex(std::max(0, defaultRobotTemplate(m_templates)));
    m_template->setToolTip(tr("Names the joints whose IDs the arm's template has"));
    connect(m_template, &QComboBox::currentIndexChanged, this, [this] { fillJointTable(); });
    form->addRow(tr("Robot:"), m_template);
    layout->addLayout(form);

    m_jointTable = new QTableWidget(0, 5, page);
    m_jointTable->setObjectName(QStringLiteral("calibrationJointTable"));
    m_jointTable->setHorizontalHeaderLabels(
        {tr("Calibrate"), tr("ID"), tr("Model"), tr("Joint"), tr("Full turn")});
    m_jointTable->verticalHeader()->hide();
    m_jointTable->horizontalHeader()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    m_jointTable->setSelectionMode(QAbstractItemView::NoSelection);
    layout->addWidget(m_jointTable, 1);

    auto *orderBox = new QGroupBox(tr("Order"), page);
    auto *orderLayout = new QVBoxLayout(orderBox);
    m_rangeFirst = new QRadioButton(tr("ServoBench: record each joint's range, then centre it "
                                       "on the encoder (recommended)"),
                                    orderBox);
    m_rangeFirst->setObjectName(QStringLiteral("rangeFirstRadio"));
    m_middleFirst = new QRadioButton(tr("LeRobot: put the arm in its middle pose first (it reads "
                                        "2047), then record the ranges"),
                                     orderBox);
    m_middleFirst->setObjectName(QStringLiteral("middlePoseFirstRadio"));
    m_rangeFirst->setChecked(true);
    auto *group = new QButtonGroup(orderBox);
    group->addButton(m_rangeFirst);
    group->addButton(m_middleFirst);
    orderLayout->addWidget(m_rangeFirst);
    orderLayout->addWidget(m_middleFirst);
    layout->addWidget(orderBox);

    m_next = widgethelpers::actionButton(tr("&Next"), "calibrationNextButton",
                                         tr("Check the choice, then switch torque off"), page);
    connect(m_next, &QPushButton::clicked, this, &CalibrationWizard::goToWarning);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_next);
    layout->addLayout(buttons);
    fillJointTable();
    return page;
}

void CalibrationWizard::fillJointTable()
{
    const int chosen = m_template->currentIndex();
    const feetech::RobotTemplate *robot =
        chosen >= 0 && chosen < m_templates.size() ? &m_templates.at(chosen) : nullptr;
    const QVector<ArmJoint> joints = armJoints(*m_client, robot);
    m_jointTable->setRowCount(int(joints.size()));
    for (int row = 0; row < joints.size(); ++row) {
        const ArmJoint &joint = joints.at(row);
        const feetech::ServoInfo &info = m_client->servo(joint.index).info;
        const bool calibratable = info.hasTable() && feetech::calibrationLimits(info.table());
        const bool inTemplate = !robot || robot->joint(joint.joint.name) != nullptr;
        auto *calibrate = checkItem(calibratable && inTemplate);
        calibrate->setData(Qt::UserRole, joint.index);
        auto *model =
            fixedItem(calibratable ? joint.joint.model
                                   : tr("%1 (no position offset)").arg(joint.joint.model));
        if (!calibratable) {
            // An SCS servo (or an unknown model) has no offset to centre its range with.
            calibrate->setFlags(Qt::ItemIsUserCheckable);
            calibrate->setToolTip(tr("This servo has no position offset register: it cannot be "
                                     "calibrated"));
        }
        m_jointTable->setItem(row, CalibrateColumn, calibrate);
        m_jointTable->setItem(row, IdColumn, fixedItem(QString::number(joint.joint.id)));
        m_jointTable->setItem(row, ModelColumn, model);
        m_jointTable->setItem(row, NameColumn, new QTableWidgetItem(joint.joint.name));
        m_jointTable->setItem(row, FullTurnColumn, checkItem(joint.joint.fullTurn));
    }
    m_jointTable->resizeColumnsToContents();
}

QWidget *CalibrationWizard::buildWarningPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    m_warning = wrappedLabel(QString(), page);
    m_warning->setObjectName(QStringLiteral("torqueWarning"));
    QFont bold = m_warning->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.2);
    m_warning->setFont(bold);
    QPalette colours = m_warning->palette();
    colours.setColor(QPalette::WindowText,
                     palette::toneColor(palette::Tone::Warning, m_warning->palette()));
    m_warning->setPalette(colours);
    layout->addWidget(m_warning);
    layout->addWidget(wrappedLabel(
        tr("Nothing is written to the servos until you have seen the results and chosen to "
           "write them. Cancel at any point writes nothing (torque stays off)."),
        page));
    layout->addStretch(1);
    m_torqueOff = widgethelpers::actionButton(
        tr("I am supporting the arm: switch torque &off"), "torqueOffStartButton",
        tr("Switch torque off on the joints and start"), page);
    connect(m_torqueOff, &QPushButton::clicked, this, &CalibrationWizard::switchTorqueOffAndStart);
    auto *back = widgethelpers::actionButton(tr("&Back"), "calibrationBackButton",
                                             tr("Choose the joints again"), page);
    connect(back, &QPushButton::clicked, this, [this] {
        if (m_stage == Stage::Choosing)
            showPage(Page::Joints);
    });
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(back);
    buttons->addStretch(1);
    buttons->addWidget(m_torqueOff);
    layout->addLayout(buttons);
    return page;
}

QWidget *CalibrationWizard::buildMiddlePosePage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(wrappedLabel(
        tr("Move every joint to the middle of its travel (LeRobot's middle pose: the arm "
           "stretched out level, the gripper half open), then take the pose. Each joint's "
           "present position there will read 2047."),
        page));
    m_middleList = wrappedLabel(QString(), page);
    m_middleList->setObjectName(QStringLiteral("middlePoseList"));
    m_middleList->setTextFormat(Qt::PlainText);
    layout->addWidget(m_middleList, 1);
    m_takeMiddle =
        widgethelpers::actionButton(tr("&Take the middle pose"), "takeMiddlePoseButton",
                                    tr("Keep the present positions as the middle"), page);
    connect(m_takeMiddle, &QPushButton::clicked, this, &CalibrationWizard::takeMiddlePose);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_takeMiddle);
    layout->addLayout(buttons);
    return page;
}

QWidget *CalibrationWizard::buildRecordingPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(wrappedLabel(
        tr("Move every joint slowly through its whole range, to both end stops, and back to "
           "the middle. Turn a full-turn joint as far as you want it to go. The bars show one "
           "turn of the encoder: the filled part is the range recorded so far, the line the "
           "present position, the dashed line the middle the range will be centred on."),
        page));
    auto *scroll = new QScrollArea(page);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *inner = new QWidget(scroll);
    m_barGrid = new QGridLayout(inner);
    m_barGrid->setColumnStretch(1, 1);
    m_barGrid->setRowStretch(100, 1);
    scroll->setWidget(inner);
    layout->addWidget(scroll, 1);
    m_finish = widgethelpers::actionButton(tr("&Finish recording"), "finishRecordingButton",
                                           tr("Stop recording and compute the calibration"), page);
    connect(m_finish, &QPushButton::clicked, this, &CalibrationWizard::finishRecording);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_finish);
    layout->addLayout(buttons);
    return page;
}

void CalibrationWizard::buildBars()
{
    QWidget *inner = m_barGrid->parentWidget();
    qDeleteAll(inner->findChildren<QWidget *>(QString(), Qt::FindDirectChildrenOnly));
    m_bars.clear();
    m_barValues.clear();
    for (int row = 0; row < m_recordings.size(); ++row) {
        const feetech::JointRecording &joint = m_recordings.at(row);
        auto *name = new QLabel(tr("%1 (%2)%3")
                                    .arg(feetech::jointDisplayName(joint.name))
                                    .arg(joint.id)
                                    .arg(joint.fullTurn ? tr(", full turn") : QString()),
                                inner);
        auto *bar = new RangeBar(inner);
        bar->setObjectName(QStringLiteral("rangeBar_%1").arg(joint.id));
        auto *values = new QLabel(inner);
        values->setObjectName(QStringLiteral("rangeValues_%1").arg(joint.id));
        values->setMinimumWidth(values->fontMetrics().horizontalAdvance(
            tr("min %1 · present %2 · max %3").arg(-99999).arg(-99999).arg(-99999)));
        m_barGrid->addWidget(name, row, 0);
        m_barGrid->addWidget(bar, row, 1);
        m_barGrid->addWidget(values, row, 2);
        m_bars.append(bar);
        m_barValues.append(values);
    }
    refreshBars();
}

QWidget *CalibrationWizard::buildResultsPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(
        wrappedLabel(tr("Each joint's new position offset and angle limits (in steps, in the new "
                        "coordinates), or why it is refused. Nothing has been written yet."),
                     page));
    m_resultTable = new QTableWidget(0, 5, page);
    m_resultTable->setObjectName(QStringLiteral("calibrationResultTable"));
    m_resultTable->setHorizontalHeaderLabels(
        {tr("Joint"), tr("Offset"), tr("Min limit"), tr("Max limit"), tr("Status")});
    m_resultTable->verticalHeader()->hide();
    m_resultTable->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    m_resultTable->setWordWrap(true);
    m_resultTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_resultTable, 1);
    m_progress = new QProgressBar(page);
    m_progress->setObjectName(QStringLiteral("calibrationProgress"));
    m_progress->hide();
    layout->addWidget(m_progress);
    m_write = widgethelpers::actionButton(tr("&Write to the servos"), "writeCalibrationButton",
                                          tr("Write the offsets and limits to EEPROM and verify "
                                             "them"),
                                          page);
    connect(m_write, &QPushButton::clicked, this, &CalibrationWizard::writeToServos);
    m_save = widgethelpers::actionButton(tr("&Save LeRobot file…"), "saveLeRobotFileButton",
                                         tr("Save the written calibration as LeRobot's JSON file"),
                                         page);
    m_save->setEnabled(false);
    connect(m_save, &QPushButton::clicked, this, &CalibrationWizard::chooseFileToSave);
    m_again =
        widgethelpers::actionButton(tr("&Record again"), "recordAgainButton",
                                    tr("Forget this recording and record the ranges again"), page);
    connect(m_again, &QPushButton::clicked, this, &CalibrationWizard::recordAgain);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_again);
    buttons->addStretch(1);
    buttons->addWidget(m_write);
    buttons->addWidget(m_save);
    layout->addLayout(buttons);
    return page;
}

void CalibrationWizard::showResults()
{
    m_resultTable->setRowCount(int(m_results.size()));
    const QColor refused = palette::toneColor(palette::Tone::Error, m_resultTable->palette());
    for (int row = 0; row < m_results.size(); ++row) {
        const feetech::JointCalibration &result = m_results.at(row);
        m_resultTable->setItem(
            row, JointColumn,
            new QTableWidgetItem(
                tr("%1 (%2)").arg(feetech::jointDisplayName(result.name)).arg(result.id)));
        const auto number = [&result](qint32 value) {
            return new QTableWidgetItem(result.ok() ? QString::number(value) : QString());
        };
        m_resultTable->setItem(row, OffsetColumn, number(result.offset));
        m_resultTable->setItem(row, MinimumColumn, number(result.minimumLimit));
        m_resultTable->setItem(row, MaximumColumn, number(result.maximumLimit));
        auto *status = new QTableWidgetItem(
            result.ok() ? tr("To write") : tr("Refused, nothing written: %1").arg(result.refusal));
        status->setToolTip(status->text());
        if (!result.ok())
            status->setForeground(refused);
        m_resultTable->setItem(row, StatusColumn, status);
    }
    m_resultTable->resizeColumnsToContents();
    m_resultTable->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    // Once the stretched column has its width, long refusals wrap onto more lines.
    QTimer::singleShot(0, m_resultTable,
                       [table = m_resultTable] { table->resizeRowsToContents(); });
}
