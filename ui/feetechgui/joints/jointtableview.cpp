// The joint table's grid: a row's servo, its position (live or last read), its target against
// the range it may be sent, its torque state and motion, coloured by what they mean.
#include "jointtableview.h"

#include "busclient.h"
#include "palette.h"
#include "registerkeys.h"
#include "servoparameters.h"
#include "targetdelegate.h"

#include <QHeaderView>

using namespace feetech::registerkeys;

JointTableView::JointTableView(QWidget *parent)
    : QTableWidget(0, ColumnCount, parent)
{
    setObjectName(QStringLiteral("jointTableView"));
    const QString step = feetech::unitText(QStringLiteral("step"));
    setHorizontalHeaderLabels({tr("ID"), tr("Model"), tr("Baud rate"),
                               tr("Position (%1)").arg(step), tr("Target (%1)").arg(step),
                               tr("Target range"), tr("Torque"), tr("Motion"), tr("Identify")});
    const auto headerTip = [this](int column, const QString &tip) {
        horizontalHeaderItem(column)->setToolTip(tip);
    };
    headerTip(PositionColumn,
              tr("Present position: live while the monitor watches the servo, otherwise the "
                 "last value read (grey)"));
    headerTip(TargetColumn,
              tr("Where Move all sends the servo: double-click or type to change it"));
    headerTip(RangeColumn,
              tr("The servo's angle limits, or the goal register's range when the limits are "
                 "unknown or both 0"));
    headerTip(TorqueColumn, tr("Tick to switch torque on, untick to switch it off"));
    headerTip(MovingColumn, tr("Whether the servo reports that it is moving"));
    headerTip(IdentifyColumn,
              tr("Wiggle the servo slowly with little torque, then put it back as it was: see "
                 "which servo of the arm it is"));
    setItemDelegateForColumn(TargetColumn, new TargetDelegate(this));
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                    | QAbstractItemView::AnyKeyPressed);
    setAlternatingRowColors(true);
    verticalHeader()->hide();
    setWordWrap(false);
    QHeaderView *header = horizontalHeader();
    header->setHighlightSections(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setStretchLastSection(true);
    // In character widths, so every column fits beside the servo tree at any font size.
    const int ems[ColumnCount] = {3, 7, 7, 10, 9, 9, 8, 6, 6};
    const int em = fontMetrics().horizontalAdvance(u'm');
    for (int column = 0; column < ColumnCount; ++column)
        setColumnWidth(column, ems[column] * em);
    connect(this, &QTableWidget::itemChanged, this, &JointTableView::onItemChanged);
}

void JointTableView::resetRows(int count)
{
    const QSignalBlocker blocker(this);
    setRowCount(0);
    setRowCount(count);
    for (int row = 0; row < count; ++row) {
        for (int column = 0; column < ColumnCount; ++column) {
            auto *item = new QTableWidgetItem;
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
            if (column == PositionColumn || column == TargetColumn)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            setItem(row, column, item);
        }
    }
}

void JointTableView::showServo(int row, const feetech::ServoInfo &info, const Torque &torque)
{
    const bool dark = palette::isDark(palette());
    m_filling = true;

    QTableWidgetItem *id = item(row, IdColumn);
    id->setText(QString::number(info.id));
    QTableWidgetItem *model = item(row, ModelColumn);
    model->setText(info.model.name);
    model->setToolTip(info.hasTable()
                          ? tr("%1 family, firmware %2")
                                .arg(feetech::familyName(*info.model.family), info.firmware())
                          : tr("Unknown model: it cannot be moved from here"));
    item(row, BaudColumn)->setText(feetech::baudText(info.baud));

    // Torque: what the servo reports, or what was just asked of it until the read-back.
    QTableWidgetItem *cell = item(row, TorqueColumn);
    const bool switchable = info.hasTable() && info.table().find(kTorqueEnable);
    cell->setFlags(switchable ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable
                              : Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    QString text;
    Qt::CheckState check = Qt::Unchecked;
    QColor colour;
    if (torque.requested) {
        const bool on = *torque.requested == feetech::TorqueMode::On;
        text = on ? tr("Switching on…") : tr("Switching off…");
        check = on ? Qt::Checked : Qt::Unchecked;
    } else if (!torque.device) {
        text = tr("Unknown");
    } else if (torque.mode == feetech::TorqueMode::Off) {
        text = tr("Off");
    } else if (torque.mode == feetech::TorqueMode::On) {
        text = tr("On");
        check = Qt::Checked;
        colour = palette::toneColor(palette::Tone::Good, dark);
    } else if (torque.mode == feetech::TorqueMode::Damping) {
        text = tr("Damping");
        check = Qt::PartiallyChecked;
        colour = palette::toneColor(palette::Tone::Warning, dark);
    } else if (const feetech::Register *reg = info.table().find(kTorqueEnable)) {
        text = feetech::displayValue(*reg, qint32(*torque.device));
    }
    cell->setText(text);
    if (switchable)
        cell->setCheckState(check);
    cell->setData(Qt::ForegroundRole, colour.isValid() ? QVariant(colour) : QVariant());
    m_filling = false;
}

void JointTableView::showPosition(int row, std::optional<qint32> value, bool live,
                                  std::optional<bool> isMoving)
{
    const bool dark = palette::isDark(palette());
    m_filling = true;
    QTableWidgetItem *position = item(row, PositionColumn);
    position->setText(value ? QString::number(*value) : QStringLiteral("—"));
    QFont font = this->font();
    font.setItalic(!live);
    position->setFont(font);
    position->setData(Qt::ForegroundRole,
                      live ? QVariant() : QVariant(palette().color(QPalette::PlaceholderText)));
    position->setToolTip(live        ? tr("Live, from the monitor")
                             : value ? tr("Last value read: it may be stale")
                                     : tr("Not read yet"));

    QTableWidgetItem *motion = item(row, MovingColumn);
    motion->setText(!isMoving ? QStringLiteral("—") : *isMoving ? tr("Moving") : tr("Still"));
    QFont motionFont = this->font();
    motionFont.setBold(isMoving.value_or(false));
    motionFont.setItalic(!live); // as stale as the position it goes with
    motion->setFont(motionFont);
    motion->setData(Qt::ForegroundRole,
                    !live ? QVariant(palette().color(QPalette::PlaceholderText))
                        : isMoving.value_or(false)
                        ? QVariant(palette::toneColor(palette::Tone::Accent, dark))
                        : QVariant());
    m_filling = false;

    // An editor opened without a target starts at the present position.
    const QSignalBlocker blocker(this);
    if (value)
        item(row, TargetColumn)->setData(TargetDelegate::SuggestionRole, *value);
}

void JointTableView::showTarget(int row, std::optional<feetech::PositionRange> range,
                                std::optional<qint32> target)
{
    const bool dark = palette::isDark(palette());
    m_filling = true;
    QTableWidgetItem *rangeItem = item(row, RangeColumn);
    QTableWidgetItem *targetItem = item(row, TargetColumn);
    if (!range) {
        rangeItem->setText(QStringLiteral("—"));
        rangeItem->setToolTip(tr("Unknown model: no goal register"));
        targetItem->setFlags(Qt::ItemIsSelectable);
    } else {
        rangeItem->setText(tr("%1 to %2").arg(range->minimum).arg(range->maximum));
        rangeItem->setToolTip(range->fromAngleLimits
                                  ? tr("From the servo's angle limits")
                                  : tr("The goal register's range: the angle limits are not "
                                       "read yet or both 0"));
        targetItem->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable);
        targetItem->setData(TargetDelegate::MinimumRole, range->minimum);
        targetItem->setData(TargetDelegate::MaximumRole, range->maximum);
        if (!targetItem->data(TargetDelegate::SuggestionRole).isValid())
            targetItem->setData(TargetDelegate::SuggestionRole,
                                (range->minimum + range->maximum) / 2);
    }
    targetItem->setData(Qt::EditRole, target ? QVariant(*target) : QVariant());
    const bool outside = target && range && !range->contains(*target);
    targetItem->setData(Qt::ForegroundRole,
                        outside ? QVariant(palette::toneColor(palette::Tone::Error, dark))
                                : QVariant());
    targetItem->setToolTip(outside ? tr("Outside the range %1 to %2: Move all will refuse it")
                                         .arg(range->minimum)
                                         .arg(range->maximum)
                               : target ? QString()
                                        : tr("No target yet: type one, load a pose or take the "
                                             "present position"));
    m_filling = false;
}

void JointTableView::onItemChanged(QTableWidgetItem *changed)
{
    if (m_filling)
        return;
    const int row = changed->row();
    if (row < 0)
        return;
    if (changed->column() == TargetColumn) {
        const QVariant value = changed->data(Qt::EditRole);
        if (value.isValid())
            emit targetEdited(row, value.toInt());
        return;
    }
    if (changed->column() == TorqueColumn) {
        // A damping servo (partly ticked) ticked again means "on".
        emit torqueToggled(row, changed->checkState() != Qt::Unchecked);
    }
}
