// Feetech registers as parameter definitions; decoding read blocks and encoding checked writes.
#include "servoparameters.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

struct FeetechParametersTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechParameters)
};

} // namespace

namespace feetech {

namespace {

QString groupFor(const Register &reg, const QVector<SettingsGroup> &groups)
{
    for (const SettingsGroup &group : groups) {
        if (group.keys.contains(reg.key))
            return group.title;
    }
    return reg.storage == Storage::Eeprom ? FeetechParametersTr::tr("Other EEPROM")
                                          : FeetechParametersTr::tr("Other RAM");
}

model::Definition definitionFor(const Register &reg, const QVector<SettingsGroup> &groups)
{
    model::Definition definition;
    definition.key = reg.key;
    definition.label = tableText(reg.label);
    definition.group = groupFor(reg, groups);
    definition.unit = tableText(reg.unit);
    definition.scale = reg.scale;
    definition.minimum = reg.minimum;
    definition.maximum = reg.maximum;
    definition.access = reg.writable() ? model::Access::ReadWrite : model::Access::ReadOnly;
    definition.storage =
        reg.storage == Storage::Eeprom ? model::Storage::Eeprom : model::Storage::Ram;
    for (const Choice &choice : reg.choices)
        definition.choices.append({choice.value, tableText(choice.label)});
    definition.note = tableText(reg.note);
    return definition;
}

} // namespace

QVector<SettingsGroup> settingsGroups()
{
    return {
        {FeetechParametersTr::tr("Identity and link"),
         {QStringLiteral("id"), QStringLiteral("baud_rate"), QStringLiteral("return_delay"),
          QStringLiteral("response_level"), QStringLiteral("secondary_id")}},
        {FeetechParametersTr::tr("Travel and mode"),
         {QStringLiteral("min_angle_limit"), QStringLiteral("max_angle_limit"),
          QStringLiteral("position_offset"), QStringLiteral("mode"),
          QStringLiteral("angular_resolution")}},
        {FeetechParametersTr::tr("Control loop"),
         {QStringLiteral("p_gain"), QStringLiteral("d_gain"), QStringLiteral("i_gain"),
          QStringLiteral("speed_p_gain"), QStringLiteral("speed_i_gain"),
          QStringLiteral("current_p_gain"), QStringLiteral("current_i_gain"),
          QStringLiteral("cw_dead_zone"), QStringLiteral("ccw_dead_zone"),
          QStringLiteral("min_startup_force")}},
        {FeetechParametersTr::tr("Limits and protection"),
         {QStringLiteral("max_temperature"), QStringLiteral("max_voltage"),
          QStringLiteral("min_voltage"), QStringLiteral("max_torque"),
          QStringLiteral("protection_current"), QStringLiteral("holding_torque"),
          QStringLiteral("protection_time"), QStringLiteral("overload_torque"),
          QStringLiteral("overcurrent_protection_time"), QStringLiteral("unload_conditions"),
          QStringLiteral("led_alarm_conditions")}},
    };
}

QVector<model::Definition> modelDefinitions(const RegisterTable &table)
{
    const QVector<SettingsGroup> groups = settingsGroups();
    QVector<model::Definition> definitions;
    definitions.reserve(table.registers().size());
    for (const Register &reg : table.registers())
        definitions.append(definitionFor(reg, groups));
    return definitions;
}

QVector<model::Definition> profileDefinitions(const RegisterTable &table)
{
    const QVector<SettingsGroup> groups = settingsGroups();
    QVector<model::Definition> definitions;
    for (const Register &reg : table.registers()) {
        if (reg.storage == Storage::Eeprom && reg.writable() && reg.key != u"id"
            && reg.key != u"baud_rate" && reg.key != u"secondary_id")
            definitions.append(definitionFor(reg, groups));
    }
    return definitions;
}

QVector<DecodedRegister> decodeRegisters(const RegisterTable &table, int address,
                                         QByteArrayView bytes)
{
    QVector<DecodedRegister> decoded;
    const int end = address + int(bytes.size());
    for (const Register &reg : table.registers()) {
        if (reg.address < address || reg.end() > end)
            continue;
        const QByteArrayView slice = bytes.sliced(reg.address - address, reg.size);
        DecodedRegister item;
        item.reg = &reg;
        item.raw = decodeRaw(slice, table.byteOrder());
        item.value = decodeValue(slice, table.format(reg));
        decoded.append(item);
    }
    return decoded;
}

std::optional<QVector<RegisterWrite>>
encodeWrites(const RegisterTable &table, const QVector<model::WriteItem> &items, QString *error)
{
    QVector<RegisterWrite> writes;
    for (const model::WriteItem &item : items) {
        const Register *reg = table.find(item.key);
        if (!reg || !reg->writable()) {
            if (error)
                *error = FeetechParametersTr::tr("%1 is not a writable register of %2.")
                             .arg(item.key, familyName(table.family()));
            return std::nullopt;
        }
        if (item.value < reg->minimum || item.value > reg->maximum) {
            if (error)
                *error = FeetechParametersTr::tr("%1 = %2 is out of range (%3 to %4).")
                             .arg(reg->key)
                             .arg(item.value)
                             .arg(reg->minimum)
                             .arg(reg->maximum);
            return std::nullopt;
        }
        const auto bytes = encodeValue(qint32(item.value), table.format(*reg));
        if (!bytes) {
            if (error)
                *error = FeetechParametersTr::tr("%1 = %2 does not fit the register.")
                             .arg(reg->key)
                             .arg(item.value);
            return std::nullopt;
        }
        writes.append({reg->address, *bytes, reg->storage == Storage::Eeprom});
    }
    return writes;
}

std::optional<qint32> parseValue(const Register &reg, const QString &text, QString *error,
                                 ValueUnits units, QString *adjusted)
{
    if (adjusted)
        adjusted->clear();
    QString trimmed = text.trimmed();
    // A value may carry its unit, as it is shown: "5000 step/s²".
    const QString unit = registerUnit(reg);
    if (units == ValueUnits::Real && !unit.isEmpty() && trimmed.endsWith(unit))
        trimmed = trimmed.chopped(unit.size()).trimmed();
    std::optional<qint64> parsed;
    std::optional<double> offStep; // the real value typed, when it lies between two steps
    for (const Choice &choice : reg.choices) {
        // In English, as the table has it and scripts write it, or as the user's language shows it.
        if (choice.label.compare(trimmed, Qt::CaseInsensitive) == 0
            || tableText(choice.label).compare(trimmed, Qt::CaseInsensitive) == 0)
            parsed = choice.value;
    }
    bool whole = false;
    const qint64 number = trimmed.toLongLong(&whole);
    if (!parsed && whole && reg.key == u"baud_rate") {
        // The baud rate is given in bits per second, not as its code. Checked before narrowing:
        // 4295967296 must not wrap round to 1000000.
        const std::optional<int> code = number > 0 && number <= std::numeric_limits<qint32>::max()
            ? baudCode(qint32(number))
            : std::nullopt;
        if (!code) {
            if (error)
                *error = FeetechParametersTr::tr("baud_rate: %1 bps is not a Feetech baud rate.")
                             .arg(trimmed);
            return std::nullopt;
        }
        parsed = *code;
    } else if (!parsed && units == ValueUnits::Register && whole) {
        parsed = number;
    } else if (!parsed && units == ValueUnits::Real) {
        bool ok = false;
        const double local = QLocale().toDouble(trimmed, &ok);
        const double real = ok ? local : trimmed.toDouble(&ok);
        const double raw = real / reg.scale;
        if (ok && std::isfinite(raw)
            && std::abs(raw) < double(std::numeric_limits<qint32>::max())) {
            parsed = qint64(std::llround(raw));
            // Not a whole number of steps, beyond what the decimal scale itself leaves (7.4 V is
            // 73.99999… steps of 0.1 V).
            if (std::abs(raw - double(*parsed)) > 1e-6 * std::max(1.0, std::abs(raw)))
                offStep = real;
        }
    }
    if (!parsed) {
        if (error)
            *error = units == ValueUnits::Real
                ? FeetechParametersTr::tr("%1: \"%2\" is not a number.").arg(reg.key, trimmed)
                : FeetechParametersTr::tr("%1: \"%2\" is not a whole number.")
                      .arg(reg.key, trimmed);
        return std::nullopt;
    }
    const qint64 value = *parsed;
    if (value < reg.minimum || value > reg.maximum) {
        if (error)
            *error = FeetechParametersTr::tr("%1 = %2 is out of range (%3 to %4).")
                         .arg(reg.key)
                         .arg(value)
                         .arg(reg.minimum)
                         .arg(reg.maximum);
        return std::nullopt;
    }
    if (offStep && adjusted) {
        const QString typed = QString::number(*offStep, 'g', 10);
        *adjusted =
            FeetechParametersTr::tr("%1: %2 is not a whole number of steps of %3: set to %4.")
                .arg(tableText(reg.label), unit.isEmpty() ? typed : typed + u' ' + unit,
                     resolutionText(reg), displayValue(reg, qint32(value)));
    }
    return qint32(value);
}

QString realNumber(const Register &reg, qint32 value)
{
    return reg.scale == 1.0 ? QString::number(value)
                            : QString::number(double(value) * reg.scale, 'g', 10);
}

QString registerUnit(const Register &reg)
{
    return unitText(reg.unit);
}

QString resolutionText(const Register &reg)
{
    const QString step = QString::number(reg.scale, 'g', 10);
    return reg.unit.isEmpty() ? step : step + u' ' + registerUnit(reg);
}

QString bitNames(const Register &reg, qint32 value)
{
    // Every bit set is listed, named or not: an undocumented status bit (STS bit 4, "angle" in
    // the ST3215 sheet) is still an alarm and must not read as "none".
    QStringList names;
    for (int bit = 0; bit < reg.size * 8; ++bit) {
        if (!(value & (1 << bit)))
            continue;
        const auto named = std::find_if(reg.bits.begin(), reg.bits.end(),
                                        [bit](const BitName &b) { return b.bit == bit; });
        names.append(named != reg.bits.end() ? tableText(named->label)
                                             : FeetechParametersTr::tr("bit %1").arg(bit));
    }
    return names.isEmpty() ? FeetechParametersTr::tr("none") : names.join(QStringLiteral(", "));
}

QString displayValue(const Register &reg, qint32 value)
{
    for (const Choice &choice : reg.choices) {
        if (choice.value == value)
            return tableText(choice.label);
    }
    if (!reg.bits.isEmpty())
        return bitNames(reg, value);
    const QString number = realNumber(reg, value);
    return reg.unit.isEmpty() ? number : number + u' ' + registerUnit(reg);
}

} // namespace feetech
