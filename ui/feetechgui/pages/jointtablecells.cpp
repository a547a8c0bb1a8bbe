// The joint table's cells: a row's servo, its position (live or last read), its target against
// the range it may be sent, its torque state and motion, coloured by what they mean.
#include "jointtable.h"

#include "busclient.h"
#include "palette.h"
#include "registerkeys.h"
#include "servoparameters.h"
#include "targetdelegate.h"

#include <QTableWidget>

#include <cmath>

using namespace feetech::registerkeys;

void JointTable::refreshRow(int row)
{
    if (row < 0 || row >= rowCount())
        return;
    const int index = servoIndex(row);
    if (index < 0)
        return;
    const feetech::ServoInfo &info = m_client->servo(index).info;
    const bool dark = palette::isDark(palette());
    m_updating = true;

    QTableWidgetItem *id = m_table->item(row, IdColumn);
    id->setText(QString::number(info.id));
    QTableWidgetItem *model = m_table->item(row, ModelColumn);
    model->setText(info.model.name);
    model->setToolTip(info.hasTable()
                          ? tr("%1 family, firmware %2")
                                .arg(feetech::familyName(*info.model.family), info.firmware())
                          : tr("Unknown model: it cannot be moved from here"));
    m_table->item(row, BaudColumn)->setText(feetech::baudText(info.baud));

    // Torque: what the servo reports, or what was just asked of it until the read-back.
    QTableWidgetItem *torque = m_table->item(row, TorqueColumn);
    Row &state = m_rows[row];
    const auto device = deviceValue(row, kTorqueEnable);
    const auto mode = device ? info.table().torqueMode(*device) : std::nullopt;
    if (state.torqueRequested && mode == state.torqueRequested)
        state.torqueRequested.reset();
    const bool switchable = info.hasTable() && info.table().find(kTorqueEnable);
    torque->setFlags(switchable ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable
                                : Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    QString torqueText;
    Qt::CheckState check = Qt::Unchecked;
    QColor torqueColour;
    if (state.torqueRequested) {
        const bool on = *state.torqueRequested == feetech::TorqueMode::On;
        torqueText = on ? tr("Switching on…") : tr("Switching off…");
        check = on ? Qt::Checked : Qt::Unchecked;
    } else if (!device) {
        torqueText = tr("Unknown");
    } else if (mode == feetech::TorqueMode::Off) {
        torqueText = tr("Off");
    } else if (mode == feetech::TorqueMode::On) {
        torqueText = tr("On");
        check = Qt::Checked;
        torqueColour = palette::toneColor(palette::Tone::Good, dark);
    } else if (mode == feetech::TorqueMode::Damping) {
        torqueText = tr("Damping");
        check = Qt::PartiallyChecked;
        torqueColour = palette::toneColor(palette::Tone::Warning, dark);
    } else if (const feetech::Register *reg = info.table().find(kTorqueEnable)) {
        torqueText = feetech::displayValue(*reg, qint32(*device));
    }
    torque->setText(torqueText);
    if (switchable)
        torque->setCheckState(check);
    torque->setData(Qt::ForegroundRole,
                    torqueColour.isValid() ? QVariant(torqueColour) : QVariant());
    m_updating = false;

    refreshPosition(row);
    refreshTarget(row);
}

void JointTable::refreshPosition(int row)
{
    if (row < 0 || row >= rowCount() || servoIndex(row) < 0)
        return;
    const bool dark = palette::isDark(palette());
    m_updating = true;
    QTableWidgetItem *item = m_table->item(row, PositionColumn);
    const std::optional<qint32> value = position(row);
    const bool live = isPositionLive(row);
    item->setText(value ? QString::number(*value) : QStringLiteral("—"));
    QFont font = m_table->font();
    font.setItalic(!live);
    item->setFont(font);
    item->setData(Qt::ForegroundRole,
                  live ? QVariant() : QVariant(palette().color(QPalette::PlaceholderText)));
    item->setToolTip(live        ? tr("Live, from the monitor")
                         : value ? tr("Last value read: it may be stale")
                                 : tr("Not read yet"));

    QTableWidgetItem *motion = m_table->item(row, MovingColumn);
    const std::optional<bool> isMoving = moving(row);
    motion->setText(!isMoving ? QStringLiteral("—") : *isMoving ? tr("Moving") : tr("Still"));
    QFont motionFont = m_table->font();
    motionFont.setBold(isMoving.value_or(false));
    motionFont.setItalic(!live); // as stale as the position it goes with
    motion->setFont(motionFont);
    motion->setData(Qt::ForegroundRole,
                    !live ? QVariant(palette().color(QPalette::PlaceholderText))
                        : isMoving.value_or(false)
                        ? QVariant(palette::toneColor(palette::Tone::Accent, dark))
                        : QVariant());
    m_updating = false;

    // An editor opened without a target starts at the present position.
    const QSignalBlocker blocker(m_table);
    QTableWidgetItem *target = m_table->item(row, TargetColumn);
    if (value)
        target->setData(TargetDelegate::SuggestionRole, *value);
}

void JointTable::refreshTarget(int row)
{
    if (row < 0 || row >= rowCount() || servoIndex(row) < 0)
        return;
    const bool dark = palette::isDark(palette());
    const std::optional<feetech::PositionRange> range = targetRange(row);
    const std::optional<qint32> target = m_rows.at(row).target;
    m_updating = true;
    QTableWidgetItem *rangeItem = m_table->item(row, RangeColumn);
    QTableWidgetItem *item = m_table->item(row, TargetColumn);
    if (!range) {
        rangeItem->setText(QStringLiteral("—"));
        rangeItem->setToolTip(tr("Unknown model: no goal register"));
        item->setFlags(Qt::ItemIsSelectable);
    } else {
        rangeItem->setText(tr("%1 to %2").arg(range->minimum).arg(range->maximum));
        rangeItem->setToolTip(range->fromAngleLimits
                                  ? tr("From the servo's angle limits")
                                  : tr("The goal register's range: the angle limits are not "
                                       "read yet or both 0"));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable);
        item->setData(TargetDelegate::MinimumRole, range->minimum);
        item->setData(TargetDelegate::MaximumRole, range->maximum);
        if (!item->data(TargetDelegate::SuggestionRole).isValid())
            item->setData(TargetDelegate::SuggestionRole, (range->minimum + range->maximum) / 2);
    }
    item->setData(Qt::EditRole, target ? QVariant(*target) : QVariant());
    const bool outside = target && range && !range->contains(*target);
    item->setData(Qt::ForegroundRole,
                  outside ? QVariant(palette::toneColor(palette::Tone::Error, dark)) : QVariant());
    item->setToolTip(outside ? tr("Outside the range %1 to %2: Move all will refuse it")
                                   .arg(range->minimum)
                                   .arg(range->maximum)
                         : target ? QString()
                                  : tr("No target yet: type one, load a pose or take the "
                                       "present position"));
    m_updating = false;
}
