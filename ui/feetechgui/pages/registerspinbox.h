// A spin box for one register: it holds the register's value, and shows and reads it in the
// register's unit, one step at a time.
#pragma once

#include "registertable.h"

#include <QSpinBox>

#include <optional>

// value() is in register units (what is written); the text is in the register's real unit, as
// the Memory table shows it ("5000 step/s²" for 50 steps of 100 step/s²), and the arrows move
// by one step of the register. A typed value between two steps becomes the nearest step and
// snapped() says so: never silently.
class RegisterSpinBox : public QSpinBox
{
    Q_OBJECT

public:
    explicit RegisterSpinBox(QWidget *parent = nullptr);

    // Range, unit and step of `reg` (non-negative where a sign means a direction); none: 0 only.
    void setRegister(const feetech::Register *reg, bool nonNegative);
    // What the user typed, in the register's unit, before it was snapped to a step; the value
    // shown when nothing was typed since.
    QString typedText() const;

signals:
    // A typed value was between two steps and became the nearest one: why, for the user.
    void snapped(const QString &note);

protected:
    QString textFromValue(int value) const override;
    int valueFromText(const QString &text) const override;
    QValidator::State validate(QString &text, int &pos) const override;

private:
    QString withoutSuffix(const QString &text) const;

    std::optional<feetech::Register> m_register;
    // Left by valueFromText, which Qt calls as it takes what was typed.
    mutable QString m_typed;
    mutable int m_typedValue = 0;
    mutable QString m_note;
};
