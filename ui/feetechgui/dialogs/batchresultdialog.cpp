// The batch result table: a read-only table, failures in the error colour, a one-line summary.
#include "batchresultdialog.h"

#include "palette.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

BatchResultDialog::BatchResultDialog(const QString &source,
                                     const QVector<feetech::ProgramOutcome> &outcomes,
                                     QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("batchResultDialog"));
    setWindowTitle(tr("Programming results"));
    using Status = feetech::ProgramOutcome::Status;
    const auto count = [&outcomes](Status status) {
        return int(std::count_if(outcomes.cbegin(), outcomes.cend(),
                                 [status](const auto &o) { return o.status == status; }));
    };
    auto *summary = new QLabel(tr("%1 to %n servo(s): %2 written and verified, %3 unchanged, "
                                  "%4 failed.",
                                  nullptr, int(outcomes.size()))
                                   .arg(source)
                                   .arg(count(Status::Ok))
                                   .arg(count(Status::Unchanged))
                                   .arg(count(Status::Failed)),
                               this);
    summary->setWordWrap(true);
    m_table = new QTableWidget(int(outcomes.size()), ColumnCount, this);
    m_table->setObjectName(QStringLiteral("batchResultTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Servo"), tr("Status"), tr("Registers written"), tr("Error")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->setWordWrap(true);
    for (int row = 0; row < outcomes.size(); ++row) {
        const feetech::ProgramOutcome &outcome = outcomes.at(row);
        const QStringList texts {tr("ID %1").arg(outcome.id), feetech::statusText(outcome.status),
                                 outcome.changed.join(QStringLiteral(", ")), outcome.error};
        for (int column = 0; column < ColumnCount; ++column) {
            auto *item = new QTableWidgetItem(texts.at(column));
            item->setToolTip(texts.at(column));
            if (column == StatusColumn && outcome.status != Status::Unchanged)
                item->setForeground(palette::toneColor(
                    outcome.status == Status::Ok ? palette::Tone::Good : palette::Tone::Error,
                    m_table->palette()));
            m_table->setItem(row, column, item);
        }
    }
    // The error takes the room that is left and wraps; rows grow to show it whole.
    QHeaderView *header = m_table->horizontalHeader();
    for (const int column : {ServoColumn, StatusColumn, ChangedColumn})
        header->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    header->setSectionResizeMode(ErrorColumn, QHeaderView::Stretch);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(summary);
    const QString leftOut = feetech::leftOutNote(outcomes);
    if (!leftOut.isEmpty()) {
        auto *note = new QLabel(leftOut, this);
        note->setObjectName(QStringLiteral("batchLeftOutNote"));
        note->setWordWrap(true);
        layout->addWidget(note);
    }
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    const int em = fontMetrics().horizontalAdvance(u'm');
    resize(em * 75, em * 25);
}
