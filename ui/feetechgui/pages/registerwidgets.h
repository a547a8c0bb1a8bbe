// Spin boxes and labels for register values, shared by the Control page and its test panel so
// that both show ranges and units the same way.
#pragma once

#include <QString>

class QLabel;
class RegisterSpinBox;
class QSpinBox;
class QWidget;

namespace registerwidgets {

// A right-aligned, accelerated spin box with an object name (for tests).
QSpinBox *spinBox(const char *name, QWidget *parent);
// The same for a register's value, in the register's unit (see RegisterSpinBox).
RegisterSpinBox *registerSpinBox(const char *name, QWidget *parent);
// A selectable label that shows a dash until it has a value.
QLabel *valueLabel(const char *name, QWidget *parent);
// " step": the suffix of a position, in the unit every page shows.
QString stepSuffix();

} // namespace registerwidgets
