// Range-limited target editing for the joint table.
#include "targetdelegate.h"

#include <QSpinBox>

QWidget *TargetDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &,
                                      const QModelIndex &index) const
{
    auto *editor = new QSpinBox(parent);
    editor->setObjectName(QStringLiteral("targetEditor"));
    editor->setFrame(false);
    editor->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    editor->setRange(index.data(MinimumRole).toInt(), index.data(MaximumRole).toInt());
    return editor;
}

void TargetDelegate::setEditorData(QWidget *widget, const QModelIndex &index) const
{
    auto *editor = static_cast<QSpinBox *>(widget);
    const QVariant target = index.data(Qt::EditRole);
    editor->setValue(target.isValid() ? target.toInt() : index.data(SuggestionRole).toInt());
    editor->selectAll();
}

void TargetDelegate::setModelData(QWidget *widget, QAbstractItemModel *model,
                                  const QModelIndex &index) const
{
    auto *editor = static_cast<QSpinBox *>(widget);
    editor->interpretText();
    model->setData(index, editor->value(), Qt::EditRole);
}

void TargetDelegate::updateEditorGeometry(QWidget *editor, const QStyleOptionViewItem &option,
                                          const QModelIndex &) const
{
    editor->setGeometry(option.rect);
}

void TargetDelegate::initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const
{
    QStyledItemDelegate::initStyleOption(option, index);
    // A number in a cell nobody gave a target would look like one somebody chose.
    if (!index.data(Qt::EditRole).isValid()) {
        option->text = QStringLiteral("—");
        option->displayAlignment = Qt::AlignCenter;
    }
}
