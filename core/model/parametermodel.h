// The parameter model both servo families share: device values kept apart from pending edits.
#pragma once

#include <QAbstractTableModel>
#include <QHash>
#include <QString>
#include <QVector>

#include <optional>

namespace model {

enum class Access { ReadOnly, ReadWrite, WriteOnly };
enum class Storage { Eeprom, Ram, Ptk };

// Clean: no edit. Edited: an edit waits to be written. Writing: it is on its way. Verified /
// Mismatch: the read-back after a write matched / did not. Failed: the write did not go out, or
// a read-back shows the device kept its old value. Unknown: the write went out but no read-back
// answered, so whether it took effect is not known (the next read settles it).
enum class State { Clean, Edited, Writing, Verified, Mismatch, Failed, Unknown };

struct Choice
{
    qint64 value = 0;
    QString label;
};

// What never changes about a parameter. Values are held in device units ("raw"); what people
// see and type is raw × scale, in `unit`.
struct Definition
{
    QString key; // stable snake_case
    QString label; // already translated
    QString group;
    QString unit;
    double scale = 1.0;
    qint64 minimum = 0; // raw
    qint64 maximum = 0; // raw
    Access access = Access::ReadWrite;
    Storage storage = Storage::Ram;
    QVector<Choice> choices;
    QString note;
};

struct WriteItem
{
    QString key;
    qint64 value = 0; // raw
};

class ParameterModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        KeyColumn,
        LabelColumn,
        DeviceColumn,
        PendingColumn,
        UnitColumn,
        StateColumn,
        ColumnCount
    };
    enum Role { RawDeviceRole = Qt::UserRole + 1, RawPendingRole, StateRole, KeyRole };

    explicit ParameterModel(QObject *parent = nullptr);

    void setDefinitions(const QVector<Definition> &definitions);
    const QVector<Definition> &definitions() const { return m_definitions; }
    const Definition *definition(const QString &key) const;

    std::optional<qint64> deviceValue(const QString &key) const;
    std::optional<qint64> pendingValue(const QString &key) const;
    State state(const QString &key) const;
    qint64 lastReadMs(const QString &key) const; // 0: never read

    // A value read from the device. It never touches an edit in progress; after a write it is
    // the read-back that settles Verified or Mismatch.
    void setDeviceValue(const QString &key, qint64 raw, qint64 nowMs = 0);

    // A user's edit, range-checked; nothing changes and *error says why when it is refused.
    bool edit(const QString &key, qint64 raw, QString *error = nullptr);
    bool editScaled(const QString &key, double value, QString *error = nullptr);
    void revert(const QString &key);
    void revertAll();
    bool hasEdits() const;

    // The edits to write, in definition order; marks them Writing. Edits of the keys in
    // `except` stay edits (a Feetech ID or baud rate, written by a flow of its own later).
    QVector<WriteItem> takeWritePlan(const QStringList &except = {});
    // The write of `key` could not be sent (link failure, refused): the edit stays, Failed.
    void markFailed(const QString &key);
    // The write of `key` went out but its outcome is not known: the edit stays, Unknown, until
    // a read settles it (Verified when the device shows the written value, Failed otherwise).
    void markUnknown(const QString &key);

    static QString stateName(State state);

    // QAbstractTableModel
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

signals:
    void parameterChanged(const QString &key);

private:
    struct Entry
    {
        std::optional<qint64> device;
        std::optional<qint64> pending;
        std::optional<qint64> written; // what the last write sent, until the read-back
        State state = State::Clean;
        qint64 lastReadMs = 0;
    };

    int rowOf(const QString &key) const { return m_rows.value(key, -1); }
    void changed(int row);
    QString formatted(int row, qint64 raw) const;

    QVector<Definition> m_definitions;
    QVector<Entry> m_entries;
    QHash<QString, int> m_rows;
};

} // namespace model
