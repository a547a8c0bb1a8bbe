// Reading, checking and saving the JSON files that profiles and poses are kept in.
#include "jsonfile.h"

#include "savefile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QJsonValue>

#include <algorithm>
#include <cmath>

namespace util {

namespace {

QString displayName(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

} // namespace

std::optional<QByteArray> readFile(const QString &path, qint64 maxBytes, const QString &tooLarge,
                                   QString *why)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *why = file.errorString();
        return std::nullopt;
    }
    if (file.size() > maxBytes) {
        *why = tooLarge;
        return std::nullopt;
    }
    QByteArray data = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        *why = file.errorString();
        return std::nullopt;
    }
    return data;
}

bool writeFileAtomically(const QString &path, const QByteArray &data, QString *why)
{
    SavingFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        *why = file.errorString();
        return false;
    }
    if (file.device().write(data) != data.size()) {
        *why = file.errorString();
        file.cancel();
        return false;
    }
    if (!file.commit()) {
        *why = file.errorString();
        return false;
    }
    return true;
}

std::optional<QJsonObject> parseVersionedObject(const QByteArray &json, const JsonFormat &format,
                                                QString *error)
{
    const auto fail = [&](const QString &why) -> std::optional<QJsonObject> {
        if (error)
            *error = why;
        return std::nullopt;
    };

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(QCoreApplication::translate("util", "not valid JSON: %1 at offset %2")
                        .arg(parseError.errorString())
                        .arg(parseError.offset));
    if (!document.isObject())
        return fail(format.notAnObject);
    const QJsonObject root = document.object();

    // The marker and the version come before anything else: a file of another kind, or from a
    // newer format, should be named as such, not as a list of unexpected entries.
    if (root.value(QLatin1String(kFormatKey)).toString() != QLatin1String(format.marker))
        return fail(
            format.wrongMarker.arg(QLatin1String(kFormatKey), QLatin1String(format.marker)));
    const QJsonValue versionValue = root.value(QLatin1String(kVersionKey));
    const double version = versionValue.toDouble();
    if (!versionValue.isDouble() || !std::isfinite(version) || version != std::floor(version))
        return fail(QCoreApplication::translate(
            "util", "the format version is missing or not a whole number"));
    if (version > format.version)
        return fail(format.newerVersion.arg(QString::number(version, 'g', 15)).arg(format.version));
    if (version < 1)
        return fail(QCoreApplication::translate("util", "unknown format version %1")
                        .arg(QString::number(version, 'g', 15)));
    QString unknown;
    if (!onlyKnownKeys(root, QVector<const char *> {kFormatKey, kVersionKey} + format.keys,
                       &unknown))
        return fail(QCoreApplication::translate("util", "unknown entry \"%1\"").arg(unknown));
    return root;
}

bool onlyKnownKeys(const QJsonObject &object, const QVector<const char *> &known, QString *unknown)
{
    for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
        const QString key = it.key();
        const bool found = std::any_of(known.begin(), known.end(), [&](const char *entry) {
            return key == QLatin1String(entry);
        });
        if (!found) {
            *unknown = key;
            return false;
        }
    }
    return true;
}

QString fileError(const QString &path, const QString &why)
{
    return QCoreApplication::translate("util", "%1: %2").arg(displayName(path), why);
}

QString notSavedError(const QString &path, const QString &why)
{
    return QCoreApplication::translate("util", "%1 was not saved: %2").arg(displayName(path), why);
}

} // namespace util
