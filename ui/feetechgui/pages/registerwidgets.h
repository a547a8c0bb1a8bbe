// Spin boxes and labels for register values, shared by the Control page and its test panel so
// that both show ranges and units the same way.
#pragma once

#include <QString>

class QLabel;
class QSpinBox;
class QWidget;

namespace feetech {
struct Register;
}

namespace registerwidgets {

// A right-aligned, accelerated spin box with an object name (for tests).
QSpinBox *spinBox(const char *name, QWidget *parent);
// A selectable label that shows a dash until it has a value.
QLabel *valueLabel(const char *name, QWidget *parent);
// Keeps a spin box's range to a register's (non-negative where a sign means a direction); an
// absent register leaves it at 0.
void setRegisterRange(QSpinBox *spin, const feetech::Register *reg, bool nonNegative);
// A register's unit as its raw values read: "step/s", or "× 100 step/s²" when scaled.
QString unitText(const feetech::Register *reg);

} // namespace registerwidgets
