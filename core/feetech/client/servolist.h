// The servos found on a Feetech bus, each with its parameter model, as a table model views show.
#pragma once

#include "bustypes.h"
#include "parametermodel.h"

#include <QAbstractTableModel>
#include <QVector>

#include <memory>
#include <optional>
#include <vector>

namespace feetech {

struct Servo
{
    ServoInfo info;
    std::unique_ptr<model::ParameterModel> parameters;
    std::optional<quint8> statusByte; // of its last reply
    bool read = false; // its table has been read at least once
};

// Belongs to a BusClient (BusClient::servos()), on the GUI thread. Fastest rate first, then by
// ID: the order the servo tree shows. A row's index changes when the list does (servosChanged);
// a servo is known by its ID and rate (indexOf).
class ServoList : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { IdColumn, BaudColumn, ModelColumn, FamilyColumn, FirmwareColumn, ColumnCount };

    explicit ServoList(QObject *parent = nullptr);
    ~ServoList() override;

    int count() const { return int(m_servos.size()); }
    const Servo &at(int index) const { return *m_servos.at(std::size_t(index)); }
    model::ParameterModel *parameters(int index) const;
    int indexOf(const ServoAddress &address) const; // -1 when not known
    QVector<int> idsInUse() const; // at every baud rate scanned
    // Whether servo `index`'s EEPROM lock reads open (lock = 0) in its last read; false when it
    // is locked, not read yet or has no lock register.
    bool eepromUnlocked(int index) const;

    // For the client and its services: a servo found, moved (a new ID or rate), changed in
    // place (new values, status, what it may do), or the whole list gone. A move takes the
    // place of any other entry at the new ID and rate, and may change every index.
    void add(const ServoInfo &info);
    void move(int index, const ServoInfo &info);
    Servo &entry(int index) { return *m_servos.at(std::size_t(index)); }
    void noteUpdated(int index);
    // A servo that no longer answers where it was listed (a check found nothing there).
    void remove(int index);
    void clear();

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    void servosChanged(); // the list itself: added, removed, or moved to another ID or baud
    void servoUpdated(int index); // new values or status for this servo

private:
    void sort();

    std::vector<std::unique_ptr<Servo>> m_servos;
};

} // namespace feetech
