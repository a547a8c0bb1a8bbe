// Packet log model: batched inserts, a capacity bound, pause, counts and tab-separated export.
#include "packetlogmodel.h"

#include "hex.h"
#include "savefile.h"

#include <QDateTime>
#include <QIODevice>

#include <algorithm>
#include <iterator>

namespace seriallink {

namespace {

// Export lines are one record each: tabs and line breaks inside text would split them.
QString oneField(QString text)
{
    for (QChar &c : text) {
        if (c == u'\t' || c == u'\n' || c == u'\r')
            c = u' ';
    }
    return text;
}

// Stable tokens in exported files, so scripts and diffs do not depend on the UI language.
QLatin1String directionToken(Direction direction)
{
    switch (direction) {
    case Direction::Out:
        return QLatin1String("out");
    case Direction::In:
        return QLatin1String("in");
    case Direction::Echo:
        return QLatin1String("echo");
    case Direction::Stray:
        return QLatin1String("stray");
    }
    return QLatin1String("?");
}

} // namespace

PacketLogModel::PacketLogModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_batchTimer.setSingleShot(true);
    m_batchTimer.setInterval(kDefaultBatchInterval);
    connect(&m_batchTimer, &QTimer::timeout, this, &PacketLogModel::flush);
}

void PacketLogModel::append(const PacketLogEntry &entry)
{
    ++m_totalCount;
    if (!entry.error.isEmpty())
        ++m_errorCount;
    m_queue.push_back(entry);
    trimQueue();
    // One timer run per batch, not per frame: a burst costs one insert.
    if (!m_paused && !m_batchTimer.isActive())
        m_batchTimer.start();
}

void PacketLogModel::flush()
{
    m_batchTimer.stop();
    if (m_paused || m_queue.empty())
        return;

    const int incoming = int(m_queue.size()); // trimQueue() keeps this <= capacity
    dropOldest(int(m_rows.size()) + incoming - m_capacity);
    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + incoming - 1);
    std::move(m_queue.begin(), m_queue.end(), std::back_inserter(m_rows));
    m_queue.clear();
    endInsertRows();
    emit countsChanged(m_totalCount, m_errorCount);
}

void PacketLogModel::dropOldest(int count)
{
    if (count <= 0)
        return;
    // Errors are what people look for among thousands of frames: ordinary rows go first, while
    // errors take at most half of the log; past that the oldest rows go, errors or not.
    const auto isError = [](const PacketLogEntry &entry) {
        return !entry.error.isEmpty();
    };
    const int errors = int(std::count_if(m_rows.begin(), m_rows.end(), isError));
    if (errors > m_capacity / 2 || int(m_rows.size()) - errors < count) {
        const int dropped = std::min(count, int(m_rows.size()));
        m_droppedErrors += int(std::count_if(m_rows.begin(), m_rows.begin() + dropped, isError));
        beginRemoveRows({}, 0, dropped - 1);
        m_rows.erase(m_rows.begin(), m_rows.begin() + dropped);
        endRemoveRows();
        return;
    }
    // Runs of ordinary rows from the oldest, each removed as one range.
    int row = 0;
    while (count > 0) {
        while (isError(m_rows.at(std::size_t(row))))
            ++row;
        int end = row;
        while (end < int(m_rows.size()) && end - row < count
               && !isError(m_rows.at(std::size_t(end))))
            ++end;
        beginRemoveRows({}, row, end - 1);
        m_rows.erase(m_rows.begin() + row, m_rows.begin() + end);
        endRemoveRows();
        count -= end - row;
    }
}

std::chrono::milliseconds PacketLogModel::batchInterval() const
{
    return m_batchTimer.intervalAsDuration();
}

void PacketLogModel::setBatchInterval(std::chrono::milliseconds interval)
{
    m_batchTimer.setInterval(std::max(interval, std::chrono::milliseconds::zero()));
}

void PacketLogModel::setCapacity(int capacity)
{
    m_capacity = std::max(capacity, 1);
    trimQueue();
    // Only the rows views already have are removed; while paused the held entries stay held.
    if (!m_paused)
        dropOldest(int(m_rows.size()) - m_capacity);
}

void PacketLogModel::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    m_paused = paused;
    if (paused) {
        m_batchTimer.stop();
        return;
    }
    // Rows may exceed a capacity lowered while paused; the flush below brings them back in.
    const int overflow = int(m_rows.size()) - m_capacity;
    if (overflow > 0) {
        beginRemoveRows({}, 0, overflow - 1);
        m_rows.erase(m_rows.begin(), m_rows.begin() + overflow);
        endRemoveRows();
    }
    flush();
}

void PacketLogModel::clear()
{
    m_batchTimer.stop();
    beginResetModel();
    m_rows.clear();
    m_queue.clear();
    endResetModel();
    m_totalCount = 0;
    m_errorCount = 0;
    m_droppedErrors = 0;
    emit countsChanged(m_totalCount, m_errorCount);
}

void PacketLogModel::trimQueue()
{
    const int overflow = int(m_queue.size()) - m_capacity;
    if (overflow > 0)
        m_queue.erase(m_queue.begin(), m_queue.begin() + overflow);
}

bool PacketLogModel::exportTo(QIODevice &device, QString *error)
{
    flush();
    const auto fail = [&] {
        if (error)
            *error = device.errorString().isEmpty() ? tr("The log could not be written.")
                                                    : device.errorString();
        return false;
    };
    if (!device.isOpen() && !device.open(QIODevice::WriteOnly | QIODevice::Text))
        return fail();
    if (device.write("time\tdirection\thex\tmeaning\terror\n") < 0)
        return fail();
    for (const PacketLogEntry &entry : m_rows) {
        const QString line = QDateTime::fromMSecsSinceEpoch(entry.timestampMs)
                                 .toString(QStringLiteral("yyyy-MM-dd hh:mm:ss.zzz"))
            + u'\t' + directionToken(entry.direction) + u'\t' + util::toHex(entry.bytes) + u'\t'
            + oneField(entry.summary) + u'\t' + oneField(entry.error) + u'\n';
        if (device.write(line.toUtf8()) < 0)
            return fail();
    }
    return true;
}

bool PacketLogModel::exportToFile(const QString &path, QString *error)
{
    // QSaveFile: an export that fails half-way never leaves a truncated file behind.
    util::SavingFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    QString why;
    if (!exportTo(file.device(), &why)) {
        file.cancel();
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, why);
        return false;
    }
    if (!file.commit()) {
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

QString PacketLogModel::directionName(Direction direction)
{
    switch (direction) {
    case Direction::Out:
        return tr("→ out");
    case Direction::In:
        return tr("← in");
    case Direction::Echo:
        return tr("echo");
    case Direction::Stray:
        return tr("stray");
    }
    return QString();
}

int PacketLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int PacketLogModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant PacketLogModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const PacketLogEntry &entry = m_rows.at(std::size_t(index.row()));
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case TimeColumn:
            return QDateTime::fromMSecsSinceEpoch(entry.timestampMs)
                .toString(QStringLiteral("hh:mm:ss.zzz"));
        case DirectionColumn:
            return directionName(entry.direction);
        case BytesColumn:
            return util::toHex(entry.bytes);
        case MeaningColumn:
            return entry.summary;
        case ErrorColumn:
            return entry.error;
        default:
            return {};
        }
    case Qt::ToolTipRole:
        if (index.column() == BytesColumn)
            return tr("%n byte(s)", nullptr, int(entry.bytes.size()));
        if (index.column() == TimeColumn)
            return QDateTime::fromMSecsSinceEpoch(entry.timestampMs)
                .toString(QStringLiteral("yyyy-MM-dd hh:mm:ss.zzz"));
        return {};
    case HasErrorRole:
        return !entry.error.isEmpty();
    case DirectionRole:
        return int(entry.direction);
    case TimestampRole:
        return entry.timestampMs;
    case RawBytesRole:
        return entry.bytes;
    default:
        return {};
    }
}

QVariant PacketLogModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case TimeColumn:
        return tr("Time");
    case DirectionColumn:
        return tr("Direction");
    case BytesColumn:
        return tr("Bytes");
    case MeaningColumn:
        return tr("Meaning");
    case ErrorColumn:
        return tr("Error");
    default:
        return {};
    }
}

} // namespace seriallink
