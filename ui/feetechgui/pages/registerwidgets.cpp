// Register-bound spin boxes and value labels of the Control page and its motion-test panel.
#include "registerwidgets.h"

#include "registerspinbox.h"
#include "registertable.h"

#include <QLabel>
#include <QSpinBox>

namespace registerwidgets {

namespace {

constexpr int kSpinBoxMinimumWidth = 96;

void styleSpinBox(QSpinBox *spin, const char *name)
{
    spin->setObjectName(QLatin1String(name));
    spin->setAlignment(Qt::AlignRight);
    spin->setAccelerated(true);
    spin->setMinimumWidth(kSpinBoxMinimumWidth);
}

} // namespace

QSpinBox *spinBox(const char *name, QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    styleSpinBox(spin, name);
    return spin;
}

RegisterSpinBox *registerSpinBox(const char *name, QWidget *parent)
{
    auto *spin = new RegisterSpinBox(parent);
    styleSpinBox(spin, name);
    return spin;
}

QLabel *valueLabel(const char *name, QWidget *parent)
{
    auto *label = new QLabel(QStringLiteral("—"), parent);
    label->setObjectName(QLatin1String(name));
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

QString stepSuffix()
{
    return u' ' + feetech::unitText(QStringLiteral("step"));
}

} // namespace registerwidgets
