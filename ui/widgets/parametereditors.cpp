// Parameter editors: built from definitions, filled and read back without emitting edits.
#include "parametereditors.h"

#include "parametermodel.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QSignalBlocker>
#include <QSpinBox>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// The parameter page's context: its translations were made there.
struct ParameterPageTr
{
    Q_DECLARE_TR_FUNCTIONS(ParameterPage)
};

} // namespace

namespace parametereditors {

namespace {

int toInt(qint64 value)
{
    return int(std::clamp<qint64>(value, std::numeric_limits<int>::min(),
                                  std::numeric_limits<int>::max()));
}

// Enough decimals to show every raw step exactly (scale 0.25 → 2).
int decimalsFor(double scale)
{
    int decimals = 0;
    double step = std::abs(scale);
    while (decimals < 6 && std::abs(step - std::round(step)) > 1e-9) {
        step *= 10;
        ++decimals;
    }
    return decimals;
}

} // namespace

QString userText(const model::Definition &definition, qint64 raw)
{
    if (definition.scale == 1.0)
        return QString::number(raw);
    return QString::number(double(raw) * definition.scale, 'g', 10); // as the model shows it
}

QWidget *create(const model::Definition &definition, QObject *context,
                const std::function<void()> &changed, const std::function<void()> &finished)
{
    QWidget *editor = nullptr;
    QString range;
    if (!definition.choices.isEmpty()) {
        auto *combo = new QComboBox;
        QStringList labels;
        for (const model::Choice &choice : definition.choices) {
            combo->addItem(choice.label, QVariant::fromValue<qlonglong>(choice.value));
            labels.append(choice.label);
        }
        combo->setCurrentIndex(-1);
        QObject::connect(combo, &QComboBox::currentIndexChanged, context, changed);
        range = ParameterPageTr::tr("%1: %2").arg(definition.label,
                                                  labels.join(ParameterPageTr::tr(" or ")));
        editor = combo;
    } else {
        QAbstractSpinBox *spin = nullptr;
        if (definition.scale == 1.0) {
            auto *box = new QSpinBox;
            box->setRange(toInt(definition.minimum), toInt(definition.maximum));
            QObject::connect(box, &QSpinBox::valueChanged, context, changed);
            spin = box;
        } else {
            auto *box = new QDoubleSpinBox;
            box->setDecimals(decimalsFor(definition.scale));
            box->setRange(double(definition.minimum) * definition.scale,
                          double(definition.maximum) * definition.scale);
            // Whole user units per step (1 µs), not one raw step (0.25 µs).
            box->setSingleStep(std::max(1.0, std::abs(definition.scale)));
            QObject::connect(box, &QDoubleSpinBox::valueChanged, context, changed);
            spin = box;
        }
        spin->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        spin->setKeyboardTracking(true); // Apply lights up as soon as a value is typed
        spin->setAccelerated(true);
        spin->setCorrectionMode(QAbstractSpinBox::CorrectToNearestValue);
        QObject::connect(spin, &QAbstractSpinBox::editingFinished, context, finished);
        const QString unit = definition.unit.isEmpty() ? QString() : u' ' + definition.unit;
        range = ParameterPageTr::tr("%1: %2 to %3%4")
                    .arg(definition.label, userText(definition, definition.minimum),
                         userText(definition, definition.maximum), unit);
        editor = spin;
    }
    editor->setObjectName(QStringLiteral("editor_") + definition.key);
    editor->setAccessibleName(definition.label);
    // No wheel focus: scrolling the page must never change a servo parameter by accident.
    editor->setFocusPolicy(Qt::StrongFocus);
    editor->setToolTip(definition.note.isEmpty() ? range : range + u'\n' + definition.note);
    return editor;
}

bool isTypedInto(const QWidget *editor)
{
    return qobject_cast<const QAbstractSpinBox *>(editor) != nullptr;
}

bool commit(QWidget *editor, model::ParameterModel &model, const QString &key, QString *error)
{
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        if (combo->currentIndex() >= 0)
            return model.edit(key, combo->currentData().toLongLong(), error);
    } else if (auto *spin = qobject_cast<QSpinBox *>(editor)) {
        return model.edit(key, spin->value(), error);
    } else if (auto *spin = qobject_cast<QDoubleSpinBox *>(editor)) {
        return model.editScaled(key, spin->value(), error);
    }
    return true;
}

void showValue(QWidget *editor, const model::Definition &definition, qint64 raw)
{
    const QSignalBlocker blocker(editor); // showing a value is not an edit
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        combo->setCurrentIndex(combo->findData(QVariant::fromValue<qlonglong>(raw)));
    } else if (auto *spin = qobject_cast<QSpinBox *>(editor)) {
        spin->setSpecialValueText(QString());
        spin->setValue(toInt(raw));
    } else if (auto *spin = qobject_cast<QDoubleSpinBox *>(editor)) {
        spin->setSpecialValueText(QString());
        spin->setValue(double(raw) * definition.scale);
    }
}

void showUnread(QWidget *editor)
{
    const QSignalBlocker blocker(editor);
    if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        combo->setCurrentIndex(-1);
    } else if (auto *spin = qobject_cast<QSpinBox *>(editor)) {
        spin->setSpecialValueText(ParameterPageTr::tr("—"));
        spin->setValue(spin->minimum());
    } else if (auto *spin = qobject_cast<QDoubleSpinBox *>(editor)) {
        spin->setSpecialValueText(ParameterPageTr::tr("—"));
        spin->setValue(spin->minimum());
    }
}

void setHighlighted(QWidget *editor, bool highlighted)
{
    if (!highlighted) {
        editor->setPalette(QPalette());
        return;
    }
    QPalette palette = editor->palette();
    const QColor background(255, 240, 170);
    const QColor text(20, 20, 20);
    palette.setColor(QPalette::Base, background);
    palette.setColor(QPalette::Button, background);
    palette.setColor(QPalette::Text, text);
    palette.setColor(QPalette::ButtonText, text);
    editor->setPalette(palette);
}

} // namespace parametereditors
