// The servos found on a Feetech bus: the list, its order, and the table model over it.
#include "servolist.h"

#include "servoparameters.h"

#include <QCoreApplication>

#include <algorithm>

namespace {

struct FeetechServoListTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechServoList)
};

} // namespace

namespace feetech {

ServoList::ServoList(QObject *parent)
    : QAbstractTableModel(parent)
{ }

ServoList::~ServoList() = default;

model::ParameterModel *ServoList::parameters(int index) const
{
    if (index < 0 || index >= count())
        return nullptr;
    return m_servos.at(std::size_t(index))->parameters.get();
}

int ServoList::indexOf(const ServoAddress &address) const
{
    for (int i = 0; i < count(); ++i) {
        if (at(i).info.address() == address)
            return i;
    }
    return -1;
}

QVector<int> ServoList::idsInUse() const
{
    QVector<int> ids;
    for (const auto &entry : m_servos)
        ids.append(entry->info.id);
    return ids;
}

bool ServoList::eepromUnlocked(int index) const
{
    if (index < 0 || index >= count() || !at(index).read)
        return false;
    const model::ParameterModel *model = at(index).parameters.get();
    const auto lock = model ? model->deviceValue(QStringLiteral("lock")) : std::nullopt;
    return lock && *lock == 0;
}

void ServoList::add(const ServoInfo &info)
{
    auto entry = std::make_unique<Servo>();
    entry->info = info;
    if (info.statusBits != 0) // the scan's answer showed error bits: the tree shows them
        entry->statusByte = info.statusBits;
    entry->parameters = std::make_unique<model::ParameterModel>();
    entry->parameters->setDefinitions(modelDefinitions(info.table()));
    beginResetModel();
    m_servos.push_back(std::move(entry));
    sort();
    endResetModel();
    emit servosChanged();
}

void ServoList::move(int index, const ServoInfo &info)
{
    if (index < 0 || index >= count())
        return;
    const Servo *moved = m_servos.at(std::size_t(index)).get();
    const bool sameAddress = moved->info.address() == info.address();
    beginResetModel();
    m_servos.at(std::size_t(index))->info = info;
    // The servo answers at its new address now, so an entry left there (a servo scanned earlier
    // and unplugged since, whose ID a flow could therefore give) is no servo on the bus.
    if (!sameAddress) {
        m_servos.erase(std::remove_if(m_servos.begin(), m_servos.end(),
                                      [moved, &info](const auto &entry) {
                                          return entry.get() != moved
                                              && entry->info.address() == info.address();
                                      }),
                       m_servos.end());
    }
    sort();
    endResetModel();
    emit servosChanged();
}

void ServoList::sort()
{
    // Fastest rate first, then by ID: the order the tree shows.
    std::stable_sort(m_servos.begin(), m_servos.end(), [](const auto &a, const auto &b) {
        return a->info.baud != b->info.baud ? a->info.baud > b->info.baud : a->info.id < b->info.id;
    });
}

void ServoList::noteUpdated(int index)
{
    if (index < 0 || index >= count())
        return;
    emit servoUpdated(index);
}

void ServoList::remove(int index)
{
    if (index < 0 || index >= count())
        return;
    beginResetModel();
    m_servos.erase(m_servos.begin() + index);
    endResetModel();
    emit servosChanged();
}

void ServoList::clear()
{
    if (m_servos.empty())
        return;
    beginResetModel();
    m_servos.clear();
    endResetModel();
    emit servosChanged();
}

int ServoList::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : count();
}

int ServoList::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ServoList::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= count() || role != Qt::DisplayRole)
        return {};
    const ServoInfo &info = at(index.row()).info;
    switch (index.column()) {
    case IdColumn:
        return info.id;
    case BaudColumn:
        return info.baud;
    case ModelColumn:
        return info.model.name;
    case FamilyColumn:
        return info.model.family ? familyName(*info.model.family) : QString();
    case FirmwareColumn:
        return info.firmware();
    default:
        return {};
    }
}

QVariant ServoList::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case IdColumn:
        return FeetechServoListTr::tr("ID");
    case BaudColumn:
        return FeetechServoListTr::tr("Rate");
    case ModelColumn:
        return FeetechServoListTr::tr("Model");
    case FamilyColumn:
        return FeetechServoListTr::tr("Family");
    case FirmwareColumn:
        return FeetechServoListTr::tr("Firmware");
    default:
        return {};
    }
}

} // namespace feetech
