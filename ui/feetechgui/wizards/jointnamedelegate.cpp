// Joint name cells: the translated name shown, the LeRobot key kept and edited.
#include "jointnamedelegate.h"

#include "robottemplate.h"

QString JointNameDelegate::shownName(const QString &key)
{
    const QString translated = feetech::jointDisplayName(key);
    return translated == key ? key : tr("%1 (%2)").arg(translated, key);
}

QString JointNameDelegate::displayText(const QVariant &value, const QLocale &locale) const
{
    if (value.userType() != QMetaType::QString)
        return QStyledItemDelegate::displayText(value, locale);
    return shownName(value.toString());
}
