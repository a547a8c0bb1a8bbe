// The Memory table's value editor: a register spin box in the register's unit for numbers.
#pragma once

#include <QStyledItemDelegate>

class RegisterTableModel;

// Numbers are edited in the register's real unit, one step of the register per arrow; what was
// typed goes to the model as typed, so a value between two steps is snapped there, with a note.
// Choices, bit fields and the baud rate keep the plain text editor.
class RegisterValueDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    RegisterValueDelegate(const RegisterTableModel *registers, QObject *parent = nullptr);

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model,
                      const QModelIndex &index) const override;

private:
    const RegisterTableModel *m_registers = nullptr;
};
