// The Memory table page: every register of the servo shown, filtered, edited, read and applied.
#pragma once

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;
class RegisterTableModel;

namespace feetech {
class BusClient;
} // namespace feetech

namespace model {
class ParameterModel;
} // namespace model

// The page asks for reads, applies and reverts; the workspace, which knows the servo shown and
// confirms address changes, does them.
class MemoryTablePage : public QWidget
{
    Q_OBJECT

public:
    explicit MemoryTablePage(QWidget *parent = nullptr);

    // Shows the registers of the client's servo `index` (-1: none, with a hint instead).
    void showServo(const feetech::BusClient &client, int index);
    void setEmptyStateShown(bool shown);
    void updateActions(bool ready, bool known, bool edits, bool idle, bool editable);
    // Whether the RAM rows should be read again while the page is on screen.
    bool refreshesLive() const;

    QTableView *table() const { return m_table; }

signals:
    void readRequested();
    void applyRequested();
    void revertRequested();
    void problem(const QString &message);

private:
    RegisterTableModel *m_registers = nullptr;
    QSortFilterProxyModel *m_filter = nullptr;
    QTableView *m_table = nullptr;
    QLineEdit *m_filterEdit = nullptr;
    QCheckBox *m_live = nullptr;
    QLabel *m_empty = nullptr; // the hint while no servo is chosen
    QLabel *m_note = nullptr; // a typed value that was put on its register's step
    QPointer<model::ParameterModel> m_shownParameters;
    QPushButton *m_read = nullptr;
    QPushButton *m_revert = nullptr;
    QPushButton *m_apply = nullptr;
};
