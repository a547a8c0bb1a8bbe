// Profile diff dialog: one row per parameter the file would change.
#include "profilediffdialog.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

QString shown(const model::Definition &definition, qint64 raw)
{
    for (const model::Choice &choice : definition.choices) {
        if (choice.value == raw)
            return choice.label;
    }
    QString text = QString::number(double(raw) * definition.scale);
    if (!definition.unit.isEmpty())
        text += u' ' + definition.unit;
    return text;
}

} // namespace

ProfileDiffDialog::ProfileDiffDialog(const QString &fileName, const QVector<profile::DiffRow> &rows,
                                     const model::ParameterModel &parameters, QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Load profile"));
    setObjectName(QStringLiteral("profileDiffDialog"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("%n parameter(s) in %1 differ from the servo. Loading makes "
                                "them edits; nothing is written until you press Apply.",
                                nullptr, int(rows.size()))
                                 .arg(fileName),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto *table = new QTableWidget(int(rows.size()), 3, this);
    table->setHorizontalHeaderLabels({tr("Parameter"), tr("On the servo"), tr("In the file")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int row = 0; row < rows.size(); ++row) {
        const profile::DiffRow &diff = rows.at(row);
        const model::Definition *definition = parameters.definition(diff.key);
        table->setItem(row, 0, new QTableWidgetItem(diff.label));
        table->setItem(row, 1,
                       new QTableWidgetItem(diff.device && definition
                                                ? shown(*definition, *diff.device)
                                                : tr("not read")));
        table->setItem(row, 2,
                       new QTableWidgetItem(definition ? shown(*definition, diff.file)
                                                       : QString::number(diff.file)));
    }
    layout->addWidget(table);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Load as edits"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(520, 360);
}
