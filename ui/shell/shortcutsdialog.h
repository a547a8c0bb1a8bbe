// Help > Keyboard shortcuts: every menu command that has a shortcut, read from the menus.
#pragma once

#include <QDialog>

class QMenuBar;
class QTableWidget;

class ShortcutsDialog : public QDialog
{
    Q_OBJECT

public:
    // Lists the shortcuts of `menus` as they are now (so the list never misses a new command).
    explicit ShortcutsDialog(const QMenuBar *menus, QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }

private:
    QTableWidget *m_table = nullptr;
};
