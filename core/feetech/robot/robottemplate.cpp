// Robot templates: reading and checking them, writing them back, the built-in arms.
#include "robottemplate.h"

#include "jsonfile.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include <cmath>

namespace {

struct RobotTemplateTr
{
    Q_DECLARE_TR_FUNCTIONS(RobotTemplate)
};

} // namespace

namespace feetech {

namespace {

constexpr char kMarker[] = "servobench-robot";
constexpr int kVersion = 1;
constexpr char kTemplateNameKey[] = "name";
constexpr char kTemplateBaudKey[] = "baud";
constexpr char kSettingsKey[] = "settings";
constexpr char kJointsKey[] = "joints";
constexpr char kTemplateIdKey[] = "id";
constexpr char kModelKey[] = "model";
constexpr char kFullTurnKey[] = "full_turn";
constexpr char kClearBitsKey[] = "clear_bits";

// Registers whose writing has a flow of its own: a template never sets them.
constexpr const char16_t *kFlowOnlyKeys[] = {u"id", u"baud_rate", u"lock", u"torque_enable"};

util::JsonFormat robotFormat()
{
    util::JsonFormat format;
    format.marker = kMarker;
    format.version = kVersion;
    format.keys = {kTemplateNameKey, kTemplateBaudKey, kSettingsKey, kClearBitsKey, kJointsKey};
    format.notAnObject =
        RobotTemplateTr::tr("not a ServoBench robot template (the document is not a JSON "
                            "object)");
    format.wrongMarker =
        RobotTemplateTr::tr("not a ServoBench robot template (\"%1\" is not \"%2\")");
    format.newerVersion =
        RobotTemplateTr::tr("the template has format version %1 and was written by a newer "
                            "ServoBench; this version reads format version %2 and older");
    return format;
}

bool isJointName(const QString &name)
{
    if (name.isEmpty() || name.size() > 64 || !name.at(0).isLetter())
        return false;
    return std::all_of(name.begin(), name.end(), [](QChar c) {
        return (c.isLetterOrNumber() && c.unicode() < 128) || c == u'_';
    });
}

using Code = util::FileError::Code;

// Stores the failure in *why; false, for the caller to return.
bool failWith(util::FileError *why, Code code, const QString &sentence, const QString &field)
{
    *why = util::FileError(code, sentence).withField(field);
    return false;
}

// Register values by key, checked against `table`; false and *why naming the first wrong one.
bool readSettings(const QJsonValue &value, const RegisterTable &table,
                  QMap<QString, qint32> &settings, util::FileError *why)
{
    if (value.isUndefined())
        return true;
    if (!value.isObject())
        return failWith(why, Code::WrongType,
                        RobotTemplateTr::tr("\"%1\" must be an object of register values")
                            .arg(QLatin1String(kSettingsKey)),
                        QLatin1String(kSettingsKey));
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it) {
        const Register *reg = table.find(it.key());
        if (!reg || !reg->writable())
            return failWith(
                why, Code::UnknownKey,
                RobotTemplateTr::tr("settings: \"%1\" is no writable register of %2 servos")
                    .arg(it.key(), familyName(table.family())),
                it.key());
        if (std::any_of(std::begin(kFlowOnlyKeys), std::end(kFlowOnlyKeys),
                        [&](const char16_t *key) { return it.key() == QStringView(key); }))
            return failWith(
                why, Code::BadValue,
                RobotTemplateTr::tr("settings: \"%1\" is set by its own flow, not by a template")
                    .arg(it.key()),
                it.key());
        if (!util::isWholeNumber(it.value()))
            return failWith(
                why, Code::WrongType,
                RobotTemplateTr::tr("settings: \"%1\" must be a whole number").arg(it.key()),
                it.key());
        const qint64 number = qint64(it.value().toDouble());
        if (number < reg->minimum || number > reg->maximum) {
            failWith(why, Code::BadValue,
                     RobotTemplateTr::tr("settings: \"%1\" = %2 is out of range (%3 to %4)")
                         .arg(it.key())
                         .arg(number)
                         .arg(reg->minimum)
                         .arg(reg->maximum),
                     it.key());
            why->withValue(QString::number(number));
            return false;
        }
        settings.insert(it.key(), qint32(number));
    }
    return true;
}

// Bits to clear by register key ({"phase": [4]}), checked against `table`; false and *why naming
// the first wrong one.
bool readClearedBits(const QJsonValue &value, const RegisterTable &table,
                     QMap<QString, quint32> &cleared, util::FileError *why)
{
    if (value.isUndefined())
        return true;
    const QString field = QLatin1String(kClearBitsKey);
    if (!value.isObject())
        return failWith(
            why, Code::WrongType,
            RobotTemplateTr::tr("\"%1\" must be an object of bit numbers by register").arg(field),
            field);
    const QJsonObject object = value.toObject();
    for (auto it = object.begin(); it != object.end(); ++it) {
        const Register *reg = table.find(it.key());
        if (!reg || !reg->writable())
            return failWith(why, Code::UnknownKey,
                            RobotTemplateTr::tr("%1: \"%2\" is no writable register of %3 servos")
                                .arg(field, it.key(), familyName(table.family())),
                            it.key());
        if (std::any_of(std::begin(kFlowOnlyKeys), std::end(kFlowOnlyKeys),
                        [&](const char16_t *key) { return it.key() == QStringView(key); }))
            return failWith(
                why, Code::BadValue,
                RobotTemplateTr::tr("%1: \"%2\" is set by its own flow, not by a template")
                    .arg(field, it.key()),
                it.key());
        if (!it.value().isArray() || it.value().toArray().isEmpty())
            return failWith(why, Code::WrongType,
                            RobotTemplateTr::tr("%1: \"%2\" must be a list of bit numbers")
                                .arg(field, it.key()),
                            it.key());
        quint32 mask = 0;
        for (const QJsonValue &bit : it.value().toArray()) {
            if (!util::isWholeNumber(bit) || bit.toInt() < 0 || bit.toInt() >= reg->size * 8) {
                failWith(why, Code::BadValue,
                         RobotTemplateTr::tr("%1: \"%2\" has bits 0 to %3")
                             .arg(field, it.key())
                             .arg(reg->size * 8 - 1),
                         it.key());
                why->withValue(QString::number(bit.toDouble()));
                return false;
            }
            mask |= 1u << bit.toInt();
        }
        cleared[it.key()] |= mask;
    }
    return true;
}

QJsonObject clearedBitsJson(const QMap<QString, quint32> &cleared)
{
    QJsonObject json;
    for (auto it = cleared.begin(); it != cleared.end(); ++it) {
        QJsonArray bits;
        for (int bit = 0; bit < 32; ++bit) {
            if (it.value() & (1u << bit))
                bits.append(bit);
        }
        json.insert(it.key(), bits);
    }
    return json;
}

bool readJoint(const QJsonValue &value, const QJsonObject &root, RobotJoint &joint,
               util::FileError *why)
{
    if (!value.isObject())
        return failWith(why, Code::WrongType,
                        RobotTemplateTr::tr("every joint must be a JSON object"), {});
    const QJsonObject object = value.toObject();
    if (const auto unknown = util::firstUnknownKey(object,
                                                   {kTemplateNameKey, kTemplateIdKey, kModelKey,
                                                    kFullTurnKey, kSettingsKey, kClearBitsKey}))
        return failWith(why, Code::UnknownKey,
                        RobotTemplateTr::tr("unknown entry \"%1\"").arg(*unknown), *unknown);
    joint.name = object.value(QLatin1String(kTemplateNameKey)).toString();
    if (!isJointName(joint.name))
        return failWith(
            why, Code::BadValue,
            RobotTemplateTr::tr(
                "\"%1\" must be a name of letters, digits and _ that starts with a letter")
                .arg(QLatin1String(kTemplateNameKey)),
            QLatin1String(kTemplateNameKey));
    const QJsonValue id = object.value(QLatin1String(kTemplateIdKey));
    if (!util::isWholeNumber(id) || id.toInt() < 0 || id.toInt() > kMaxServoId)
        return failWith(why, Code::BadValue,
                        RobotTemplateTr::tr("\"%1\" must be a servo ID from 0 to %2")
                            .arg(QLatin1String(kTemplateIdKey))
                            .arg(kMaxServoId),
                        QLatin1String(kTemplateIdKey));
    joint.id = id.toInt();
    joint.model = object.value(QLatin1String(kModelKey)).toString();
    const auto model = ModelTable::builtIn().findByName(joint.model);
    if (!model || !model->family)
        return failWith(
            why, Code::BadValue,
            RobotTemplateTr::tr("\"%1\": \"%2\" is no model with a known register table")
                .arg(QLatin1String(kModelKey), joint.model),
            QLatin1String(kModelKey));
    const QJsonValue fullTurn = object.value(QLatin1String(kFullTurnKey));
    if (!fullTurn.isUndefined() && !fullTurn.isBool())
        return failWith(
            why, Code::WrongType,
            RobotTemplateTr::tr("\"%1\" must be true or false").arg(QLatin1String(kFullTurnKey)),
            QLatin1String(kFullTurnKey));
    joint.fullTurn = fullTurn.toBool(false);
    const RegisterTable &table = RegisterTable::forFamily(*model->family);
    return readSettings(root.value(QLatin1String(kSettingsKey)), table, joint.settings, why)
        && readSettings(object.value(QLatin1String(kSettingsKey)), table, joint.settings, why)
        && readClearedBits(root.value(QLatin1String(kClearBitsKey)), table, joint.clearedBits, why)
        && readClearedBits(object.value(QLatin1String(kClearBitsKey)), table, joint.clearedBits,
                           why);
}

} // namespace

const RobotJoint *RobotTemplate::joint(QStringView name) const
{
    const auto found = std::find_if(joints.begin(), joints.end(),
                                    [name](const RobotJoint &j) { return j.name == name; });
    return found == joints.end() ? nullptr : &*found;
}

std::optional<RobotTemplate> robotTemplateFromJson(const QByteArray &json, const QString &source,
                                                   util::FileError *error)
{
    util::FileError why;
    const auto fail = [&](util::FileError what) -> std::optional<RobotTemplate> {
        util::report(error, what.inFile(source));
        return std::nullopt;
    };
    const auto failOn = [&](Code code, const QString &what, const char *field) {
        return fail(util::FileError(code, what).withField(QLatin1String(field)));
    };
    const auto root = util::parseVersionedObject(json, robotFormat(), &why);
    if (!root)
        return fail(why);
    RobotTemplate robot;
    robot.name = root->value(QLatin1String(kTemplateNameKey)).toString().trimmed();
    if (robot.name.isEmpty())
        return failOn(Code::MissingField,
                      RobotTemplateTr::tr("\"%1\" must be a name for the robot")
                          .arg(QLatin1String(kTemplateNameKey)),
                      kTemplateNameKey);
    const QJsonValue baud = root->value(QLatin1String(kTemplateBaudKey));
    if (!baud.isUndefined()) {
        if (!util::isWholeNumber(baud) || !baudCode(qint32(baud.toDouble())))
            return failOn(Code::BadValue,
                          RobotTemplateTr::tr("\"%1\" must be a Feetech baud rate in bps")
                              .arg(QLatin1String(kTemplateBaudKey)),
                          kTemplateBaudKey);
        robot.baud = qint32(baud.toDouble());
    }
    const QJsonArray joints = root->value(QLatin1String(kJointsKey)).toArray();
    if (joints.isEmpty() || joints.size() > kMaxServoId)
        return failOn(Code::MissingField,
                      RobotTemplateTr::tr("\"%1\" must list the robot's joints")
                          .arg(QLatin1String(kJointsKey)),
                      kJointsKey);
    for (int i = 0; i < joints.size(); ++i) {
        RobotJoint joint;
        const QString where = RobotTemplateTr::tr("joint %1").arg(i + 1);
        if (!readJoint(joints.at(i), *root, joint, &why))
            return fail(util::FileError(why.code(),
                                        where
                                            + (joint.name.isEmpty()
                                                   ? QString()
                                                   : QStringLiteral(" (%1)").arg(joint.name))
                                            + QStringLiteral(": ") + why.reason())
                            .withField(why.field())
                            .withValue(why.value()));
        for (const RobotJoint &other : std::as_const(robot.joints)) {
            if (other.name == joint.name)
                return failOn(Code::Duplicate,
                              RobotTemplateTr::tr("joint %1: the name \"%2\" is used twice")
                                  .arg(i + 1)
                                  .arg(joint.name),
                              kTemplateNameKey);
            if (other.id == joint.id)
                return fail(
                    util::FileError(Code::Duplicate,
                                    RobotTemplateTr::tr("joint %1 (%2): ID %3 is already %4's")
                                        .arg(i + 1)
                                        .arg(joint.name)
                                        .arg(joint.id)
                                        .arg(other.name))
                        .withField(QLatin1String(kTemplateIdKey))
                        .withValue(QString::number(joint.id)));
        }
        robot.joints.append(joint);
    }
    return robot;
}

MotorTarget motorTarget(const RobotTemplate &robot, const RobotJoint &joint)
{
    // The joint as the user's language names it: the target's name is for messages.
    return {jointDisplayName(joint.name),
            joint.id,
            robot.baud,
            joint.model,
            joint.settings,
            joint.clearedBits};
}

QVector<JointCheck> jointChecks(const RobotTemplate &robot)
{
    QVector<JointCheck> joints;
    for (const RobotJoint &joint : robot.joints)
        joints.append({joint.id, joint.model, joint.settings, std::nullopt, {}, joint.clearedBits});
    return joints;
}

SettingsExpectations settingsExpectations(const RobotTemplate &robot)
{
    SettingsExpectations expected;
    expected.source = robotDisplayName(robot.name);
    for (const RobotJoint &joint : robot.joints) {
        expected.byId.insert(quint8(joint.id), joint.settings);
        expected.clearedBitsById.insert(quint8(joint.id), joint.clearedBits);
    }
    return expected;
}

QByteArray robotTemplateToJson(const RobotTemplate &robot)
{
    QJsonArray joints;
    for (const RobotJoint &joint : robot.joints) {
        QJsonObject settings;
        for (auto it = joint.settings.begin(); it != joint.settings.end(); ++it)
            settings.insert(it.key(), it.value());
        QJsonObject written {{QLatin1String(kTemplateNameKey), joint.name},
                             {QLatin1String(kTemplateIdKey), joint.id},
                             {QLatin1String(kModelKey), joint.model},
                             {QLatin1String(kFullTurnKey), joint.fullTurn},
                             {QLatin1String(kSettingsKey), settings}};
        if (!joint.clearedBits.isEmpty())
            written.insert(QLatin1String(kClearBitsKey), clearedBitsJson(joint.clearedBits));
        joints.append(written);
    }
    const QJsonObject root {{QLatin1String(util::kFormatKey), QLatin1String(kMarker)},
                            {QLatin1String(util::kVersionKey), kVersion},
                            {QLatin1String(kTemplateNameKey), robot.name},
                            {QLatin1String(kTemplateBaudKey), robot.baud},
                            {QLatin1String(kJointsKey), joints}};
    return QJsonDocument(root).toJson();
}

const QVector<RobotTemplate> &builtInRobotTemplates()
{
    static const QVector<RobotTemplate> templates = [] {
        QVector<RobotTemplate> loaded;
        const QDir folder(QStringLiteral(":/robots"));
        for (const QString &name :
             folder.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
            util::FileError error;
            const QString path = folder.filePath(name);
            auto robot = loadRobotTemplate(path, &error);
            if (!robot)
                qFatal("ServoBench: built-in robot template is invalid: %s",
                       qPrintable(error.describe()));
            loaded.append(std::move(*robot));
        }
        return loaded;
    }();
    return templates;
}

std::optional<RobotTemplate> loadRobotTemplate(const QString &path, util::FileError *error)
{
    const auto bytes =
        util::readFile(path, util::kMaxJsonFileBytes,
                       RobotTemplateTr::tr("the file is too large for a robot template"), error);
    if (!bytes)
        return std::nullopt;
    return robotTemplateFromJson(*bytes, path, error);
}

bool saveRobotTemplate(const RobotTemplate &robot, const QString &path, util::FileError *error)
{
    return util::writeFileAtomically(path, robotTemplateToJson(robot), error);
}

QString userRobotTemplateFolder()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("robots"));
}

QVector<RobotTemplate> availableRobotTemplates(QStringList *problems)
{
    QVector<RobotTemplate> templates = builtInRobotTemplates();
    const QDir folder(userRobotTemplateFolder());
    for (const QString &name :
         folder.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        util::FileError error;
        if (auto robot = loadRobotTemplate(folder.filePath(name), &error))
            templates.append(std::move(*robot));
        else if (problems)
            problems->append(error.describe());
    }
    return templates;
}

int defaultRobotTemplate(const QVector<RobotTemplate> &templates)
{
    for (int i = 0; i < templates.size(); ++i) {
        if (templates.at(i).name == QLatin1String("SO-101 follower arm"))
            return i;
    }
    return templates.isEmpty() ? -1 : 0;
}

const RobotTemplate *defaultRobotTemplateIn(const QVector<RobotTemplate> &templates)
{
    const int chosen = defaultRobotTemplate(templates);
    return chosen >= 0 ? &templates.at(chosen) : nullptr;
}

QString robotDisplayName(const QString &name)
{
    return QCoreApplication::translate("RobotTemplate", name.toUtf8().constData());
}

QString jointDisplayName(const QString &name)
{
    return QCoreApplication::translate("Joint", name.toUtf8().constData());
}

} // namespace feetech
