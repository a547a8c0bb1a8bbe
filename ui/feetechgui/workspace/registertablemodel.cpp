// Memory table model: register rows with raw and real-unit values, edits through the model.
#include "registertablemodel.h"

#include "palette.h"
#include "parametermodel.h"
#include "registertable.h"
#include "servoparameters.h"

#include <QBrush>
#include <QColor>
#include <QCoreApplication>
#include <QFont>
#include <QLocale>
#include <QPalette>

#include <cmath>

namespace {

QColor stateBackground(model::State state)
{
    const bool dark = palette::isDark();
    switch (state) {
    case model::State::Edited:
    case model::State::Writing:
    case model::State::Unknown:
        return dark ? QColor(90, 72, 20) : QColor(255, 240, 170);
    case model::State::Verified:
        return dark ? QColor(28, 70, 36) : QColor(214, 240, 218);
    case model::State::Mismatch:
    case model::State::Failed:
        return dark ? QColor(96, 32, 28) : QColor(250, 216, 212);
    case model::State::Clean:
        break;
    }
    return {};
}

} // namespace

RegisterTableModel::RegisterTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void RegisterTableModel::setServo(const feetech::RegisterTable *table,
                                  model::ParameterModel *parameters)
{
    if (table == m_table && parameters == m_parameters)
        return; // the same servo: keep whatever cell is being edited
    beginResetModel();
    if (m_parameters)
        disconnect(m_parameters, nullptr, this, nullptr);
    m_adjustments.clear();
    m_table = parameters ? table : nullptr;
    m_parameters = table ? parameters : nullptr;
    if (m_parameters) {
        connect(m_parameters, &model::ParameterModel::parameterChanged, this,
                &RegisterTableModel::parameterChanged);
        connect(m_parameters, &QObject::destroyed, this, [this] { setServo(nullptr, nullptr); });
    }
    endResetModel();
}

void RegisterTableModel::setEditable(bool editable)
{
    if (m_editable == editable)
        return;
    m_editable = editable;
    if (rowCount() > 0)
        emit dataChanged(index(0, ValueColumn), index(rowCount() - 1, ValueColumn));
}

const feetech::Register *RegisterTableModel::registerAt(int row) const
{
    if (!m_table || row < 0 || row >= m_table->registers().size())
        return nullptr;
    return &m_table->registers().at(row);
}

int RegisterTableModel::rowOf(const QString &key) const
{
    if (!m_table)
        return -1;
    for (int row = 0; row < m_table->registers().size(); ++row) {
        if (m_table->registers().at(row).key == key)
            return row;
    }
    return -1;
}

int RegisterTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() || !m_table ? 0 : int(m_table->registers().size());
}

int RegisterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant RegisterTableModel::data(const QModelIndex &index, int role) const
{
    const feetech::Register *reg = registerAt(index.row());
    if (!reg || !m_parameters)
        return {};
    const std::optional<qint64> device = m_parameters->deviceValue(reg->key);
    const std::optional<qint64> pending = m_parameters->pendingValue(reg->key);
    const model::State state = m_parameters->state(reg->key);
    const std::optional<qint64> shown = pending ? pending : device;

    if (role == KeyRole)
        return reg->key;
    if (role == PendingRole)
        return pending.has_value();
    if (role == RegisterValueRole)
        return shown ? QVariant(qint32(*shown)) : QVariant();
    if (role == Qt::BackgroundRole) {
        const QColor colour = stateBackground(state);
        return colour.isValid() ? QVariant(QBrush(colour)) : QVariant();
    }
    if (role == Qt::ForegroundRole && state != model::State::Clean) {
        return QBrush(palette::isDark() ? QColor(240, 240, 240) : QColor(20, 20, 20));
    }
    if (role == Qt::FontRole && index.column() == ValueColumn && pending) {
        QFont bold;
        bold.setBold(true);
        return bold;
    }
    if (role == Qt::TextAlignmentRole) {
        switch (index.column()) {
        case AddressColumn:
        case SizeColumn:
        case RawColumn:
            return int(Qt::AlignRight | Qt::AlignVCenter);
        default:
            return int(Qt::AlignLeft | Qt::AlignVCenter);
        }
    }
    if (role == Qt::ToolTipRole) {
        const bool plain = reg->choices.isEmpty() && reg->bits.isEmpty();
        QString tip = plain ? tr("%1 to %2")
                                  .arg(feetech::displayValue(*reg, reg->minimum),
                                       feetech::displayValue(*reg, reg->maximum))
                            : tr("%1 to %2").arg(reg->minimum).arg(reg->maximum);
        if (plain && reg->scale != 1.0)
            tip += tr(", in steps of %1").arg(feetech::resolutionText(*reg));
        if (m_adjustments.contains(reg->key))
            tip += u'\n' + m_adjustments.value(reg->key);
        if (!reg->note.isEmpty())
            tip += u'\n' + feetech::tableText(reg->note);
        if (pending && device)
            tip += u'\n' + tr("On the servo: %1").arg(feetech::displayValue(*reg, qint32(*device)));
        return tip;
    }
    if (role == Qt::EditRole && index.column() == ValueColumn) {
        if (!shown)
            return QString();
        if (!reg->choices.isEmpty())
            return feetech::displayValue(*reg, qint32(*shown));
        return feetech::realNumber(*reg, qint32(*shown));
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (index.column()) {
    case AddressColumn:
        return reg->address;
    case KeyColumn:
        return reg->key;
    case LabelColumn:
        return feetech::tableText(reg->label);
    case SizeColumn:
        return reg->size;
    case AreaColumn:
        return reg->storage == feetech::Storage::Eeprom ? tr("EEPROM") : tr("RAM");
    case AccessColumn:
        return reg->writable() ? tr("RW") : tr("RO");
    case RawColumn: {
        if (!device)
            return tr("—");
        const auto raw = feetech::toRaw(qint32(*device), m_table->format(*reg));
        if (!raw)
            return QString();
        return QString(
            QStringLiteral("0x")
            + QStringLiteral("%1").arg(*raw, reg->size * 2, 16, QLatin1Char('0')).toUpper());
    }
    case ValueColumn:
        return shown ? feetech::displayValue(*reg, qint32(*shown)) : tr("—");
    case StateColumn:
        if (state == model::State::Clean)
            return QString();
        // A value put on the register's step says so in its row until the edit is dropped.
        return m_adjustments.contains(reg->key) ? snappedStateName(state)
                                                : model::ParameterModel::stateName(state);
    default:
        return {};
    }
}

bool RegisterTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    const feetech::Register *reg = registerAt(index.row());
    if (role != Qt::EditRole || index.column() != ValueColumn || !reg || !m_parameters)
        return false;
    const QString text = value.toString().trimmed();
    if (text.isEmpty())
        return false;
    QString error;
    QString adjusted;
    const auto raw = feetech::parseValue(*reg, text, &error, feetech::ValueUnits::Real, &adjusted);
    if (!raw) {
        emit editRefused(error);
        return false;
    }
    if (adjusted.isEmpty())
        m_adjustments.remove(reg->key);
    else
        m_adjustments.insert(reg->key, adjusted);
    if (!m_parameters->edit(reg->key, *raw, &error)) {
        m_adjustments.remove(reg->key);
        emit editRefused(error);
        return false;
    }
    // The row repaints (its state says "snapped") even when the value itself did not change.
    emit dataChanged(index.siblingAtColumn(0), index.siblingAtColumn(ColumnCount - 1));
    if (!adjusted.isEmpty())
        emit editAdjusted(adjusted);
    return true;
}

Qt::ItemFlags RegisterTableModel::flags(const QModelIndex &index) const
{
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    const feetech::Register *reg = registerAt(index.row());
    if (reg && index.column() == ValueColumn && m_editable && reg->writable() && !m_table->isRaw())
        flags |= Qt::ItemIsEditable;
    return flags;
}

QVariant RegisterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case AddressColumn:
        return tr("Addr");
    case KeyColumn:
        return tr("Key");
    case LabelColumn:
        return tr("Register");
    case SizeColumn:
        return tr("Size");
    case AreaColumn:
        return tr("Area");
    case AccessColumn:
        return tr("Access");
    case RawColumn:
        return tr("Raw");
    case ValueColumn:
        return tr("Value");
    case StateColumn:
        return tr("State");
    default:
        return {};
    }
}

QString RegisterTableModel::snappedStateName(model::State state)
{
    return tr("%1, snapped", "state of a register whose typed value was put on a step")
        .arg(model::ParameterModel::stateName(state));
}

void RegisterTableModel::parameterChanged(const QString &key)
{
    // A dropped edit (Revert, a servo read anew) takes its note with it.
    if (m_parameters && m_parameters->state(key) == model::State::Clean)
        m_adjustments.remove(key);
    const int row = rowOf(key);
    if (row >= 0)
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}
