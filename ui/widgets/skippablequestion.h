// A question asked before something moves (Identify's wiggle), with a "Don't ask again" box. A
// question skipped is remembered in QSettings under questions/; View > Ask skipped questions
// again brings every one of them back.
#pragma once

#include <QCoreApplication>
#include <QString>

class QWidget;

class SkippableQuestion
{
    Q_DECLARE_TR_FUNCTIONS(SkippableQuestion)

public:
    // `key` names the question in the settings; `goAhead` is the button that goes ahead.
    SkippableQuestion(QString key, QString title, QString goAhead);

    // True to go ahead: the user said so now, or ticked "Don't ask again" when going ahead
    // before. Cancel (or Escape) is the default: nothing moves on a stray Enter. A tick with
    // Cancel is not remembered, so a skipped question always means "go ahead".
    bool ask(QWidget *parent, const QString &text) const;
    bool isSkipped() const;

    static bool anySkipped();
    static void askAllAgain();

private:
    QString m_key;
    QString m_title;
    QString m_goAhead;
};
