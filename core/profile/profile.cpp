// JSON parameter profiles: writing in user units, strict validation on reading, the device diff.
#include "profile.h"

#include "jsonfile.h"

#include <QCoreApplication>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>

#include <cmath>

namespace {

// Translation context for the messages of this file.
struct ProfileTr
{
    Q_DECLARE_TR_FUNCTIONS(Profile)
};

} // namespace

namespace profile {

namespace {

constexpr char kFamilyKey[] = "family";
constexpr char kModelKey[] = "model";
constexpr char kSavedKey[] = "saved";
constexpr char kNoteKey[] = "note";
constexpr char kParametersKey[] = "parameters";

// How far user value / scale may sit from a whole raw value and still count as one: decimal
// scales such as 0.1 V do not divide exactly in binary floating point.
constexpr double kRawTolerance = 1e-6;

// On/off parameters travel as JSON booleans so a hand-edited profile reads naturally.
bool isSwitch(const model::Definition &definition)
{
    if (definition.choices.size() != 2)
        return false;
    const qint64 first = definition.choices.at(0).value;
    const qint64 second = definition.choices.at(1).value;
    return (first == 0 && second == 1) || (first == 1 && second == 0);
}

const model::Definition *findDefinition(const QVector<model::Definition> &definitions,
                                        const QString &key)
{
    for (const model::Definition &definition : definitions) {
        if (definition.key == key)
            return &definition;
    }
    return nullptr;
}

// A value as it appears in the file, for messages: numbers in user units, switches as JSON.
// The lower end of a range goes without its unit ("500 to 1500 µs"), as people write it.
QString userText(const model::Definition &definition, double user, bool withUnit = true)
{
    if (isSwitch(definition))
        return user != 0 ? QStringLiteral("true") : QStringLiteral("false");
    QString text = QString::number(user, 'g', 15);
    if (withUnit && !definition.unit.isEmpty())
        text += u' ' + definition.unit;
    return text;
}

QString rawText(const model::Definition &definition, qint64 raw, bool withUnit = true)
{
    return userText(definition, double(raw) * definition.scale, withUnit);
}

QJsonValue jsonValue(const model::Definition &definition, qint64 raw)
{
    if (isSwitch(definition))
        return raw != 0;
    if (definition.scale == 1.0)
        return raw;
    return double(raw) * definition.scale;
}

// The raw value a file entry stands for, or nothing and *error (WrongType or BadValue, its
// detail saying why) when it has the wrong type, lies outside the definition's range or falls
// between two raw steps.
std::optional<qint64> rawValue(const model::Definition &definition, const QJsonValue &value,
                               util::FileError *error)
{
    using Code = util::FileError::Code;
    const auto fail = [&](Code code, const QString &why) -> std::optional<qint64> {
        *error = util::FileError(code, why).withField(definition.key);
        return std::nullopt;
    };
    double raw = 0;
    double user = 0;
    if (isSwitch(definition)) {
        if (!value.isBool())
            return fail(Code::WrongType, ProfileTr::tr("expected true or false"));
        raw = value.toBool() ? 1 : 0;
        user = raw;
    } else {
        if (!value.isDouble())
            return fail(Code::WrongType, ProfileTr::tr("expected a number"));
        user = value.toDouble();
        raw = user / definition.scale;
    }
    // The range check comes first so that llround below only ever sees a representable value.
    if (!std::isfinite(raw) || raw < double(definition.minimum) - kRawTolerance
        || raw > double(definition.maximum) + kRawTolerance) {
        return fail(Code::BadValue,
                    ProfileTr::tr("%1 is out of range (%2 to %3)")
                        .arg(userText(definition, user),
                             rawText(definition, definition.minimum, false),
                             rawText(definition, definition.maximum)));
    }
    const qint64 rounded = std::llround(raw);
    if (std::abs(raw - double(rounded)) > kRawTolerance) {
        return fail(
            Code::BadValue,
            definition.scale == 1.0
                ? ProfileTr::tr("%1 is not a whole number").arg(userText(definition, user))
                : ProfileTr::tr("%1 is not a multiple of %2")
                      .arg(userText(definition, user), userText(definition, definition.scale)));
    }
    return rounded;
}

bool optionalText(const QJsonObject &root, const char *key, QString *text)
{
    const QJsonValue value = root.value(QLatin1String(key));
    if (value.isUndefined())
        return true;
    if (!value.isString())
        return false;
    *text = value.toString();
    return true;
}

// How a profile file names itself, and what it may hold at the top.
util::JsonFormat profileFormat()
{
    return {
        kFormatMarker,
        kFormatVersion,
        {kFamilyKey, kModelKey, kSavedKey, kNoteKey, kParametersKey},
        ProfileTr::tr("not a ServoBench profile (the document is not a JSON object)"),
        ProfileTr::tr("not a ServoBench profile (\"%1\" is not \"%2\")"),
        ProfileTr::tr("the profile has format version %1 and was written by a newer ServoBench; "
                      "this version reads format version %2 and older")};
}

} // namespace

std::optional<qint64> Profile::value(const QString &key) const
{
    for (const ProfileValue &entry : values) {
        if (entry.key == key)
            return entry.raw;
    }
    return std::nullopt;
}

QByteArray toJson(const Profile &profile, const QVector<model::Definition> &definitions)
{
    QJsonObject parameters;
    for (const ProfileValue &entry : profile.values) {
        // Without its definition a raw value has no unit or scale to be written in.
        if (const model::Definition *definition = findDefinition(definitions, entry.key))
            parameters.insert(entry.key, jsonValue(*definition, entry.raw));
    }
    QJsonObject root;
    root.insert(QLatin1String(util::kFormatKey), QLatin1String(kFormatMarker));
    root.insert(QLatin1String(util::kVersionKey), kFormatVersion);
    root.insert(QLatin1String(kFamilyKey), profile.family);
    root.insert(QLatin1String(kModelKey), profile.model);
    // UTC, so the time means the same wherever the file is opened.
    if (profile.saved.isValid())
        root.insert(QLatin1String(kSavedKey), profile.saved.toUTC().toString(Qt::ISODate));
    if (!profile.note.isEmpty())
        root.insert(QLatin1String(kNoteKey), profile.note);
    root.insert(QLatin1String(kParametersKey), parameters);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

bool save(const QString &path, const Profile &profile,
          const QVector<model::Definition> &definitions, util::FileError *error)
{
    using Code = util::FileError::Code;
    const auto fail = [&](util::FileError why) {
        util::report(error, why.inFile(path, util::FileError::Action::Saving));
        return false;
    };
    // toJson would drop such a value without a word; the user must hear that it cannot be saved.
    for (const ProfileValue &entry : profile.values) {
        if (!findDefinition(definitions, entry.key))
            return fail(util::FileError(Code::UnknownKey,
                                        ProfileTr::tr("unknown parameter \"%1\"").arg(entry.key))
                            .withField(entry.key));
    }
    const QByteArray json = toJson(profile, definitions);
    // Write nothing that load() would refuse, so every saved profile can be loaded again.
    util::FileError why;
    const std::optional<Profile> check = parse(json, profile.family, definitions, &why);
    if (!check)
        return fail(why);
    // A switch holding neither 0 nor 1 would come back as 1: refuse rather than change it.
    for (const ProfileValue &entry : profile.values) {
        const model::Definition *definition = findDefinition(definitions, entry.key);
        if (definition->access != model::Access::ReadOnly && check->value(entry.key) != entry.raw)
            return fail(
                util::FileError(Code::BadValue,
                                ProfileTr::tr("%1: the raw value %2 cannot be kept in a profile")
                                    .arg(entry.key)
                                    .arg(entry.raw))
                    .withField(entry.key)
                    .withValue(QString::number(entry.raw)));
    }
    return util::writeFileAtomically(path, json, error);
}

std::optional<Profile> parse(const QByteArray &json, const QString &expectedFamily,
                             const QVector<model::Definition> &definitions, util::FileError *error)
{
    using Code = util::FileError::Code;
    const auto fail = [&](Code code, const QString &why,
                          const char *field = nullptr) -> std::optional<Profile> {
        util::report(error, util::FileError(code, why).withField(QLatin1String(field)));
        return std::nullopt;
    };
    const std::optional<QJsonObject> parsed =
        util::parseVersionedObject(json, profileFormat(), error);
    if (!parsed)
        return std::nullopt;
    const QJsonObject &root = *parsed;

    Profile profile;
    const QJsonValue family = root.value(QLatin1String(kFamilyKey));
    if (!family.isString() || family.toString().isEmpty())
        return fail(Code::MissingField, ProfileTr::tr("the profile names no servo family"),
                    kFamilyKey);
    profile.family = family.toString();
    if (profile.family != expectedFamily)
        return fail(Code::WrongServos,
                    ProfileTr::tr("the profile is for \"%1\" servos, not \"%2\"")
                        .arg(profile.family, expectedFamily),
                    kFamilyKey);
    if (!optionalText(root, kModelKey, &profile.model))
        return fail(Code::WrongType,
                    ProfileTr::tr("\"%1\" must be text").arg(QLatin1String(kModelKey)), kModelKey);
    if (!optionalText(root, kNoteKey, &profile.note))
        return fail(Code::WrongType,
                    ProfileTr::tr("\"%1\" must be text").arg(QLatin1String(kNoteKey)), kNoteKey);
    QString saved;
    if (!optionalText(root, kSavedKey, &saved))
        return fail(Code::WrongType,
                    ProfileTr::tr("\"%1\" must be text").arg(QLatin1String(kSavedKey)), kSavedKey);
    if (!saved.isEmpty()) {
        profile.saved = QDateTime::fromString(saved, Qt::ISODate);
        if (!profile.saved.isValid())
            return fail(Code::BadValue,
                        ProfileTr::tr("\"%1\": \"%2\" is not an ISO 8601 date and time")
                            .arg(QLatin1String(kSavedKey), saved),
                        kSavedKey);
    }

    const QJsonValue parametersValue = root.value(QLatin1String(kParametersKey));
    if (!parametersValue.isObject())
        return fail(
            Code::MissingField,
            ProfileTr::tr("the profile has no \"%1\" object").arg(QLatin1String(kParametersKey)),
            kParametersKey);
    const QJsonObject parameters = parametersValue.toObject();

    QHash<QString, int> rows;
    for (int row = 0; row < definitions.size(); ++row)
        rows.insert(definitions.at(row).key, row);
    QVector<std::optional<qint64>> raws(definitions.size());
    for (auto it = parameters.constBegin(); it != parameters.constEnd(); ++it) {
        const int row = rows.value(it.key(), -1);
        if (row < 0) {
            util::report(error,
                         util::FileError(Code::UnknownKey,
                                         ProfileTr::tr("unknown parameter \"%1\"").arg(it.key()))
                             .withField(it.key()));
            return std::nullopt;
        }
        const model::Definition &definition = definitions.at(row);
        // A full register dump carries read-only values (model number, present position); they
        // cannot be applied, so they are skipped rather than held against the file.
        if (definition.access == model::Access::ReadOnly)
            continue;
        util::FileError why;
        raws[row] = rawValue(definition, it.value(), &why);
        if (!raws.at(row)) {
            util::report(
                error,
                util::FileError(why.code(), ProfileTr::tr("%1: %2").arg(it.key(), why.reason()))
                    .withField(it.key()));
            return std::nullopt;
        }
    }
    // Definition order, so callers write in the order the device expects.
    for (int row = 0; row < definitions.size(); ++row) {
        if (raws.at(row))
            profile.values.append({definitions.at(row).key, *raws.at(row)});
    }
    return profile;
}

std::optional<Profile> load(const QString &path, const QString &expectedFamily,
                            const QVector<model::Definition> &definitions, util::FileError *error)
{
    util::FileError why;
    std::optional<Profile> profile;
    if (const auto json = util::readFile(path, util::kMaxJsonFileBytes,
                                         ProfileTr::tr("too large to be a profile"), &why))
        profile = parse(*json, expectedFamily, definitions, &why);
    if (!profile)
        util::report(error, why.inFile(path));
    return profile;
}

QVector<DiffRow> diff(const Profile &profile, const model::ParameterModel &parameters)
{
    QVector<DiffRow> rows;
    for (const ProfileValue &entry : profile.values) {
        const model::Definition *definition = parameters.definition(entry.key);
        // What cannot be written to this device is no change it would see.
        if (!definition || definition->access == model::Access::ReadOnly)
            continue;
        const std::optional<qint64> device = parameters.deviceValue(entry.key);
        if (device && *device == entry.raw)
            continue;
        rows.append({entry.key, definition->label, device, entry.raw});
    }
    return rows;
}

Profile fromModel(const model::ParameterModel &parameters, const QString &family,
                  const QString &modelName, bool preferPending)
{
    Profile profile;
    profile.family = family;
    profile.model = modelName;
    // Whole seconds: that is what the file keeps, so a reloaded profile compares equal.
    const QDateTime now = QDateTime::currentDateTimeUtc();
    profile.saved = now.addMSecs(-now.time().msec());
    for (const model::Definition &definition : parameters.definitions()) {
        std::optional<qint64> raw;
        if (preferPending)
            raw = parameters.pendingValue(definition.key);
        if (!raw)
            raw = parameters.deviceValue(definition.key);
        if (raw)
            profile.values.append({definition.key, *raw});
    }
    return profile;
}

} // namespace profile
