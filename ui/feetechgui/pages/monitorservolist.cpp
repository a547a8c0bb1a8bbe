// The Monitor page's servo list: rows built from the bus client, ticks by ID and baud rate.
#include "monitorservolist.h"

#include "busclient.h"

namespace {

constexpr int kIdRole = Qt::UserRole + 1;
constexpr int kBaudRole = Qt::UserRole + 2;
constexpr int kIndexRole = Qt::UserRole + 3;

} // namespace

MonitorServoList::MonitorServoList(QWidget *parent)
    : QListWidget(parent)
{
    setObjectName(QStringLiteral("monitorServoList"));
    setToolTip(tr("The servos to stream; ticking or unticking one while streaming restarts the "
                  "stream"));
    setMinimumHeight(fontMetrics().height() * 6);
    connect(this, &QListWidget::itemChanged, this, [this] {
        if (!m_updating)
            emit ticksChanged();
    });
}

void MonitorServoList::rebuild(const feetech::BusClient *client)
{
    QHash<feetech::ServoAddress, bool> previous;
    for (int row = 0; row < count(); ++row)
        previous.insert(keyOf(item(row)), item(row)->checkState() == Qt::Checked);
    m_updating = true;
    clear();
    const int servos = client ? client->servos()->count() : 0;
    m_names = client ? feetech::JointNames::of(*client) : feetech::JointNames();
    for (int index = 0; index < servos; ++index) {
        const feetech::ServoInfo &info = client->servos()->at(index).info;
        const QString model = info.model.name.isEmpty() ? tr("unknown model") : info.model.name;
        auto *entry = new QListWidgetItem(
            tr("%1 · %2 · %3")
                .arg(m_names.label(info.address()), model, feetech::baudText(info.baud)),
            this);
        entry->setData(kIdRole, info.id);
        entry->setData(kBaudRole, info.baud);
        entry->setData(kIndexRole, index);
        if (info.hasTable()) {
            entry->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            entry->setCheckState(previous.value(info.address(), true) ? Qt::Checked
                                                                      : Qt::Unchecked);
        } else {
            // Without the family's table the feedback block cannot be decoded.
            entry->setFlags(Qt::ItemIsUserCheckable);
            entry->setCheckState(Qt::Unchecked);
            entry->setToolTip(tr("Unknown model: its feedback cannot be decoded"));
        }
    }
    m_updating = false;
    if (count() == 0) {
        auto *hint = new QListWidgetItem(tr("Scan the bus to find servos."), this);
        hint->setFlags(Qt::NoItemFlags);
    }
}

void MonitorServoList::setSelectedServos(const QVector<int> &indexes)
{
    m_updating = true;
    for (int row = 0; row < count(); ++row) {
        QListWidgetItem *entry = item(row);
        if (entry->flags() & Qt::ItemIsUserCheckable) {
            entry->setCheckState(indexes.contains(entry->data(kIndexRole).toInt()) ? Qt::Checked
                                                                                   : Qt::Unchecked);
        }
    }
    m_updating = false;
    emit ticksChanged();
}

QVector<int> MonitorServoList::selectedServos() const
{
    QVector<int> indexes;
    for (int row = 0; row < count(); ++row) {
        if (item(row)->checkState() == Qt::Checked)
            indexes.append(item(row)->data(kIndexRole).toInt());
    }
    return indexes;
}

QVector<feetech::ServoAddress> MonitorServoList::checkedKeys() const
{
    QVector<feetech::ServoAddress> keys;
    for (int row = 0; row < count(); ++row) {
        if (item(row)->checkState() == Qt::Checked)
            keys.append(keyOf(item(row)));
    }
    return keys;
}

bool MonitorServoList::isListed(const feetech::ServoAddress &key) const
{
    for (int row = 0; row < count(); ++row) {
        if ((item(row)->flags() & Qt::ItemIsUserCheckable) && keyOf(item(row)) == key)
            return true;
    }
    return false;
}

QHash<feetech::ServoAddress, bool> MonitorServoList::ticks() const
{
    QHash<feetech::ServoAddress, bool> ticks;
    for (int row = 0; row < count(); ++row) {
        if (item(row)->flags() & Qt::ItemIsUserCheckable)
            ticks.insert(keyOf(item(row)), item(row)->checkState() == Qt::Checked);
    }
    return ticks;
}

feetech::ServoAddress MonitorServoList::keyOf(const QListWidgetItem *entry) const
{
    return {quint8(entry->data(kIdRole).toInt()), entry->data(kBaudRole).toInt()};
}
