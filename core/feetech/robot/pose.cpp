// Pose files: JSON writing, strict validation on reading, atomic saving.
#include "pose.h"

#include "feetechpacket.h"
#include "jsonfile.h"
#include "modeltable.h"
#include "registertable.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace {

// Translation context for the messages of this file.
struct PoseTr
{
    Q_DECLARE_TR_FUNCTIONS(Pose)
};

} // namespace

namespace feetech {

namespace {

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

// The entries of one element of "servos".
constexpr char kPoseIdKey[] = "id";
constexpr char kBaudKey[] = "baud";
constexpr char kPositionKey[] = "position";

// One element of "servos"; nothing and *why (its detail the sentence) when it is not a valid
// entry.
std::optional<PoseEntry> parseEntry(const QJsonValue &value, util::FileError *why)
{
    using Code = util::FileError::Code;
    const auto fail = [&](Code code, const QString &sentence, const char *field = nullptr,
                          const QJsonValue &offending =
                              QJsonValue(QJsonValue::Undefined)) -> std::optional<PoseEntry> {
        *why = util::FileError(code, sentence).withField(QLatin1String(field));
        if (!offending.isUndefined())
            why->withValue(jsonText(offending));
        return std::nullopt;
    };
    if (!value.isObject())
        return fail(Code::WrongType, PoseTr::tr("not a JSON object"));
    const QJsonObject object = value.toObject();
    if (const auto unknown = util::firstUnknownKey(object, {kPoseIdKey, kBaudKey, kPositionKey})) {
        *why = util::FileError(Code::UnknownKey, PoseTr::tr("unknown entry \"%1\"").arg(*unknown))
                   .withField(*unknown);
        return std::nullopt;
    }
    for (const char *key : {kPoseIdKey, kBaudKey, kPositionKey}) {
        if (!object.contains(QLatin1String(key)))
            return fail(Code::MissingField, PoseTr::tr("\"%1\" is missing").arg(QLatin1String(key)),
                        key);
    }

    PoseEntry entry;
    const QJsonValue idValue = object.value(QLatin1String(kPoseIdKey));
    const std::optional<qint64> id = wholeNumber(idValue);
    if (!id || *id < 0 || *id > kMaxServoId)
        return fail(Code::BadValue,
                    PoseTr::tr("\"%1\": %2 is not a servo ID (0 to %3)")
                        .arg(QLatin1String(kPoseIdKey), jsonText(idValue))
                        .arg(kMaxServoId),
                    kPoseIdKey, idValue);
    entry.id = quint8(*id);

    const QJsonValue baudValue = object.value(QLatin1String(kBaudKey));
    const std::optional<qint64> baud = wholeNumber(baudValue);
    if (!baud || *baud != qint32(*baud) || !baudRates().contains(qint32(*baud)))
        return fail(Code::BadValue,
                    PoseTr::tr("\"%1\": %2 is not a Feetech baud rate in bps")
                        .arg(QLatin1String(kBaudKey), jsonText(baudValue)),
                    kBaudKey, baudValue);
    entry.baud = qint32(*baud);

    const QJsonValue positionValue = object.value(QLatin1String(kPositionKey));
    const std::optional<qint64> position = wholeNumber(positionValue);
    if (!position)
        return fail(Code::BadValue,
                    PoseTr::tr("\"%1\": %2 is not an integer number of steps")
                        .arg(QLatin1String(kPositionKey), jsonText(positionValue)),
                    kPositionKey, positionValue);
    if (std::abs(*position) > kPoseMaxMagnitude)
        return fail(Code::BadValue,
                    PoseTr::tr("\"%1\": %2 is out of range (%3 to %4)")
                        .arg(QLatin1String(kPositionKey), jsonText(positionValue))
                        .arg(-kPoseMaxMagnitude)
                        .arg(kPoseMaxMagnitude),
                    kPositionKey, positionValue);
    entry.position = qint32(*position);
    return entry;
}

// The top-level entries of a pose besides its format and version.
constexpr char kNameKey[] = "name";
constexpr char kServosKey[] = "servos";

// How a pose file names itself, and what it may hold at the top.
util::JsonFormat poseFormat()
{
    util::JsonFormat format;
    format.marker = kPoseFormatMarker;
    format.version = kPoseFormatVersion;
    format.keys = {kNameKey, kServosKey};
    format.notAnObject = PoseTr::tr("not a ServoBench pose (the document is not a JSON object)");
    format.wrongMarker = PoseTr::tr("not a ServoBench pose (\"%1\" is not \"%2\")");
    format.newerVersion = PoseTr::tr("the pose has format version %1 and was written by a newer "
                                     "ServoBench; this version reads format version %2 and older");
    return format;
}

} // namespace

const PoseEntry *Pose::find(const ServoAddress &servo) const
{
    const auto it = std::find_if(servos.begin(), servos.end(),
                                 [&](const PoseEntry &entry) { return entry.address() == servo; });
    return it == servos.end() ? nullptr : &*it;
}

QByteArray poseToJson(const Pose &pose)
{
    QJsonArray servos;
    for (const PoseEntry &entry : pose.servos) {
        QJsonObject object;
        object.insert(QLatin1String(kPoseIdKey), int(entry.id));
        object.insert(QLatin1String(kBaudKey), entry.baud);
        object.insert(QLatin1String(kPositionKey), entry.position);
        servos.append(object);
    }
    QJsonObject root;
    root.insert(QLatin1String(util::kFormatKey), QLatin1String(kPoseFormatMarker));
    root.insert(QLatin1String(util::kVersionKey), kPoseFormatVersion);
    if (!pose.name.isEmpty())
        root.insert(QLatin1String(kNameKey), pose.name);
    root.insert(QLatin1String(kServosKey), servos);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<Pose> poseFromJson(const QByteArray &json, util::FileError *error)
{
    using Code = util::FileError::Code;
    const std::optional<QJsonObject> root = util::parseVersionedObject(json, poseFormat(), error);
    if (!root)
        return std::nullopt;
    const auto fail = [&](const util::FileError &why) -> std::optional<Pose> {
        util::report(error, why);
        return std::nullopt;
    };

    Pose pose;
    const QJsonValue name = root->value(QLatin1String(kNameKey));
    if (!name.isUndefined() && !name.isString())
        return fail(util::FileError(Code::WrongType,
                                    PoseTr::tr("\"%1\" must be text").arg(QLatin1String(kNameKey)))
                        .withField(QLatin1String(kNameKey)));
    pose.name = name.toString();

    const QJsonValue servosValue = root->value(QLatin1String(kServosKey));
    if (!servosValue.isArray())
        return fail(util::FileError(
                        Code::MissingField,
                        PoseTr::tr("the pose has no \"%1\" list").arg(QLatin1String(kServosKey)))
                        .withField(QLatin1String(kServosKey)));
    const QJsonArray servos = servosValue.toArray();
    QSet<QPair<int, qint32>> seen;
    for (int i = 0; i < servos.size(); ++i) {
        util::FileError why;
        const std::optional<PoseEntry> entry = parseEntry(servos.at(i), &why);
        // Entries are numbered from 1, as a person counts them in the file.
        if (!entry)
            return fail(
                util::FileError(why.code(),
                                PoseTr::tr("servo entry %1: %2").arg(i + 1).arg(why.reason()))
                    .withField(why.field())
                    .withValue(why.value()));
        const QPair<int, qint32> address(entry->id, entry->baud);
        if (seen.contains(address))
            return fail(
                util::FileError(Code::Duplicate,
                                PoseTr::tr("servo entry %1: ID %2 at %3 bps is already in the pose")
                                    .arg(i + 1)
                                    .arg(entry->id)
                                    .arg(entry->baud))
                    .withField(QLatin1String(kPoseIdKey))
                    .withValue(QString::number(entry->id)));
        seen.insert(address);
        pose.servos.append(*entry);
    }
    return pose;
}

bool savePose(const QString &path, const Pose &pose, util::FileError *error)
{
    const QByteArray json = poseToJson(pose);
    util::FileError why;
    // Write nothing loadPose would refuse, so every saved pose loads again.
    const bool saved = poseFromJson(json, &why) && util::writeFileAtomically(path, json, &why);
    if (!saved)
        util::report(error, why.inFile(path, util::FileError::Action::Saving));
    return saved;
}

std::optional<Pose> loadPose(const QString &path, util::FileError *error)
{
    util::FileError why;
    std::optional<Pose> pose;
    if (const auto json = util::readFile(path, util::kMaxJsonFileBytes,
                                         PoseTr::tr("too large to be a pose"), &why))
        pose = poseFromJson(*json, &why);
    if (!pose)
        util::report(error, why.inFile(path));
    return pose;
}

} // namespace feetech
