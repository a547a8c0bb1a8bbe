// Widget factories shared by the pages.
#include "common/widgethelpers.h"

#include <QPushButton>

namespace widgethelpers {

QPushButton *actionButton(const QString &text, const char *name, const QString &tip,
                          QWidget *parent)
{
    auto *button = new QPushButton(text, parent);
    button->setObjectName(QLatin1String(name));
    button->setToolTip(tip);
    button->setAutoDefault(false);
    return button;
}

} // namespace widgethelpers
