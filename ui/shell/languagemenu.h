// View > Language: the language ServoBench shows, remembered, taking effect on a restart.
#pragma once

#include <QMenu>

class QActionGroup;

class LanguageMenu : public QMenu
{
    Q_OBJECT

public:
    // The QSettings key holding the chosen language: a locale name, or empty for the system's.
    static QString settingsKey();

    explicit LanguageMenu(QWidget *parent = nullptr);

    // Chooses `language` ("" = the system's) as if picked from the menu, without asking to
    // restart (for tests).
    void choose(const QString &language);

signals:
    // The user chose another language and asked to restart ServoBench now.
    void restartRequested();

private:
    void picked(const QString &language);

    QActionGroup *m_group = nullptr;
};
