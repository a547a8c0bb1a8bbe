// A Feetech register table as parameter-model definitions, and register values to and from bytes.
#pragma once

#include "bustypes.h"
#include "parametermodel.h"
#include "registertable.h"

#include <QStringList>
#include <QVector>

#include <optional>

namespace feetech {

// The registers users change most, grouped for the Settings page; keys a family lacks are
// skipped.
struct SettingsGroup
{
    QString title; // translated
    QStringList keys;
};
QVector<SettingsGroup> settingsGroups();

// One definition per register, in address order. Values are in register units (decoded, signed
// where the register has a sign bit); scale and unit give the real units.
QVector<model::Definition> modelDefinitions(const RegisterTable &table);

// What a profile of this family holds: the writable EEPROM settings except the ID and the baud
// rate, which would change how the servo is reached.
QVector<model::Definition> profileDefinitions(const RegisterTable &table);

struct DecodedRegister
{
    const Register *reg = nullptr;
    qint32 value = 0; // register units
    quint16 raw = 0; // the bytes as an unsigned number in the family's order
};
// The registers that lie wholly inside `bytes` read at `address`.
QVector<DecodedRegister> decodeRegisters(const RegisterTable &table, int address,
                                         QByteArrayView bytes);

// Edits as register writes, each range-checked and encoded in the family's byte order and sign
// bit. Nothing and *error (naming the register) when any value is unknown or out of range.
std::optional<QVector<RegisterWrite>>
encodeWrites(const RegisterTable &table, const QVector<model::WriteItem> &items, QString *error);

// How a person gave a value: in register units (the command line: "74" for 7.4 V), or in the
// register's real unit in the user's locale (the memory table: "7,4" or "7.4").
enum class ValueUnits { Register, Real };

// A value typed by a person (a number in `units`, "1000000" for the baud rate in bps, a
// choice's label) in register units; nothing and *error when it is not valid for the register.
// The GUI and the command line both read values with this one function. A real value between
// two of the register's steps (50 step/s² where a step is 100) becomes the nearest step, and
// *adjusted says so (it is cleared when nothing was changed): never silently.
std::optional<qint32> parseValue(const Register &reg, const QString &text, QString *error,
                                 ValueUnits units = ValueUnits::Register,
                                 QString *adjusted = nullptr);

// A register's value in its real unit, without the unit: "5000", "7.4" (a dot in every locale,
// as displayValue shows it).
QString realNumber(const Register &reg, qint32 value);
// The register's unit, translated; empty for a plain number.
QString registerUnit(const Register &reg);
// What one step of the register is worth in its unit: "100 step/s²", "0.1 V", "1".
QString resolutionText(const Register &reg);

// The names of the bits set in a bit-field register ("voltage, temperature"), or "none".
QString bitNames(const Register &reg, qint32 value);
// The value as a person reads it: choice label, bit names, or the number in real units.
QString displayValue(const Register &reg, qint32 value);

} // namespace feetech
