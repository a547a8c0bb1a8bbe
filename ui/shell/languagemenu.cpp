// View > Language: the language ServoBench shows, remembered, taking effect on a restart.
#include "languagemenu.h"

#include "translations.h"

#include <QActionGroup>
#include <QMessageBox>
#include <QSettings>

QString LanguageMenu::settingsKey()
{
    return QStringLiteral("language");
}

LanguageMenu::LanguageMenu(QWidget *parent)
    : QMenu(tr("&Language"), parent)
    , m_group(new QActionGroup(this))
{
    setObjectName(QStringLiteral("languageMenu"));
    const QString current = QSettings().value(settingsKey()).toString();
    const auto add = [this, &current](const QString &text, const QString &language) {
        QAction *action = addAction(text);
        action->setCheckable(true);
        action->setChecked(language == current);
        action->setData(language);
        action->setObjectName(QStringLiteral("language_") + language);
        m_group->addAction(action);
        connect(action, &QAction::triggered, this, [this, language] { picked(language); });
    };
    add(tr("The system's language"), QString());
    addSeparator();
    // Each language by its own name, so a user who cannot read the current one finds theirs.
    add(util::nativeLanguageName(QStringLiteral("en")), QStringLiteral("en"));
    for (const QString &language : util::translatedLanguages())
        add(util::nativeLanguageName(language), language);
}

void LanguageMenu::choose(const QString &language)
{
    QSettings().setValue(settingsKey(), language);
    for (QAction *action : m_group->actions())
        action->setChecked(action->data().toString() == language);
}

void LanguageMenu::picked(const QString &language)
{
    const QString before = QSettings().value(settingsKey()).toString();
    choose(language);
    if (language == before)
        return;
    // Every window builds its texts once: the new language shows from the next start.
    QMessageBox box(QMessageBox::Question, tr("Language"),
                    tr("ServoBench shows the new language after it starts again."),
                    QMessageBox::NoButton, parentWidget());
    QPushButton *restart = box.addButton(tr("Restart now"), QMessageBox::AcceptRole);
    box.addButton(tr("Later"), QMessageBox::RejectRole);
    box.setDefaultButton(restart);
    box.exec();
    if (box.clickedButton() == restart)
        emit restartRequested();
}
