// Reading, checking and saving the JSON files that profiles and poses are kept in.
#include "jsonfile.h"

#include "savefile.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QJsonValue>

#include <algorithm>
#include <cmath>

namespace util {

bool isWholeNumber(const QJsonValue &value)
{
    return value.isDouble() && std::isfinite(value.toDouble())
        && value.toDouble() == std::floor(value.toDouble()) && std::abs(value.toDouble()) < 1e9;
}

std::optional<QByteArray> readFile(const QString &path, qint64 maxBytes, const QString &tooLarge,
                                   FileError *error)
{
    QFile file(path);
    const auto fail = [&](FileError::Code code, const QString &why) -> std::optional<QByteArray> {
        report(error, FileError(code, why).inFile(path));
        return std::nullopt;
    };
    if (!file.open(QIODevice::ReadOnly))
        return fail(FileError::Code::CannotRead, file.errorString());
    if (file.size() > maxBytes)
        return fail(FileError::Code::TooLarge, tooLarge);
    QByteArray data = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return fail(FileError::Code::CannotRead, file.errorString());
    return data;
}

bool writeFileAtomically(const QString &path, const QByteArray &data, FileError *error)
{
    SavingFile file(path);
    const auto fail = [&]() {
        report(error,
               FileError(FileError::Code::CannotWrite, file.errorString())
                   .inFile(path, FileError::Action::Saving));
        return false;
    };
    if (!file.open(QIODevice::WriteOnly))
        return fail();
    if (file.device().write(data) != data.size()) {
        // The reason is taken before cancel(), which would replace it with its own.
        const bool failed = fail();
        file.cancel();
        return failed;
    }
    if (!file.commit())
        return fail();
    return true;
}

std::optional<QJsonObject> parseVersionedObject(const QByteArray &json, const JsonFormat &format,
                                                FileError *error)
{
    using Code = FileError::Code;
    const auto fail = [&](const FileError &why) -> std::optional<QJsonObject> {
        report(error, why);
        return std::nullopt;
    };

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(FileError(Code::NotJson, parseError.errorString())
                        .withValue(QString::number(parseError.offset)));
    if (!document.isObject())
        return fail(FileError(Code::NotAnObject, format.notAnObject));
    const QJsonObject root = document.object();

    // The marker and the version come before anything else: a file of another kind, or from a
    // newer format, should be named as such, not as a list of unexpected entries.
    if (root.value(QLatin1String(kFormatKey)).toString() != QLatin1String(format.marker))
        return fail(FileError(Code::WrongFormat,
                              format.wrongMarker.arg(QLatin1String(kFormatKey),
                                                     QLatin1String(format.marker)))
                        .withField(QLatin1String(kFormatKey)));
    const QJsonValue versionValue = root.value(QLatin1String(kVersionKey));
    const double version = versionValue.toDouble();
    if (!versionValue.isDouble() || !std::isfinite(version) || version != std::floor(version))
        return fail(FileError(Code::BadVersion).withField(QLatin1String(kVersionKey)));
    const QString versionText = QString::number(version, 'g', 15);
    if (version > format.version)
        return fail(
            FileError(Code::NewerVersion, format.newerVersion.arg(versionText).arg(format.version))
                .withField(QLatin1String(kVersionKey))
                .withValue(versionText));
    if (version < 1)
        return fail(FileError(Code::UnknownVersion)
                        .withField(QLatin1String(kVersionKey))
                        .withValue(versionText));
    if (const auto unknown =
            firstUnknownKey(root, QVector<const char *> {kFormatKey, kVersionKey} + format.keys))
        return fail(FileError(Code::UnknownKey).withField(*unknown));
    return root;
}

std::optional<QString> firstUnknownKey(const QJsonObject &object,
                                       const QVector<const char *> &known)
{
    for (auto it = object.constBegin(); it != object.constEnd(); ++it) {
        const QString key = it.key();
        const bool found = std::any_of(known.begin(), known.end(), [&](const char *entry) {
            return key == QLatin1String(entry);
        });
        if (!found)
            return key;
    }
    return std::nullopt;
}

} // namespace util
