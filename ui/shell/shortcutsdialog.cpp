// Help > Keyboard shortcuts: every menu command that has a shortcut, read from the menus.
#include "shortcutsdialog.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

// "&Save profile…" as a menu shows it: "Save profile…".
QString shownText(QString text)
{
    text.replace(QLatin1String("&&"), QStringLiteral("\x01"));
    text.remove(u'&');
    text.replace(u'\x01', u'&');
    // Translations mark the accelerator as "(&S)" after the text: nothing of it is left.
    text.remove(QLatin1String("()"));
    return text.trimmed();
}

void addShortcuts(const QMenu *menu, const QString &path, QTableWidget *table)
{
    for (QAction *action : menu->actions()) {
        if (action->menu()) {
            addShortcuts(action->menu(), path + QStringLiteral(" > ") + shownText(action->text()),
                         table);
            continue;
        }
        if (action->shortcut().isEmpty() || action->isSeparator())
            continue;
        const int row = table->rowCount();
        table->insertRow(row);
        table->setItem(row, 0,
                       new QTableWidgetItem(action->shortcut().toString(QKeySequence::NativeText)));
        table->setItem(
            row, 1, new QTableWidgetItem(path + QStringLiteral(" > ") + shownText(action->text())));
    }
}

} // namespace

ShortcutsDialog::ShortcutsDialog(const QMenuBar *menus, QWidget *parent)
    : QDialog(parent)
    , m_table(new QTableWidget(0, 2, this))
{
    setWindowTitle(tr("Keyboard shortcuts"));
    setObjectName(QStringLiteral("shortcutsDialog"));
    m_table->setObjectName(QStringLiteral("shortcutsTable"));
    m_table->setHorizontalHeaderLabels({tr("Keys"), tr("Command")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    for (QAction *action : menus->actions()) {
        if (action->menu())
            addShortcuts(action->menu(), shownText(action->text()), m_table);
    }
    m_table->resizeColumnToContents(0);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(buttons);
    resize(520, 360);
}
