// A bounded, batched table of every frame in and out of a link, for the packet log view.
#pragma once

#include "linktypes.h"

#include <QAbstractTableModel>
#include <QTimer>

#include <chrono>
#include <deque>

class QIODevice;

namespace seriallink {

// Frames can arrive by the thousand per second, so appends are queued and inserted together
// by a short timer, and the oldest rows go once `capacity` is reached. QtCore only: a view
// colours error rows itself from HasErrorRole.
class PacketLogModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        TimeColumn,
        DirectionColumn,
        BytesColumn,
        MeaningColumn,
        ErrorColumn,
        ColumnCount
    };
    enum Role { HasErrorRole = Qt::UserRole + 1, DirectionRole, TimestampRole, RawBytesRole };

    static constexpr int kDefaultCapacity = 20000;
    static constexpr std::chrono::milliseconds kDefaultBatchInterval {50};

    explicit PacketLogModel(QObject *parent = nullptr);

    // Queues an entry; it shows within one batch interval unless the log is paused.
    void append(const PacketLogEntry &entry);
    // Inserts what is queued now (nothing while paused).
    void flush();

    int capacity() const { return m_capacity; }
    void setCapacity(int capacity); // at least 1; drops the oldest rows at once if needed
    std::chrono::milliseconds batchInterval() const;
    void setBatchInterval(std::chrono::milliseconds interval);

    // While paused the rows and counts that views see stay as they are; what arrives meanwhile
    // is held (within capacity) and shows on resume.
    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    int heldCount() const { return int(m_queue.size()); }

    void clear();

    // Every entry appended since the last clear(), including those already dropped for
    // capacity and those held while paused.
    int totalCount() const { return m_totalCount; }
    int errorCount() const { return m_errorCount; }
    // Errors dropped for capacity: ordinary rows go first, so errors stay longer, but not
    // forever (they may take half of the log).
    int droppedErrorCount() const { return m_droppedErrors; }

    const PacketLogEntry &entry(int row) const { return m_rows.at(std::size_t(row)); }

    // Tab-separated text, one header line then one line per row shown (queued entries are
    // inserted first unless paused). *error says why when it fails.
    bool exportTo(QIODevice &device, QString *error = nullptr);
    bool exportToFile(const QString &path, QString *error = nullptr);

    static QString directionName(Direction direction);

    // QAbstractTableModel
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    // After a batch went in, a clear, or a resume: what totalCount() / errorCount() say now.
    void countsChanged(int total, int errors);

private:
    // Drops `count` rows for capacity, ordinary ones first.
    void dropOldest(int count);
    void trimQueue();

    std::deque<PacketLogEntry> m_rows;
    int m_droppedErrors = 0;
    std::deque<PacketLogEntry> m_queue;
    QTimer m_batchTimer;
    int m_capacity = kDefaultCapacity;
    int m_totalCount = 0;
    int m_errorCount = 0;
    bool m_paused = false;
};

} // namespace seriallink
