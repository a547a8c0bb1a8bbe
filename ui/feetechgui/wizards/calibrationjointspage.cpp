// The calibration wizard's joint choice, and how scanned servos become named joints.
#include "calibrationjointspage.h"

#include "busclient.h"
#include "jointnamedelegate.h"
#include "lerobotcalibration.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSet>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace {

enum JointColumn { CalibrateColumn, IdColumn, ModelColumn, NameColumn, FullTurnColumn };

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
    for (int index = 0; index < client.servos()->count(); ++index) {
        const feetech::ServoInfo &info = client.servos()->at(index).info;
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

CalibrationJointsPage::CalibrationJointsPage(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
    , m_templates(feetech::availableRobotTemplates())
{
    QWidget *page = this;
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(widgethelpers::wrappedLabel(
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
    m_template->setCurrentIndex(std::max(0, feetech::defaultRobotTemplate(m_templates)));
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
    // The names are LeRobot's keys, edited as such; the user's language shows beside them.
    m_jointTable->setItemDelegateForColumn(NameColumn, new JointNameDelegate(m_jointTable));
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
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_next);
    layout->addLayout(buttons);
    fillJointTable();
}

void CalibrationJointsPage::fillJointTable()
{
    const int chosen = m_template->currentIndex();
    const feetech::RobotTemplate *robot =
        chosen >= 0 && chosen < m_templates.size() ? &m_templates.at(chosen) : nullptr;
    const QVector<ArmJoint> joints = armJoints(*m_client, robot);
    m_jointTable->setRowCount(int(joints.size()));
    for (int row = 0; row < joints.size(); ++row) {
        const ArmJoint &joint = joints.at(row);
        const feetech::ServoInfo &info = m_client->servos()->at(joint.index).info;
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

bool CalibrationJointsPage::choose(Choice *choice, QString *error) const
{
    *choice = {};
    const auto refuse = [error](const QString &why) {
        *error = why;
        return false;
    };
    QSet<QString> names;
    for (int row = 0; row < m_jointTable->rowCount(); ++row) {
        if (m_jointTable->item(row, CalibrateColumn)->checkState() != Qt::Checked)
            continue;
        const int index = m_jointTable->item(row, CalibrateColumn)->data(Qt::UserRole).toInt();
        const feetech::ServoInfo &info = m_client->servos()->at(index).info;
        const QString name = m_jointTable->item(row, NameColumn)->text().trimmed();
        if (!feetech::isLeRobotMotorName(name))
            return refuse(tr("\"%1\" is not a joint name: use letters, digits and _, a letter "
                             "first (LeRobot's motor names, such as shoulder_pan).")
                              .arg(name));
        if (names.contains(name))
            return refuse(tr("Two joints are named \"%1\": give each its own name.").arg(name));
        names.insert(name);
        const auto limits =
            info.hasTable() ? feetech::calibrationLimits(info.table()) : std::nullopt;
        if (!limits)
            return refuse(tr("Servo %1 (%2) has no position offset on a 4096-step encoder: it "
                             "cannot be calibrated. Leave it out.")
                              .arg(info.id)
                              .arg(info.model.name));
        feetech::JointRecording joint;
        joint.name = name;
        joint.id = info.id;
        joint.fullTurn = m_jointTable->item(row, FullTurnColumn)->checkState() == Qt::Checked;
        joint.limits = *limits;
        choice->recordings.append(joint);
        choice->indexes.append(index);
        choice->described.append(
            tr("%1 (ID %2)").arg(feetech::jointDisplayName(name)).arg(info.id));
    }
    if (choice->recordings.isEmpty())
        return refuse(tr("Choose at least one joint to calibrate."));
    return true;
}

bool CalibrationJointsPage::keepOnly(int id, const QString &name, bool fullTurn)
{
    int kept = -1;
    for (int row = 0; row < m_jointTable->rowCount(); ++row) {
        if (m_jointTable->item(row, IdColumn)->text() == QString::number(id))
            kept = row;
    }
    if (kept < 0)
        return false;
    // The other joints keep what the arm's file says of them: they are not shown. The file
    // names the joint, so its name and tick cannot be changed; its full-turn flag can.
    for (int row = 0; row < m_jointTable->rowCount(); ++row) {
        m_jointTable->item(row, CalibrateColumn)
            ->setCheckState(row == kept ? Qt::Checked : Qt::Unchecked);
        m_jointTable->setRowHidden(row, row != kept);
    }
    m_jointTable->item(kept, CalibrateColumn)->setFlags(Qt::ItemIsEnabled);
    m_jointTable->item(kept, NameColumn)->setText(name);
    m_jointTable->item(kept, NameColumn)->setFlags(Qt::ItemIsEnabled);
    m_jointTable->item(kept, FullTurnColumn)->setCheckState(fullTurn ? Qt::Checked : Qt::Unchecked);
    m_template->setEnabled(false);
    return true;
}

feetech::CalibrationOrder CalibrationJointsPage::order() const
{
    return m_middleFirst->isChecked() ? feetech::CalibrationOrder::MiddlePoseFirst
                                      : feetech::CalibrationOrder::RangeFirst;
}

const feetech::RobotTemplate *CalibrationJointsPage::chosenTemplate() const
{
    const int chosen = m_template->currentIndex();
    return chosen >= 0 && chosen < m_templates.size() ? &m_templates.at(chosen) : nullptr;
}
