// Reading the tables' JSON files: the root object checked, the built-in resources.
#include "tablejson.h"
#include "registertabletr.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>

namespace feetech {

std::optional<QJsonObject> parseTableObject(const QByteArray &json, TableProblems &problems)
{
    QJsonParseError parseError {};
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        problems.fail(RegisterTableTr::tr("not valid JSON at offset %1: %2")
                          .arg(parseError.offset)
                          .arg(parseError.errorString()));
        return std::nullopt;
    }
    if (!document.isObject()) {
        problems.fail(RegisterTableTr::tr("the document is not a JSON object"));
        return std::nullopt;
    }
    const QJsonObject root = document.object();
    if (root.value(QLatin1String("format")).toInt(-1) != 1) {
        problems.fail(RegisterTableTr::tr("unsupported \"format\" (expected 1)"));
        return std::nullopt;
    }
    return root;
}

QByteArray readBuiltInTable(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("ServoBench: the built-in resource %s is missing", qPrintable(path));
    return file.readAll();
}

} // namespace feetech
