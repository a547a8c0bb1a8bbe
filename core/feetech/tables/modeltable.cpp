// Loading and validating the model table (resources/feetech/models.json), and what it says.
#include "modeltable.h"

#include "jsonfile.h"
#include "registertabletr.h"
#include "tablejson.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>
#include <QSet>

namespace feetech {

std::optional<ModelTable> ModelTable::fromJson(const QByteArray &json, const QString &source,
                                               QString *error)
{
    TableProblems problems(source);
    const auto finish = [&]() -> std::optional<ModelTable> {
        if (error)
            *error = problems.message();
        return std::nullopt;
    };
    const auto root = parseTableObject(json, problems);
    if (!root)
        return finish();

    ModelTable table;
    QString ratesError;
    const auto rates = parseBaudRates(*root, &ratesError);
    if (!rates) {
        problems.fail(ratesError);
        return finish();
    }
    table.m_baudRates = *rates;
    const QJsonObject majors = root->value(QLatin1String("families_by_major")).toObject();
    for (auto it = majors.begin(); it != majors.end(); ++it) {
        bool ok = false;
        const int major = it.key().toInt(&ok);
        const auto family = familyFromKey(it.value().toString());
        if (!ok || major < 0 || major > 255 || !family) {
            problems.fail(
                RegisterTableTr::tr("families_by_major: \"%1\" is not a major number with a family")
                    .arg(it.key()));
            return finish();
        }
        table.m_familiesByMajor.append({major, *family});
    }
    QSet<int> seen;
    for (const QJsonValue &entry : root->value(QLatin1String("models")).toArray()) {
        const QJsonObject object = entry.toObject();
        ModelInfo model;
        const QJsonValue major = object.value(QLatin1String("major"));
        const QJsonValue minor = object.value(QLatin1String("minor"));
        model.name = object.value(QLatin1String("name")).toString();
        if (!util::isWholeNumber(major) || !util::isWholeNumber(minor) || major.toInt() < 0
            || major.toInt() > 255 || minor.toInt() < 0 || minor.toInt() > 255
            || model.name.isEmpty()) {
            problems.fail(
                RegisterTableTr::tr("model \"%1\": needs a name and major and minor numbers 0-255")
                    .arg(model.name));
            return finish();
        }
        model.major = major.toInt();
        model.minor = minor.toInt();
        const QJsonValue family = object.value(QLatin1String("family"));
        if (!family.isNull()) {
            model.family = familyFromKey(family.toString());
            if (!model.family) {
                problems.fail(RegisterTableTr::tr("model \"%1\": unknown family").arg(model.name));
                return finish();
            }
        }
        if (seen.contains(model.major * 256 + model.minor)) {
            problems.fail(RegisterTableTr::tr("model %1/%2 is listed twice")
                              .arg(model.major)
                              .arg(model.minor));
            return finish();
        }
        seen.insert(model.major * 256 + model.minor);
        table.m_models.append(model);
    }
    return table;
}

const ModelTable &ModelTable::builtIn()
{
    static const ModelTable table = [] {
        const QString path = QStringLiteral(":/feetech/models.json");
        QString error;
        auto loaded = fromJson(readBuiltInTable(path), path, &error);
        if (!loaded)
            qFatal("ServoBench: built-in model table is invalid: %s", qPrintable(error));
        return std::move(*loaded);
    }();
    return table;
}

ModelInfo ModelTable::identify(quint8 major, quint8 minor) const
{
    for (const ModelInfo &model : m_models) {
        if (model.major == major && model.minor == minor)
            return model;
    }
    ModelInfo unknown {major, minor, {}, std::nullopt};
    for (const auto &[familyMajor, family] : m_familiesByMajor) {
        if (familyMajor == major)
            unknown.family = family;
    }
    unknown.name = unknown.family
        ? RegisterTableTr::tr("%1 (model %2/%3)")
              .arg(familyName(*unknown.family))
              .arg(major)
              .arg(minor)
        : RegisterTableTr::tr("Unknown model %1/%2").arg(major).arg(minor);
    return unknown;
}

std::optional<ModelInfo> ModelTable::findByName(QStringView name) const
{
    // "SCS009/SCS0009" answers to either name.
    for (const ModelInfo &model : m_models) {
        for (const QString &alias : model.name.split(u'/')) {
            if (alias.compare(name, Qt::CaseInsensitive) == 0)
                return model;
        }
    }
    return std::nullopt;
}

quint16 modelNumber(quint8 major, quint8 minor, ByteOrder order)
{
    QByteArray bytes;
    bytes.append(char(major));
    bytes.append(char(minor));
    return decodeRaw(bytes, order);
}

QVector<qint32> baudRates()
{
    return ModelTable::builtIn().baudRates();
}

std::optional<int> baudCode(qint32 baud)
{
    const int code = int(baudRates().indexOf(baud));
    return code >= 0 ? std::optional<int>(code) : std::nullopt;
}

qint32 baudForCode(int code)
{
    const QVector<qint32> &rates = ModelTable::builtIn().baudRates();
    return code >= 0 && code < rates.size() ? rates.at(code) : 0;
}

} // namespace feetech
