// Memory table value editor: register spin boxes for numbers, text for the rest.
#include "registervaluedelegate.h"

#include "registerspinbox.h"
#include "registertable.h"
#include "registertablemodel.h"

namespace {

constexpr char kFilled[] = "servobenchEditorFilled";

// A number people type, not a choice, a bit field or a rate typed in bits per second.
bool isPlainNumber(const feetech::Register &reg)
{
    return reg.choices.isEmpty() && reg.bits.isEmpty() && reg.key != u"baud_rate";
}

} // namespace

RegisterValueDelegate::RegisterValueDelegate(const RegisterTableModel *registers, QObject *parent)
    : QStyledItemDelegate(parent)
    , m_registers(registers)
{ }

QWidget *RegisterValueDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                             const QModelIndex &index) const
{
    const QString key = index.data(RegisterTableModel::KeyRole).toString();
    const feetech::Register *reg = m_registers->registerAt(m_registers->rowOf(key));
    if (!reg || !isPlainNumber(*reg))
        return QStyledItemDelegate::createEditor(parent, option, index);
    auto *spin = new RegisterSpinBox(parent);
    spin->setObjectName(QStringLiteral("registerValueEditor"));
    spin->setFrame(false);
    spin->setRegister(reg, false);
    return spin;
}

void RegisterValueDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    // Filled once, as it opens: the view fills it again at every change of the register (a live
    // refresh of RAM, several a second), which would wipe out what is being typed.
    if (editor->property(kFilled).toBool())
        return;
    editor->setProperty(kFilled, true);
    auto *spin = qobject_cast<RegisterSpinBox *>(editor);
    if (!spin) {
        QStyledItemDelegate::setEditorData(editor, index);
        return;
    }
    const QVariant value = index.data(RegisterTableModel::RegisterValueRole);
    spin->setValue(value.isValid() ? value.toInt() : spin->minimum());
}

void RegisterValueDelegate::setModelData(QWidget *editor, QAbstractItemModel *model,
                                         const QModelIndex &index) const
{
    auto *spin = qobject_cast<RegisterSpinBox *>(editor);
    if (!spin) {
        QStyledItemDelegate::setModelData(editor, model, index);
        return;
    }
    // As typed: the model puts it on a step and says so.
    model->setData(index, spin->typedText(), Qt::EditRole);
}
