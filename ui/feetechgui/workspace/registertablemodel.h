// The memory table of one Feetech servo: every register of its table, bound to its parameter model.
#pragma once

#include <QAbstractTableModel>
#include <QHash>
#include <QPointer>

namespace feetech {
class RegisterTable;
struct Register;
} // namespace feetech
namespace model {
class ParameterModel;
enum class State;
} // namespace model

// Rows are the table's registers in address order; values and edits live in the parameter
// model, so the Settings form and this table always agree.
class RegisterTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column {
        AddressColumn,
        KeyColumn,
        LabelColumn,
        SizeColumn,
        AreaColumn,
        AccessColumn,
        RawColumn,
        ValueColumn,
        StateColumn,
        ColumnCount
    };
    // RegisterValueRole: the value shown, in register units (what an editor starts from).
    enum Role { KeyRole = Qt::UserRole + 1, PendingRole, RegisterValueRole };

    explicit RegisterTableModel(QObject *parent = nullptr);

    // Null table or model: an empty table.
    void setServo(const feetech::RegisterTable *table, model::ParameterModel *parameters);
    void setEditable(bool editable); // while the link is up and nothing else runs
    const feetech::Register *registerAt(int row) const;
    int rowOf(const QString &key) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // Why the edit of `key` is not what was typed (put on the register's step); empty if it is.
    QString adjustment(const QString &key) const { return m_adjustments.value(key); }
    // The state column of a row whose typed value was snapped: "Edited, snapped".
    static QString snappedStateName(model::State state);

signals:
    void editRefused(const QString &message);
    // A typed value became the nearest step of its register: the sentence that says so.
    void editAdjusted(const QString &note);

private:
    void parameterChanged(const QString &key);

    const feetech::RegisterTable *m_table = nullptr;
    QPointer<model::ParameterModel> m_parameters;
    bool m_editable = false;
    QHash<QString, QString> m_adjustments; // by key, until the edit is dropped or made again
};
