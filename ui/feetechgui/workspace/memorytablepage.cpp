// The Memory table page: the register table of the servo shown, its filter and its buttons.
#include "memorytablepage.h"

#include "busclient.h"
#include "parametermodel.h"
#include "registertablemodel.h"
#include "registervaluedelegate.h"
#include "widgethelpers.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>

using widgethelpers::actionButton;

MemoryTablePage::MemoryTablePage(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("memoryTablePage"));
    auto *layout = new QVBoxLayout(this);
    auto *top = new QHBoxLayout;
    m_filterEdit = new QLineEdit(this);
    m_filterEdit->setObjectName(QStringLiteral("registerFilter"));
    m_filterEdit->setPlaceholderText(tr("Filter registers"));
    m_filterEdit->setClearButtonEnabled(true);
    m_live = new QCheckBox(tr("Refresh RAM live"), this);
    m_live->setObjectName(QStringLiteral("liveCheck"));
    m_live->setChecked(true);
    m_live->setToolTip(tr("Read the RAM registers (present position, load, voltage…) "
                          "several times a second while this table is shown"));
    top->addWidget(m_filterEdit, 1);
    top->addWidget(m_live);
    layout->addLayout(top);
    m_empty = new QLabel(tr("No servo chosen: scan the bus, then choose a servo in the "
                            "tree; every register of its memory table shows here."),
                         this);
    m_empty->setObjectName(QStringLiteral("memoryEmptyState"));
    m_empty->setWordWrap(true);
    m_empty->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(m_empty);
    m_registers = new RegisterTableModel(this);
    m_filter = new QSortFilterProxyModel(this);
    m_filter->setSourceModel(m_registers);
    m_filter->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_filter->setFilterKeyColumn(-1);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("memoryTable"));
    m_table->setModel(m_filter);
    m_table->setItemDelegateForColumn(RegisterTableModel::ValueColumn,
                                      new RegisterValueDelegate(m_registers, m_table));
    m_table->setAlternatingRowColors(true);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::AnyKeyPressed);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(RegisterTableModel::LabelColumn,
                                                      QHeaderView::Stretch);
    layout->addWidget(m_table, 1);
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("memoryValueNote"));
    m_note->setWordWrap(true);
    m_note->hide();
    layout->addWidget(m_note);
    auto *buttons = new QHBoxLayout;
    m_read =
        actionButton(tr("Read"), "tableReadButton", tr("Read every register of the servo"), this);
    m_revert = actionButton(tr("Revert"), "tableRevertButton", tr("Drop every edit"), this);
    m_apply = actionButton(tr("Apply"), "tableApplyButton",
                           tr("Write the edited registers, then read them back"), this);
    QFont bold = m_apply->font();
    bold.setBold(true);
    m_apply->setFont(bold);
    buttons->addStretch(1);
    buttons->addWidget(m_read);
    buttons->addWidget(m_revert);
    buttons->addWidget(m_apply);
    layout->addLayout(buttons);

    connect(m_filterEdit, &QLineEdit::textChanged, m_filter,
            &QSortFilterProxyModel::setFilterFixedString);
    connect(m_registers, &RegisterTableModel::editRefused, this, &MemoryTablePage::problem);
    connect(m_registers, &RegisterTableModel::editAdjusted, this, [this](const QString &note) {
        m_note->setText(note);
        m_note->show();
    });
    connect(m_read, &QPushButton::clicked, this, &MemoryTablePage::readRequested);
    connect(m_apply, &QPushButton::clicked, this, &MemoryTablePage::applyRequested);
    connect(m_revert, &QPushButton::clicked, this, &MemoryTablePage::revertRequested);
}

void MemoryTablePage::showServo(const feetech::BusClient &client, int index)
{
    model::ParameterModel *parameters = client.servos()->parameters(index);
    if (parameters != m_shownParameters)
        m_note->hide(); // a note speaks of the servo it was typed for
    m_shownParameters = parameters;
    m_registers->setServo(index >= 0 ? &client.servos()->at(index).info.table() : nullptr,
                          parameters);
    m_table->resizeColumnsToContents();
    // Bit lists can be long: the value column keeps a reading width (the tooltip and a wider
    // window show the rest) so the register names keep theirs.
    m_table->setColumnWidth(RegisterTableModel::ValueColumn,
                            std::min(m_table->columnWidth(RegisterTableModel::ValueColumn),
                                     m_table->fontMetrics().horizontalAdvance(u'm') * 15));
    int stateWidth = 0;
    for (const model::State state :
         {model::State::Edited, model::State::Writing, model::State::Verified,
          model::State::Mismatch, model::State::Failed, model::State::Unknown})
        stateWidth = std::max(
            stateWidth,
            m_table->fontMetrics().horizontalAdvance(RegisterTableModel::snappedStateName(state)));
    m_table->setColumnWidth(RegisterTableModel::StateColumn, stateWidth + 16);
}

void MemoryTablePage::setEmptyStateShown(bool shown)
{
    m_empty->setVisible(shown);
}

void MemoryTablePage::updateActions(bool ready, bool known, bool edits, bool idle, bool editable)
{
    m_read->setEnabled(ready);
    m_apply->setEnabled(ready && known && edits);
    m_revert->setEnabled(idle && edits);
    m_registers->setEditable(editable);
}

bool MemoryTablePage::refreshesLive() const
{
    return m_live->isChecked();
}
