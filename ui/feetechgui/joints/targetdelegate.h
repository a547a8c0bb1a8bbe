// The editor of the joint table's target cells: a spin box limited to where the servo may be
// sent, and a dash in a cell nobody has given a target.
#pragma once

#include <QStyledItemDelegate>

class TargetDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    // Roles of a target cell that the editor reads.
    enum Role {
        MinimumRole = Qt::UserRole + 1,
        MaximumRole,
        SuggestionRole, // where the editor starts in a cell without a target
    };

    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                          const QModelIndex &index) const override;
    void setEditorData(QWidget *widget, const QModelIndex &index) const override;
    void setModelData(QWidget *widget, QAbstractItemModel *model,
                      const QModelIndex &index) const override;
    void updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                              const QModelIndex &index) const override;

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override;
};
