// A question with "Don't ask again", remembered in QSettings.
#include "skippablequestion.h"

#include <QCheckBox>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>

#include <algorithm>

namespace {

const QString kGroup = QStringLiteral("questions");

QString settingsKey(const QString &key)
{
    return kGroup + u'/' + key;
}

} // namespace

SkippableQuestion::SkippableQuestion(QString key, QString title, QString goAhead)
    : m_key(std::move(key))
    , m_title(std::move(title))
    , m_goAhead(std::move(goAhead))
{ }

bool SkippableQuestion::isSkipped() const
{
    return QSettings().value(settingsKey(m_key), false).toBool();
}

bool SkippableQuestion::ask(QWidget *parent, const QString &text) const
{
    if (isSkipped())
        return true;
    QMessageBox box(QMessageBox::Question, m_title, text, QMessageBox::NoButton, parent);
    box.setObjectName(QStringLiteral("skippableQuestion"));
    QPushButton *goAhead = box.addButton(m_goAhead, QMessageBox::AcceptRole);
    goAhead->setObjectName(QStringLiteral("goAheadButton"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.setEscapeButton(cancel);
    auto *dontAsk = new QCheckBox(tr("Don't ask again"), &box);
    dontAsk->setObjectName(QStringLiteral("dontAskAgainBox"));
    dontAsk->setToolTip(tr("View > Ask skipped questions again brings it back"));
    box.setCheckBox(dontAsk);
    box.exec();
    if (box.clickedButton() != goAhead)
        return false;
    if (dontAsk->isChecked())
        QSettings().setValue(settingsKey(m_key), true);
    return true;
}

bool SkippableQuestion::anySkipped()
{
    QSettings settings;
    settings.beginGroup(kGroup);
    const QStringList keys = settings.childKeys();
    return std::any_of(keys.cbegin(), keys.cend(),
                       [&settings](const QString &key) { return settings.value(key).toBool(); });
}

void SkippableQuestion::askAllAgain()
{
    QSettings().remove(kGroup);
}
