// Versioned JSON files (profiles, poses): size-limited reading, format checks, atomic saving.
#pragma once

#include "fileerror.h"

#include <QByteArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QVector>

#include <optional>

namespace util {

// The entries every versioned ServoBench file carries.
inline constexpr char kFormatKey[] = "format";
inline constexpr char kVersionKey[] = "version";

// ServoBench files are a few kilobytes: anything far larger is a wrongly picked file (a log, a
// firmware image) and is not read whole just to be refused.
inline constexpr qint64 kMaxJsonFileBytes = 1024 * 1024;

// What sets one kind of file apart. The sentences name the kind ("not a ServoBench pose"), so
// the caller translates them in its own context.
struct JsonFormat
{
    const char *marker = nullptr; // the value of "format"
    int version = 0; // the newest format version this build reads
    QVector<const char *> keys; // the entries the root may have besides format and version
    QString notAnObject; // the document is valid JSON but not an object
    QString wrongMarker; // %1: the format key, %2: the marker
    QString newerVersion; // %1: the file's version, %2: `version`
};

// A JSON number that is a whole number a file may hold (an ID, a step count), not 1.5 or 1e300.
bool isWholeNumber(const QJsonValue &value);

// The whole file, or nothing and *error naming the file: CannotRead (the file system's words),
// or TooLarge (the sentence `tooLarge`) when the file is larger than maxBytes.
std::optional<QByteArray> readFile(const QString &path, qint64 maxBytes, const QString &tooLarge,
                                   FileError *error);

// Writes atomically (QSaveFile): the whole new file or the old one untouched. False and *error
// (CannotWrite with the file system's words, naming the file) when it could not.
bool writeFileAtomically(const QString &path, const QByteArray &data, FileError *error);

// The document's root object once it is valid JSON, carries format.marker, a whole version from
// 1 to format.version and no other entry than those and format.keys; otherwise nothing and
// *error (when given) says why, naming no file.
std::optional<QJsonObject> parseVersionedObject(const QByteArray &json, const JsonFormat &format,
                                                FileError *error = nullptr);

// The first key of `object` that is not among `known`; nothing when every key is.
std::optional<QString> firstUnknownKey(const QJsonObject &object,
                                       const QVector<const char *> &known);

} // namespace util
