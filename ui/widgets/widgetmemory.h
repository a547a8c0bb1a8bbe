// Settings a user chose in a form (scan options, Monitor choices), kept across runs: each
// widget gets back its last value from QSettings when created and saves every change.
#pragma once

#include <QString>

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace widgetmemory {

void remember(QSpinBox *box, const QString &key);
void remember(QCheckBox *box, const QString &key);
// By the item's data where it has one (stable across languages), else by its text.
void remember(QComboBox *box, const QString &key);

} // namespace widgetmemory
