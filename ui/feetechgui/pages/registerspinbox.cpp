// The register spin box: register units inside, the register's real unit on screen.
#include "registerspinbox.h"

#include "servoparameters.h"

#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>

#include <algorithm>
#include <cmath>
#include <utility>

namespace {

// The editor speaks the user's locale; no group separator, which typing would not repeat.
QLocale editorLocale()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

} // namespace

RegisterSpinBox::RegisterSpinBox(QWidget *parent)
    : QSpinBox(parent)
{
    // A value is taken when typing ends, not at every key: "5" on the way to "50" is no step.
    setKeyboardTracking(false);
    connect(this, &QAbstractSpinBox::editingFinished, this, [this] {
        if (!m_note.isEmpty())
            emit snapped(std::exchange(m_note, {}));
    });
}

void RegisterSpinBox::setRegister(const feetech::Register *reg, bool nonNegative)
{
    const QSignalBlocker blocker(this);
    m_register = reg ? std::optional<feetech::Register>(*reg) : std::nullopt;
    m_typed.clear();
    m_note.clear();
    if (!reg) {
        setRange(0, 0);
        setSuffix({});
        return;
    }
    const QString unit = feetech::registerUnit(*reg);
    setSuffix(unit.isEmpty() ? QString() : u' ' + unit);
    setRange(nonNegative ? std::max(0, reg->minimum) : reg->minimum, reg->maximum);
    setSingleStep(1);
}

QString RegisterSpinBox::typedText() const
{
    if (!m_typed.isEmpty() && value() == m_typedValue)
        return m_typed;
    return withoutSuffix(lineEdit()->displayText());
}

QString RegisterSpinBox::textFromValue(int value) const
{
    if (!m_register || m_register->scale == 1.0)
        return editorLocale().toString(value);
    return editorLocale().toString(double(value) * m_register->scale, 'g', 10);
}

int RegisterSpinBox::valueFromText(const QString &text) const
{
    if (!m_register)
        return QSpinBox::valueFromText(text);
    QString error;
    QString note;
    const QString typed = withoutSuffix(text);
    const auto parsed =
        feetech::parseValue(*m_register, typed, &error, feetech::ValueUnits::Real, &note);
    if (!parsed)
        return value();
    m_typed = typed;
    m_typedValue = *parsed;
    m_note = note;
    return *parsed;
}

QValidator::State RegisterSpinBox::validate(QString &text, int &pos) const
{
    if (!m_register)
        return QSpinBox::validate(text, pos);
    const QString typed = withoutSuffix(text);
    const QLocale locale = editorLocale();
    if (typed.isEmpty() || typed == locale.negativeSign() || typed == locale.decimalPoint())
        return QValidator::Intermediate;
    bool ok = false;
    double real = locale.toDouble(typed, &ok);
    if (!ok)
        real = typed.toDouble(&ok);
    if (!ok || !std::isfinite(real))
        return QValidator::Invalid;
    const double steps = std::round(real / m_register->scale);
    return steps >= minimum() && steps <= maximum() ? QValidator::Acceptable
                                                    : QValidator::Intermediate;
}

QString RegisterSpinBox::withoutSuffix(const QString &text) const
{
    QString stripped = text.trimmed();
    const QString unit = suffix().trimmed();
    if (!unit.isEmpty() && stripped.endsWith(unit))
        stripped.chop(unit.size());
    return stripped.trimmed();
}
