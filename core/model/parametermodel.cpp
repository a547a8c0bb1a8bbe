// Parameter model: device value vs pending edit, states, range checks and write plans.
#include "parametermodel.h"

#include <QCoreApplication>

#include <cmath>

namespace model {

ParameterModel::ParameterModel(QObject *parent)
    : QAbstractTableModel(parent)
{ }

void ParameterModel::setDefinitions(const QVector<Definition> &definitions)
{
    beginResetModel();
    m_definitions = definitions;
    m_entries = QVector<Entry>(definitions.size());
    m_rows.clear();
    for (int row = 0; row < definitions.size(); ++row)
        m_rows.insert(definitions.at(row).key, row);
    endResetModel();
}

const Definition *ParameterModel::definition(const QString &key) const
{
    const int row = rowOf(key);
    return row < 0 ? nullptr : &m_definitions.at(row);
}

std::optional<qint64> ParameterModel::deviceValue(const QString &key) const
{
    const int row = rowOf(key);
    return row < 0 ? std::nullopt : m_entries.at(row).device;
}

std::optional<qint64> ParameterModel::pendingValue(const QString &key) const
{
    const int row = rowOf(key);
    return row < 0 ? std::nullopt : m_entries.at(row).pending;
}

State ParameterModel::state(const QString &key) const
{
    const int row = rowOf(key);
    return row < 0 ? State::Clean : m_entries.at(row).state;
}

qint64 ParameterModel::lastReadMs(const QString &key) const
{
    const int row = rowOf(key);
    return row < 0 ? 0 : m_entries.at(row).lastReadMs;
}

void ParameterModel::setDeviceValue(const QString &key, qint64 raw, qint64 nowMs)
{
    const int row = rowOf(key);
    if (row < 0)
        return;
    Entry &entry = m_entries[row];
    entry.device = raw;
    entry.lastReadMs = nowMs;
    if (entry.state == State::Writing && entry.written) {
        entry.state = *entry.written == raw ? State::Verified : State::Mismatch;
        entry.written.reset();
    } else if (entry.state == State::Unknown && entry.written) {
        // A later read settles a write whose outcome was unknown.
        if (*entry.written == raw) {
            entry.state = State::Verified;
            if (entry.pending == entry.written)
                entry.pending.reset();
        } else {
            entry.state = State::Failed;
        }
        entry.written.reset();
    }
    changed(row);
}

bool ParameterModel::edit(const QString &key, qint64 raw, QString *error)
{
    const int row = rowOf(key);
    const auto fail = [&](const QString &what) {
        if (error)
            *error = what;
        return false;
    };
    if (row < 0)
        return fail(tr("unknown parameter \"%1\"").arg(key));
    const Definition &meta = m_definitions.at(row);
    if (meta.access == Access::ReadOnly)
        return fail(tr("%1 is read-only").arg(meta.label));
    if (raw < meta.minimum || raw > meta.maximum)
        return fail(
            tr("%1 must be between %2 and %3")
                .arg(meta.label, formatted(row, meta.minimum), formatted(row, meta.maximum)));
    Entry &entry = m_entries[row];
    if (entry.device && *entry.device == raw) {
        // Typing the device's own value back is no edit.
        entry.pending.reset();
        entry.state = State::Clean;
    } else {
        entry.pending = raw;
        entry.state = State::Edited;
    }
    changed(row);
    return true;
}

bool ParameterModel::editScaled(const QString &key, double value, QString *error)
{
    const Definition *meta = definition(key);
    if (!meta || !std::isfinite(value))
        return edit(key, meta ? meta->maximum + 1 : 0, error);
    return edit(key, std::llround(value / meta->scale), error);
}

void ParameterModel::revert(const QString &key)
{
    const int row = rowOf(key);
    if (row < 0)
        return;
    Entry &entry = m_entries[row];
    entry.pending.reset();
    entry.written.reset();
    entry.state = State::Clean;
    changed(row);
}

void ParameterModel::revertAll()
{
    for (const Definition &meta : std::as_const(m_definitions))
        revert(meta.key);
}

bool ParameterModel::hasEdits() const
{
    for (const Entry &entry : m_entries) {
        if (entry.pending)
            return true;
    }
    return false;
}

QVector<WriteItem> ParameterModel::takeWritePlan(const QStringList &except)
{
    QVector<WriteItem> plan;
    for (int row = 0; row < m_entries.size(); ++row) {
        Entry &entry = m_entries[row];
        if (!entry.pending || except.contains(m_definitions.at(row).key))
            continue;
        plan.append({m_definitions.at(row).key, *entry.pending});
        entry.written = entry.pending;
        entry.pending.reset();
        entry.state = State::Writing;
        changed(row);
    }
    return plan;
}

void ParameterModel::markFailed(const QString &key)
{
    const int row = rowOf(key);
    if (row < 0)
        return;
    Entry &entry = m_entries[row];
    if (entry.written && !entry.pending)
        entry.pending = entry.written; // keep what the user asked for, to try again
    entry.written.reset();
    entry.state = State::Failed;
    changed(row);
}

void ParameterModel::markUnknown(const QString &key)
{
    const int row = rowOf(key);
    if (row < 0)
        return;
    Entry &entry = m_entries[row];
    if (entry.written && !entry.pending)
        entry.pending = entry.written; // an Apply would write it again; a read may settle it
    entry.state = State::Unknown;
    changed(row);
}

QString ParameterModel::stateName(State state)
{
    switch (state) {
    case State::Clean:
        return QString();
    case State::Edited:
        return tr("Edited");
    case State::Writing:
        return tr("Writing");
    case State::Verified:
        return tr("Verified");
    case State::Mismatch:
        return tr("Mismatch");
    case State::Failed:
        return tr("Failed");
    case State::Unknown:
        return tr("Unknown");
    }
    return QString();
}

void ParameterModel::changed(int row)
{
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    emit parameterChanged(m_definitions.at(row).key);
}

QString ParameterModel::formatted(int row, qint64 raw) const
{
    const Definition &meta = m_definitions.at(row);
    for (const Choice &choice : meta.choices) {
        if (choice.value == raw)
            return choice.label;
    }
    const double value = double(raw) * meta.scale;
    QString text = meta.scale == 1.0 ? QString::number(raw) : QString::number(value, 'g', 10);
    if (!meta.unit.isEmpty())
        text += u' ' + meta.unit;
    return text;
}

int ParameterModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_definitions.size());
}

int ParameterModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ParameterModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_definitions.size())
        return {};
    const Definition &meta = m_definitions.at(index.row());
    const Entry &entry = m_entries.at(index.row());
    switch (role) {
    case RawDeviceRole:
        return entry.device ? QVariant(*entry.device) : QVariant();
    case RawPendingRole:
        return entry.pending ? QVariant(*entry.pending) : QVariant();
    case StateRole:
        return int(entry.state);
    case KeyRole:
        return meta.key;
    case Qt::DisplayRole:
        switch (index.column()) {
        case KeyColumn:
            return meta.key;
        case LabelColumn:
            return meta.label;
        case DeviceColumn:
            return entry.device ? formatted(index.row(), *entry.device) : QString();
        case PendingColumn:
            return entry.pending ? formatted(index.row(), *entry.pending) : QString();
        case UnitColumn:
            return meta.unit;
        case StateColumn:
            return stateName(entry.state);
        default:
            return {};
        }
    case Qt::ToolTipRole:
        return meta.note.isEmpty() ? tr("%1: %2 to %3")
                                         .arg(meta.label, formatted(index.row(), meta.minimum),
                                              formatted(index.row(), meta.maximum))
                                   : meta.note;
    default:
        return {};
    }
}

QVariant ParameterModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case KeyColumn:
        return tr("Key");
    case LabelColumn:
        return tr("Parameter");
    case DeviceColumn:
        return tr("Device");
    case PendingColumn:
        return tr("Edit");
    case UnitColumn:
        return tr("Unit");
    case StateColumn:
        return tr("State");
    default:
        return {};
    }
}

} // namespace model
