// Settings a user chose in a form (scan options, Monitor choices), kept across runs: each
// widget gets back its last value from QSettings when created and saves every change.
#include "widgetmemory.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSettings>
#include <QSpinBox>

namespace widgetmemory {

void remember(QSpinBox *box, const QString &key)
{
    const QVariant saved = QSettings().value(key);
    bool ok = false;
    const int value = saved.toInt(&ok);
    if (ok && value >= box->minimum() && value <= box->maximum())
        box->setValue(value);
    QObject::connect(box, &QSpinBox::valueChanged, box,
                     [key](int now) { QSettings().setValue(key, now); });
}

void remember(QCheckBox *box, const QString &key)
{
    const QVariant saved = QSettings().value(key);
    if (saved.isValid())
        box->setChecked(saved.toBool());
    QObject::connect(box, &QCheckBox::toggled, box,
                     [key](bool now) { QSettings().setValue(key, now); });
}

void remember(QComboBox *box, const QString &key)
{
    const QString saved = QSettings().value(key).toString();
    if (!saved.isEmpty()) {
        int index = box->findData(saved);
        if (index < 0)
            index = box->findText(saved);
        if (index >= 0)
            box->setCurrentIndex(index);
    }
    QObject::connect(box, &QComboBox::currentIndexChanged, box, [box, key](int index) {
        const QVariant data = box->itemData(index);
        QSettings().setValue(key, data.isValid() ? data.toString() : box->itemText(index));
    });
}

} // namespace widgetmemory
