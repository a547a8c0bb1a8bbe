// Pose files: JSON writing, strict validation on reading, atomic saving.
#include "feetech/pose.h"

#include "feetech/feetechpacket.h"
#include "feetech/registertable.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <QSaveFile>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace feetech {

namespace {

// Translation context for the messages of this file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(Pose)
};

constexpr char kFormatKey[] = "format";
constexpr char kVersionKey[] = "version";
constexpr char kNameKey[] = "name";
constexpr char kServosKey[] = "servos";
constexpr char kIdKey[] = "id";
constexpr char kBaudKey[] = "baud";
constexpr char kPositionKey[] = "position";

// A pose of 254 servos is a few kilobytes: anything far larger is a wrongly picked file (a log,
// a firmware image) and is not read whole just to be refused.
constexpr qint64 kMaxFileBytes = 1024 * 1024;

QString displayName(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// A whole JSON number, or nothing (strings, booleans, fractions, absurd magnitudes).
std::optional<qint64> wholeNumber(const QJsonValue &value)
{
    if (!value.isDouble())
        return std::nullopt;
    const double number = value.toDouble();
    if (!std::isfinite(number) || number != std::floor(number) || std::abs(number) > 1e15)
        return std::nullopt;
    return qint64(number);
}

QString jsonText(const QJsonValue &value)
{
    if (value.isString())
        return u'"' + value.toString() + u'"';
    if (value.isDouble())
        return QString::number(value.toDouble(), 'g', 15);
    if (value.isBool())
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (value.isNull())
        return QStringLiteral("null");
    return value.isArray() ? QStringLiteral("[…]") : QStringLiteral("{…}");
}

bool onlyKnownKeys(const QJsonObject &object, std::initializer_list<const char *> known,
                   QString *unknown)
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

// One element of "servos"; nothing and *why when it is not a valid entry.
std::optional<PoseEntry> parseEntry(const QJsonValue &value, QString *why)
{
    if (!value.isObject()) {
        *why = Tr::tr("not a JSON object");
        return std::nullopt;
    }
    const QJsonObject object = value.toObject();
    QString unknown;
    if (!onlyKnownKeys(object, {kIdKey, kBaudKey, kPositionKey}, &unknown)) {
        *why = Tr::tr("unknown entry \"%1\"").arg(unknown);
        return std::nullopt;
    }
    for (const char *key : {kIdKey, kBaudKey, kPositionKey}) {
        if (!object.contains(QLatin1String(key))) {
            *why = Tr::tr("\"%1\" is missing").arg(QLatin1String(key));
            return std::nullopt;
        }
    }

    PoseEntry entry;
    const QJsonValue idValue = object.value(QLatin1String(kIdKey));
    const std::optional<qint64> id = wholeNumber(idValue);
    if (!id || *id < 0 || *id > kMaxServoId) {
        *why = Tr::tr("\"%1\": %2 is not a servo ID (0 to %3)")
                   .arg(QLatin1String(kIdKey), jsonText(idValue))
                   .arg(kMaxServoId);
        return std::nullopt;
    }
    entry.id = quint8(*id);

    const QJsonValue baudValue = object.value(QLatin1String(kBaudKey));
    const std::optional<qint64> baud = wholeNumber(baudValue);
    if (!baud || *baud != qint32(*baud) || !baudRates().contains(qint32(*baud))) {
        *why = Tr::tr("\"%1\": %2 is not a Feetech baud rate in bps")
                   .arg(QLatin1String(kBaudKey), jsonText(baudValue));
        return std::nullopt;
    }
    entry.baud = qint32(*baud);

    const QJsonValue positionValue = object.value(QLatin1String(kPositionKey));
    const std::optional<qint64> position = wholeNumber(positionValue);
    if (!position) {
        *why = Tr::tr("\"%1\": %2 is not an integer number of steps")
                   .arg(QLatin1String(kPositionKey), jsonText(positionValue));
        return std::nullopt;
    }
    if (std::abs(*position) > kPoseMaxMagnitude) {
        *why = Tr::tr("\"%1\": %2 is out of range (%3 to %4)")
                   .arg(QLatin1String(kPositionKey), jsonText(positionValue))
                   .arg(-kPoseMaxMagnitude)
                   .arg(kPoseMaxMagnitude);
        return std::nullopt;
    }
    entry.position = qint32(*position);
    return entry;
}

} // namespace

const PoseEntry *Pose::find(quint8 id, qint32 baud) const
{
    const auto it = std::find_if(servos.begin(), servos.end(), [&](const PoseEntry &entry) {
        return entry.id == id && entry.baud == baud;
    });
    return it == servos.end() ? nullptr : &*it;
}

QByteArray poseToJson(const Pose &pose)
{
    QJsonArray servos;
    for (const PoseEntry &entry : pose.servos) {
        QJsonObject object;
        object.insert(QLatin1String(kIdKey), int(entry.id));
        object.insert(QLatin1String(kBaudKey), entry.baud);
        object.insert(QLatin1String(kPositionKey), entry.position);
        servos.append(object);
    }
    QJsonObject root;
    root.insert(QLatin1String(kFormatKey), QLatin1String(kPoseFormatMarker));
    root.insert(QLatin1String(kVersionKey), kPoseFormatVersion);
    if (!pose.name.isEmpty())
        root.insert(QLatin1String(kNameKey), pose.name);
    root.insert(QLatin1String(kServosKey), servos);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<Pose> poseFromJson(const QByteArray &json, QString *error)
{
    const auto fail = [&](const QString &why) -> std::optional<Pose> {
        if (error)
            *error = why;
        return std::nullopt;
    };

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(Tr::tr("not valid JSON: %1 at offset %2")
                        .arg(parseError.errorString())
                        .arg(parseError.offset));
    if (!document.isObject())
        return fail(Tr::tr("not a ServoBench pose (the document is not a JSON object)"));
    const QJsonObject root = document.object();

    // The marker and version first: a profile or a newer pose must be named as such, not as a
    // list of unexpected entries.
    if (root.value(QLatin1String(kFormatKey)).toString() != QLatin1String(kPoseFormatMarker))
        return fail(Tr::tr("not a ServoBench pose (\"%1\" is not \"%2\")")
                        .arg(QLatin1String(kFormatKey), QLatin1String(kPoseFormatMarker)));
    const std::optional<qint64> version = wholeNumber(root.value(QLatin1String(kVersionKey)));
    if (!version)
        return fail(Tr::tr("the format version is missing or not a whole number"));
    if (*version > kPoseFormatVersion)
        return fail(Tr::tr("the pose has format version %1 and was written by a newer "
                           "ServoBench; this version reads format version %2 and older")
                        .arg(*version)
                        .arg(kPoseFormatVersion));
    if (*version < 1)
        return fail(Tr::tr("unknown format version %1").arg(*version));

    QString unknown;
    if (!onlyKnownKeys(root, {kFormatKey, kVersionKey, kNameKey, kServosKey}, &unknown))
        return fail(Tr::tr("unknown entry \"%1\"").arg(unknown));

    Pose pose;
    const QJsonValue name = root.value(QLatin1String(kNameKey));
    if (!name.isUndefined() && !name.isString())
        return fail(Tr::tr("\"%1\" must be text").arg(QLatin1String(kNameKey)));
    pose.name = name.toString();

    const QJsonValue servosValue = root.value(QLatin1String(kServosKey));
    if (!servosValue.isArray())
        return fail(Tr::tr("the pose has no \"%1\" list").arg(QLatin1String(kServosKey)));
    const QJsonArray servos = servosValue.toArray();
    QSet<QPair<int, qint32>> seen;
    for (int i = 0; i < servos.size(); ++i) {
        QString why;
        const std::optional<PoseEntry> entry = parseEntry(servos.at(i), &why);
        // Entries are numbered from 1, as a person counts them in the file.
        if (!entry)
            return fail(Tr::tr("servo entry %1: %2").arg(i + 1).arg(why));
        const QPair<int, qint32> address(entry->id, entry->baud);
        if (seen.contains(address))
            return fail(Tr::tr("servo entry %1: ID %2 at %3 bps is already in the pose")
                            .arg(i + 1)
                            .arg(entry->id)
                            .arg(entry->baud));
        seen.insert(address);
        pose.servos.append(*entry);
    }
    return pose;
}

bool savePose(const QString &path, const Pose &pose, QString *error)
{
    const auto fail = [&](const QString &why) {
        if (error)
            *error = Tr::tr("%1 was not saved: %2").arg(displayName(path), why);
        return false;
    };
    const QByteArray json = poseToJson(pose);
    // Write nothing loadPose would refuse, so every saved pose loads again.
    QString why;
    const std::optional<Pose> check = poseFromJson(json, &why);
    if (!check)
        return fail(why);

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(file.errorString());
    if (file.write(json) != json.size()) {
        const QString reason = file.errorString();
        file.cancelWriting();
        return fail(reason);
    }
    if (!file.commit())
        return fail(file.errorString());
    return true;
}

std::optional<Pose> loadPose(const QString &path, QString *error)
{
    const auto fail = [&](const QString &why) -> std::optional<Pose> {
        if (error)
            *error = Tr::tr("%1: %2").arg(displayName(path), why);
        return std::nullopt;
    };
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return fail(file.errorString());
    if (file.size() > kMaxFileBytes)
        return fail(Tr::tr("too large to be a pose"));
    const QByteArray json = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return fail(file.errorString());
    QString why;
    std::optional<Pose> pose = poseFromJson(json, &why);
    if (!pose)
        return fail(why);
    return pose;
}

} // namespace feetech
