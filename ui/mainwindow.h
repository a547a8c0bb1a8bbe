// ServoBench's main window: menus, status bar and the page area.
#pragma once

#include <QMainWindow>

class QLabel;

class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(QWidget *parent = nullptr);

private:
    void createMenus();
    void showAbout();

    QLabel *m_connectionState = nullptr;
};
