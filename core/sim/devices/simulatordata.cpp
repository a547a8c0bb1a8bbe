// Reads resources/feetech/simulator.json, refusing a malformed file with the field at fault.
#include "simulatordata.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include <cmath>
#include <limits>

namespace {

struct SimulatorDataTr
{
    Q_DECLARE_TR_FUNCTIONS(SimulatorData)
};

} // namespace

namespace sim {

namespace {

constexpr int kFormat = 1;
constexpr char kBuiltInPath[] = ":/feetech/simulator.json";

// Thrown inside parse() only: the dotted path of the field and what is wrong with it.
struct FieldError
{
    QString field;
    QString why;
};

QString unknownKey(const QJsonObject &object, const QStringList &known)
{
    for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
        if (!known.contains(it.key()))
            return it.key();
    }
    return {};
}

QJsonObject objectAt(const QJsonObject &parent, const QString &key, const QString &field,
                     bool required)
{
    const QJsonValue value = parent.value(key);
    if (value.isUndefined() && !required)
        return {};
    if (!value.isObject())
        throw FieldError {field, SimulatorDataTr::tr("must be an object")};
    return value.toObject();
}

qint64 wholeNumber(const QJsonValue &value, const QString &field, qint64 minimum, qint64 maximum)
{
    const double number = value.toDouble(std::numeric_limits<double>::quiet_NaN());
    if (!value.isDouble() || number != std::floor(number) || number < double(minimum)
        || number > double(maximum))
        throw FieldError {
            field,
            SimulatorDataTr::tr("must be a whole number from %1 to %2").arg(minimum).arg(maximum)};
    return qint64(number);
}

void readDefaults(const QJsonObject &object, const QString &field, QHash<QString, qint32> &into)
{
    for (auto it = object.constBegin(); it != object.constEnd(); ++it)
        into.insert(it.key(),
                    qint32(wholeNumber(it.value(), field + u'.' + it.key(),
                                       std::numeric_limits<qint32>::min(),
                                       std::numeric_limits<qint32>::max())));
}

} // namespace

const SimulatorData &SimulatorData::builtIn()
{
    static const SimulatorData data = [] {
        QFile file(QString::fromLatin1(kBuiltInPath));
        if (!file.open(QIODevice::ReadOnly))
            qFatal("ServoBench: the built-in resource %s is missing", kBuiltInPath);
        QString error;
        const auto parsed = parse(file.readAll(), QStringLiteral("simulator.json"), &error);
        if (!parsed)
            qFatal("ServoBench: built-in simulator data is invalid: %s", qPrintable(error));
        return *parsed;
    }();
    return data;
}

std::optional<SimulatorData> SimulatorData::parse(const QByteArray &json, const QString &fileName,
                                                  QString *error)
{
    try {
        QJsonParseError parseError;
        const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
        if (parseError.error != QJsonParseError::NoError)
            throw FieldError {{}, parseError.errorString()};
        if (!document.isObject())
            throw FieldError {{}, SimulatorDataTr::tr("the document is not a JSON object")};
        const QJsonObject root = document.object();
        const QString unknown = unknownKey(
            root,
            {QStringLiteral("format"), QStringLiteral("defaults"), QStringLiteral("families")});
        if (!unknown.isEmpty())
            throw FieldError {unknown, SimulatorDataTr::tr("is not a field of this file")};
        const QJsonValue format = root.value(QLatin1String("format"));
        if (!format.isDouble() || format.toDouble() != kFormat)
            throw FieldError {QStringLiteral("format"),
                              SimulatorDataTr::tr("must be %1").arg(kFormat)};

        QHash<QString, qint32> common;
        readDefaults(objectAt(root, QStringLiteral("defaults"), QStringLiteral("defaults"), false),
                     QStringLiteral("defaults"), common);
        const QJsonObject families =
            objectAt(root, QStringLiteral("families"), QStringLiteral("families"), true);
        const QString stray = [&families] {
            for (auto it = families.constBegin(); it != families.constEnd(); ++it) {
                if (!feetech::familyFromKey(it.key()))
                    return it.key();
            }
            return QString();
        }();
        if (!stray.isEmpty())
            throw FieldError {QStringLiteral("families.") + stray,
                              SimulatorDataTr::tr("is not a Feetech family (scs, sts, sms, hls)")};

        SimulatorData data;
        for (const feetech::Family family : feetech::kAllFamilies) {
            const QString key = feetech::familyKey(family);
            const QString field = QStringLiteral("families.") + key;
            const QJsonObject object = objectAt(families, key, field, true);
            const QString extra = unknownKey(
                object,
                {QStringLiteral("firmware"), QStringLiteral("defaults"), QStringLiteral("note")});
            if (!extra.isEmpty())
                throw FieldError {field + u'.' + extra,
                                  SimulatorDataTr::tr("is not a field of a family")};
            const QJsonObject firmware = objectAt(object, QStringLiteral("firmware"),
                                                  field + QStringLiteral(".firmware"), true);
            FamilyData &entry = data.m_families[index(family)];
            entry.firmware.major =
                int(wholeNumber(firmware.value(QLatin1String("major")),
                                field + QStringLiteral(".firmware.major"), 0, 255));
            entry.firmware.minor =
                int(wholeNumber(firmware.value(QLatin1String("minor")),
                                field + QStringLiteral(".firmware.minor"), 0, 255));
            entry.defaults = common;
            readDefaults(objectAt(object, QStringLiteral("defaults"),
                                  field + QStringLiteral(".defaults"), false),
                         field + QStringLiteral(".defaults"), entry.defaults);
        }
        return data;
    } catch (const FieldError &failure) {
        if (error)
            *error = failure.field.isEmpty()
                ? SimulatorDataTr::tr("%1: %2").arg(fileName, failure.why)
                : SimulatorDataTr::tr("%1: %2 %3").arg(fileName, failure.field, failure.why);
        return std::nullopt;
    }
}

SimulatedFirmware SimulatorData::firmware(feetech::Family family) const
{
    return m_families[index(family)].firmware;
}

std::optional<qint32> SimulatorData::fallbackDefault(feetech::Family family, QStringView key) const
{
    const auto &defaults = m_families[index(family)].defaults;
    const auto found = defaults.constFind(key.toString());
    if (found == defaults.constEnd())
        return std::nullopt;
    return *found;
}

std::size_t SimulatorData::index(feetech::Family family)
{
    for (std::size_t i = 0; i < std::size(feetech::kAllFamilies); ++i) {
        if (feetech::kAllFamilies[i] == family)
            return i;
    }
    return 0;
}

} // namespace sim
