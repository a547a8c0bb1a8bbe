// Loading and validating the register tables (resources/feetech/<family>.json), and the rates
// as people read them.
#include "registertable.h"

#include "jsonfile.h"
#include "modeltable.h"
#include "registertabletr.h"
#include "tablejson.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QSet>

#include <cmath>
#include <map>

namespace feetech {

QString familyKey(Family family)
{
    switch (family) {
    case Family::Scs:
        return QStringLiteral("scs");
    case Family::Sts:
        return QStringLiteral("sts");
    case Family::Sms:
        return QStringLiteral("sms");
    case Family::Hls:
        return QStringLiteral("hls");
    }
    return {};
}

QString familyName(Family family)
{
    return familyKey(family).toUpper();
}

QString tableText(const QString &english)
{
    return english.isEmpty()
        ? english
        : QCoreApplication::translate("FeetechRegister", english.toUtf8().constData());
}

QString unitText(const QString &english)
{
    // The tables' units are their texts: datastrings.cpp lists every one for lupdate.
    return tableText(english);
}

std::optional<Family> familyFromKey(QStringView key)
{
    for (const Family family : kAllFamilies) {
        if (key.compare(familyKey(family), Qt::CaseInsensitive) == 0)
            return family;
    }
    return std::nullopt;
}

namespace {

bool parseRegister(const QJsonObject &object, ByteOrder order, Register &reg,
                   TableProblems &problems)
{
    static const QSet<QString> kKnownFields {
        QStringLiteral("address"), QStringLiteral("size"),     QStringLiteral("key"),
        QStringLiteral("label"),   QStringLiteral("storage"),  QStringLiteral("access"),
        QStringLiteral("unit"),    QStringLiteral("scale"),    QStringLiteral("min"),
        QStringLiteral("max"),     QStringLiteral("sign_bit"), QStringLiteral("default"),
        QStringLiteral("choices"), QStringLiteral("bits"),     QStringLiteral("note"),
    };
    static const QRegularExpression kKeyPattern(QStringLiteral("^[a-z][a-z0-9_]*$"));

    const QJsonValue address = object.value(QLatin1String("address"));
    reg.key = object.value(QLatin1String("key")).toString();
    const QString where =
        RegisterTableTr::tr("register \"%1\" (address %2)")
            .arg(reg.key,
                 address.isDouble() ? QString::number(address.toInt()) : QStringLiteral("?"));
    const auto fail = [&](const QString &what) {
        return problems.fail(where + u": " + what);
    };

    for (auto it = object.begin(); it != object.end(); ++it) {
        if (!kKnownFields.contains(it.key()))
            return fail(RegisterTableTr::tr("unknown field \"%1\"").arg(it.key()));
    }
    if (!kKeyPattern.match(reg.key).hasMatch())
        return fail(RegisterTableTr::tr("the key must be snake_case"));
    if (!util::isWholeNumber(address) || address.toInt() < 0 || address.toInt() > 255)
        return fail(RegisterTableTr::tr("the address must be a whole number from 0 to 255"));
    reg.address = address.toInt();
    const QJsonValue size = object.value(QLatin1String("size"));
    if (!util::isWholeNumber(size) || (size.toInt() != 1 && size.toInt() != 2))
        return fail(RegisterTableTr::tr("the size must be 1 or 2 bytes"));
    reg.size = size.toInt();
    if (reg.end() > 256)
        return fail(RegisterTableTr::tr("the register runs past address 255"));
    reg.label = object.value(QLatin1String("label")).toString();
    if (reg.label.isEmpty())
        return fail(RegisterTableTr::tr("the label is missing"));

    const QString storage = object.value(QLatin1String("storage")).toString();
    if (storage == QLatin1String("eeprom"))
        reg.storage = Storage::Eeprom;
    else if (storage == QLatin1String("ram"))
        reg.storage = Storage::Ram;
    else
        return fail(RegisterTableTr::tr("storage must be \"eeprom\" or \"ram\""));
    const QString access = object.value(QLatin1String("access")).toString();
    if (access == QLatin1String("ro"))
        reg.access = Access::ReadOnly;
    else if (access == QLatin1String("rw"))
        reg.access = Access::ReadWrite;
    else
        return fail(RegisterTableTr::tr("access must be \"ro\" or \"rw\""));

    const QJsonValue unit = object.value(QLatin1String("unit"));
    if (!unit.isUndefined() && !unit.isString())
        return fail(RegisterTableTr::tr("the unit must be a string"));
    reg.unit = unit.toString();
    const QJsonValue scale = object.value(QLatin1String("scale"));
    if (!scale.isUndefined() && (!scale.isDouble() || scale.toDouble() <= 0))
        return fail(RegisterTableTr::tr("the scale must be a positive number"));
    reg.scale = scale.isUndefined() ? 1.0 : scale.toDouble();

    const QJsonValue signBit = object.value(QLatin1String("sign_bit"));
    if (!signBit.isUndefined() && !signBit.isNull()) {
        if (!util::isWholeNumber(signBit) || signBit.toInt() < 1 || signBit.toInt() >= reg.size * 8)
            return fail(RegisterTableTr::tr("the sign bit must lie inside the register"));
        reg.signBit = signBit.toInt();
    }
    const ValueFormat format {reg.size, order, reg.signBit};
    const auto fits = [&](qint32 value) {
        return value >= minimumValue(format) && value <= maximumMagnitude(format);
    };

    const QJsonValue minimum = object.value(QLatin1String("min"));
    const QJsonValue maximum = object.value(QLatin1String("max"));
    if (!util::isWholeNumber(minimum) || !util::isWholeNumber(maximum))
        return fail(RegisterTableTr::tr("min and max must be whole numbers"));
    reg.minimum = minimum.toInt();
    reg.maximum = maximum.toInt();
    if (reg.minimum > reg.maximum)
        return fail(RegisterTableTr::tr("min is greater than max"));
    if (!fits(reg.minimum) || !fits(reg.maximum))
        return fail(RegisterTableTr::tr("the range %1..%2 does not fit a %3-byte register")
                        .arg(reg.minimum)
                        .arg(reg.maximum)
                        .arg(reg.size));
    const QJsonValue defaultValue = object.value(QLatin1String("default"));
    if (!defaultValue.isUndefined() && !defaultValue.isNull()) {
        // min and max already fit the register, so this also checks the default fits it.
        if (!util::isWholeNumber(defaultValue) || defaultValue.toInt() < reg.minimum
            || defaultValue.toInt() > reg.maximum)
            return fail(RegisterTableTr::tr("the default does not fit the register"));
        reg.defaultValue = defaultValue.toInt();
    }

    for (const QJsonValue &entry : object.value(QLatin1String("choices")).toArray()) {
        const QJsonObject choice = entry.toObject();
        const QJsonValue value = choice.value(QLatin1String("value"));
        const QString label = choice.value(QLatin1String("label")).toString();
        if (!util::isWholeNumber(value) || !fits(value.toInt()) || label.isEmpty())
            return fail(
                RegisterTableTr::tr("a choice needs a value that fits the register and a label"));
        reg.choices.append({value.toInt(), label});
    }
    for (const QJsonValue &entry : object.value(QLatin1String("bits")).toArray()) {
        const QJsonObject bit = entry.toObject();
        const QJsonValue index = bit.value(QLatin1String("bit"));
        const QString label = bit.value(QLatin1String("label")).toString();
        if (!util::isWholeNumber(index) || index.toInt() < 0 || index.toInt() >= reg.size * 8
            || label.isEmpty())
            return fail(
                RegisterTableTr::tr("a bit needs an index inside the register and a label"));
        reg.bits.append({index.toInt(), label});
    }
    reg.note = object.value(QLatin1String("note")).toString();
    return true;
}

} // namespace

std::optional<RegisterTable> RegisterTable::fromJson(const QByteArray &json, const QString &source,
                                                     QString *error)
{
    TableProblems problems(source);
    const auto finish = [&]() -> std::optional<RegisterTable> {
        if (error)
            *error = problems.message();
        return std::nullopt;
    };
    const auto root = parseTableObject(json, problems);
    if (!root)
        return finish();

    RegisterTable table;
    const auto family = familyFromKey(root->value(QLatin1String("family")).toString());
    if (!family) {
        problems.fail(RegisterTableTr::tr("unknown family \"%1\"")
                          .arg(root->value(QLatin1String("family")).toString()));
        return finish();
    }
    table.m_family = *family;
    table.m_title = root->value(QLatin1String("title")).toString(familyName(*family));
    const QString order = root->value(QLatin1String("byte_order")).toString();
    if (order == QLatin1String("little")) {
        table.m_byteOrder = ByteOrder::Little;
    } else if (order == QLatin1String("big")) {
        table.m_byteOrder = ByteOrder::Big;
    } else {
        problems.fail(RegisterTableTr::tr("byte_order must be \"little\" or \"big\""));
        return finish();
    }

    const QJsonValue registers = root->value(QLatin1String("registers"));
    if (!registers.isArray() || registers.toArray().isEmpty()) {
        problems.fail(RegisterTableTr::tr("there are no registers"));
        return finish();
    }
    QSet<QString> keys;
    for (const QJsonValue &entry : registers.toArray()) {
        Register reg;
        if (!entry.isObject()) {
            problems.fail(RegisterTableTr::tr("every register must be a JSON object"));
            return finish();
        }
        if (!parseRegister(entry.toObject(), table.m_byteOrder, reg, problems))
            return finish();
        if (keys.contains(reg.key)) {
            problems.fail(RegisterTableTr::tr("the key \"%1\" is used twice").arg(reg.key));
            return finish();
        }
        keys.insert(reg.key);
        table.m_registers.append(reg);
    }
    std::sort(table.m_registers.begin(), table.m_registers.end(),
              [](const Register &a, const Register &b) { return a.address < b.address; });
    for (int i = 1; i < table.m_registers.size(); ++i) {
        const Register &previous = table.m_registers.at(i - 1);
        const Register &current = table.m_registers.at(i);
        if (current.address < previous.end()) {
            problems.fail(RegisterTableTr::tr("registers \"%1\" and \"%2\" overlap at address %3")
                              .arg(previous.key, current.key)
                              .arg(current.address));
            return finish();
        }
    }
    QString factsError;
    const auto facts = parseTableFacts(*root, table.m_registers, &factsError);
    if (!facts) {
        problems.fail(factsError);
        return finish();
    }
    table.m_facts = *facts;
    return table;
}

const RegisterTable &RegisterTable::forFamily(Family family)
{
    static const std::map<Family, RegisterTable> tables = [] {
        std::map<Family, RegisterTable> loaded;
        for (const Family each : kAllFamilies) {
            const QString path = QStringLiteral(":/feetech/registers-%1.json").arg(familyKey(each));
            QString error;
            auto table = fromJson(readBuiltInTable(path), path, &error);
            if (!table || table->family() != each)
                qFatal("ServoBench: built-in register table is invalid: %s", qPrintable(error));
            loaded.emplace(each, std::move(*table));
        }
        return loaded;
    }();
    return tables.at(family);
}

const Register *RegisterTable::find(QStringView key) const
{
    for (const Register &reg : m_registers) {
        if (reg.key == key)
            return &reg;
    }
    return nullptr;
}

const Register *RegisterTable::at(int address) const
{
    for (const Register &reg : m_registers) {
        if (reg.address == address)
            return &reg;
    }
    return nullptr;
}

QVector<Block> RegisterTable::blocks() const
{
    QVector<Block> result;
    for (const Register &reg : m_registers) {
        if (!result.isEmpty() && result.last().address + result.last().size == reg.address)
            result.last().size += reg.size;
        else
            result.append({reg.address, reg.size});
    }
    return result;
}

std::optional<TorqueMode> RegisterTable::torqueMode(qint64 value) const
{
    for (const TorqueMode mode :
         {TorqueMode::Off, TorqueMode::On, TorqueMode::Damping, TorqueMode::CalibrateMiddle}) {
        if (torqueValue(mode) == std::optional<qint32>(qint32(value)) && value == qint32(value))
            return mode;
    }
    return std::nullopt;
}

QVector<Block> RegisterTable::ramBlocks() const
{
    QVector<Block> ram;
    for (const Register &reg : m_registers) {
        if (reg.storage != Storage::Ram)
            continue;
        if (!ram.isEmpty() && ram.last().address + ram.last().size == reg.address)
            ram.last().size += reg.size;
        else
            ram.append({reg.address, reg.size});
    }
    return ram;
}

const RegisterTable &RegisterTable::rawView()
{
    static const RegisterTable table = [] {
        RegisterTable raw;
        raw.m_raw = true;
        raw.m_title = RegisterTableTr::tr("Raw bytes (unknown model)");
        for (int address = 0; address < kRawViewSize; ++address) {
            Register reg;
            reg.address = address;
            reg.key = QStringLiteral("byte_%1").arg(address, 3, 10, QLatin1Char('0'));
            reg.label = RegisterTableTr::tr("Byte %1").arg(address);
            reg.storage = address < 40 ? Storage::Eeprom : Storage::Ram;
            reg.maximum = 255;
            raw.m_registers.append(reg);
        }
        return raw;
    }();
    return table;
}

qint32 defaultBaud(Family family)
{
    const Register *baud = RegisterTable::forFamily(family).find(u"baud_rate");
    return baudForCode(baud && baud->defaultValue ? *baud->defaultValue : 0);
}

QString baudText(qint32 baud)
{
    return baud >= 1000000 && baud % 1000000 == 0
        ? RegisterTableTr::tr("%1 Mbps").arg(baud / 1000000)
        : RegisterTableTr::tr("%L1 bps").arg(baud);
}

} // namespace feetech
