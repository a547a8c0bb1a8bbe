// Register-bound spin boxes and value labels of the Control page and its motion-test panel.
#include "registerwidgets.h"

#include "registertable.h"

#include <QCoreApplication>
#include <QLabel>
#include <QLocale>
#include <QSignalBlocker>
#include <QSpinBox>

#include <algorithm>

namespace registerwidgets {

namespace {
constexpr int kSpinBoxMinimumWidth = 96;
}

QSpinBox *spinBox(const char *name, QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    spin->setObjectName(QLatin1String(name));
    spin->setAlignment(Qt::AlignRight);
    spin->setAccelerated(true);
    spin->setMinimumWidth(kSpinBoxMinimumWidth);
    return spin;
}

QLabel *valueLabel(const char *name, QWidget *parent)
{
    auto *label = new QLabel(QStringLiteral("—"), parent);
    label->setObjectName(QLatin1String(name));
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

void setRegisterRange(QSpinBox *spin, const feetech::Register *reg, bool nonNegative)
{
    const QSignalBlocker blocker(spin);
    if (!reg) {
        spin->setRange(0, 0);
        return;
    }
    spin->setRange(nonNegative ? std::max(0, reg->minimum) : reg->minimum, reg->maximum);
}

QString unitText(const feetech::Register *reg)
{
    if (!reg)
        return {};
    if (reg->scale == 1.0)
        return feetech::tableText(reg->unit);
    // The Control page's context: the translation was made there.
    return QCoreApplication::translate("ControlPage", "× %1 %2",
                                       "scale and unit of a register value")
        .arg(QLocale().toString(reg->scale, 'g', 6), feetech::tableText(reg->unit))
        .trimmed();
}

} // namespace registerwidgets
