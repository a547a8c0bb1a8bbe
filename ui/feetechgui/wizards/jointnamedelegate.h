// A cell holding a LeRobot joint name: the user's language shows, the file's key is edited.
#pragma once

#include <QStyledItemDelegate>

// The cell's data stays the key a LeRobot file uses ("shoulder_pan"); a name the user's
// language translates is shown translated, with the key beside it.
class JointNameDelegate : public QStyledItemDelegate
{
    Q_OBJECT

public:
    using QStyledItemDelegate::QStyledItemDelegate;

    // "肩部旋转 (shoulder_pan)"; the key alone when it has no translation.
    static QString shownName(const QString &key);

    QString displayText(const QVariant &value, const QLocale &locale) const override;
};
