// LeRobot calibration files: reading and checking them, writing them, and LeRobot's folder.
#include "lerobotcalibration.h"

#include "jsonfile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace {

struct LeRobotCalibrationTr
{
    Q_DECLARE_TR_FUNCTIONS(LeRobotCalibration)
};

} // namespace

namespace feetech {

namespace {

constexpr char kIdKey[] = "id";
constexpr char kDriveModeKey[] = "drive_mode";
constexpr char kHomingOffsetKey[] = "homing_offset";
constexpr char kRangeMinKey[] = "range_min";
constexpr char kRangeMaxKey[] = "range_max";

struct Field
{
    const char *key;
    qint32 minimum;
    qint32 maximum;
};

// The fields of a motor, in the order LeRobot writes them, with the values each may hold.
constexpr Field kFields[] = {
    {kIdKey, 0, 253},
    {kDriveModeKey, 0, 1},
    {kHomingOffsetKey, -kLeRobotMaximumOffset, kLeRobotMaximumOffset},
    {kRangeMinKey, 0, kLeRobotMaximumPosition},
    {kRangeMaxKey, 0, kLeRobotLargestLimit},
};

QString environment(const char *name)
{
    return qEnvironmentVariable(name);
}

} // namespace

bool isLeRobotMotorName(const QString &name)
{
    static const QRegularExpression pattern(QStringLiteral("^[A-Za-z][A-Za-z0-9_]{0,63}$"));
    return pattern.match(name).hasMatch();
}

std::optional<QVector<LeRobotMotor>>
leRobotCalibrationFromJson(const QByteArray &json, const QString &source, util::FileError *error)
{
    using Code = util::FileError::Code;
    const auto fail = [&](util::FileError why) -> std::optional<QVector<LeRobotMotor>> {
        util::report(error, why.inFile(source));
        return std::nullopt;
    };
    const auto failOn = [&](Code code, const QString &why, const QString &field = {}) {
        return fail(util::FileError(code, why).withField(field));
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(util::FileError(Code::NotJson, parseError.errorString())
                        .withValue(QString::number(parseError.offset)));
    if (!document.isObject())
        return failOn(Code::NotAnObject,
                      LeRobotCalibrationTr::tr(
                          "not a LeRobot calibration (the document is not a JSON object of "
                          "motors by joint name)"));
    const QJsonObject root = document.object();
    if (root.isEmpty())
        return failOn(Code::MissingField,
                      LeRobotCalibrationTr::tr("the calibration names no motor"));
    QVector<LeRobotMotor> motors;
    QSet<int> ids;
    for (auto it = root.constBegin(); it != root.constEnd(); ++it) {
        const QString name = it.key();
        if (name.trimmed().isEmpty())
            return failOn(Code::BadValue, LeRobotCalibrationTr::tr("a motor has an empty name"),
                          name);
        if (!isLeRobotMotorName(name))
            return failOn(Code::BadValue,
                          LeRobotCalibrationTr::tr(
                              "motor \"%1\": not a motor name (ASCII letters, digits and _, a "
                              "letter first)")
                              .arg(name),
                          name);
        if (!it.value().isObject())
            return failOn(Code::WrongType,
                          LeRobotCalibrationTr::tr(
                              "motor \"%1\": not an object of id, drive_mode, homing_offset, "
                              "range_min and range_max")
                              .arg(name),
                          name);
        const QJsonObject object = it.value().toObject();
        if (const auto unknown = util::firstUnknownKey(
                object, {kIdKey, kDriveModeKey, kHomingOffsetKey, kRangeMinKey, kRangeMaxKey}))
            return failOn(
                Code::UnknownKey,
                LeRobotCalibrationTr::tr("motor \"%1\": unknown field \"%2\"").arg(name, *unknown),
                *unknown);
        qint32 values[std::size(kFields)] = {};
        for (std::size_t i = 0; i < std::size(kFields); ++i) {
            const Field &field = kFields[i];
            const QJsonValue value = object.value(QLatin1String(field.key));
            const QString key = QLatin1String(field.key);
            if (value.isUndefined())
                return failOn(
                    Code::MissingField,
                    LeRobotCalibrationTr::tr("motor \"%1\": \"%2\" is missing").arg(name, key),
                    key);
            if (!util::isWholeNumber(value))
                return failOn(
                    Code::WrongType,
                    LeRobotCalibrationTr::tr("motor \"%1\": \"%2\" must be a whole number")
                        .arg(name, key),
                    key);
            const double number = value.toDouble();
            if (number < field.minimum || number > field.maximum)
                return fail(util::FileError(Code::BadValue,
                                            LeRobotCalibrationTr::tr(
                                                "motor \"%1\": \"%2\" is %3, outside %4 to %5")
                                                .arg(name, key)
                                                .arg(qint64(number))
                                                .arg(field.minimum)
                                                .arg(field.maximum))
                                .withField(key)
                                .withValue(QString::number(qint64(number))));
            values[i] = qint32(number);
        }
        LeRobotMotor motor {name, values[0], values[1], values[2], values[3], values[4]};
        if (motor.rangeMin >= motor.rangeMax)
            return fail(util::FileError(Code::BadValue,
                                        LeRobotCalibrationTr::tr(
                                            "motor \"%1\": \"%2\" (%3) must be below \"%4\" (%5)")
                                            .arg(name, QLatin1String(kRangeMinKey))
                                            .arg(motor.rangeMin)
                                            .arg(QLatin1String(kRangeMaxKey))
                                            .arg(motor.rangeMax))
                            .withField(QLatin1String(kRangeMinKey))
                            .withValue(QString::number(motor.rangeMin)));
        if (ids.contains(motor.id))
            return fail(util::FileError(Code::Duplicate,
                                        LeRobotCalibrationTr::tr(
                                            "motor \"%1\": ID %2 is used by another motor too")
                                            .arg(name)
                                            .arg(motor.id))
                            .withField(QLatin1String(kIdKey))
                            .withValue(QString::number(motor.id)));
        ids.insert(motor.id);
        motors.append(motor);
    }
    std::sort(motors.begin(), motors.end(),
              [](const LeRobotMotor &a, const LeRobotMotor &b) { return a.id < b.id; });
    return motors;
}

QByteArray leRobotCalibrationToJson(const QVector<LeRobotMotor> &motors)
{
    // Written by hand rather than through QJsonObject, which would sort the joints by name:
    // LeRobot keeps them in the arm's order, base first.
    QByteArray text = "{\n";
    for (int i = 0; i < motors.size(); ++i) {
        const LeRobotMotor &motor = motors.at(i);
        const qint32 values[] = {motor.id, motor.driveMode, motor.homingOffset, motor.rangeMin,
                                 motor.rangeMax};
        text += "    "
            + QJsonDocument(QJsonObject {{QStringLiteral("k"), motor.name}})
                  .toJson(QJsonDocument::Compact)
                  .mid(5) // {"k":"name"} -> "name"}
                  .chopped(1)
            + ": {\n";
        for (std::size_t f = 0; f < std::size(kFields); ++f) {
            text += "        \"" + QByteArray(kFields[f].key) + "\": "
                + QByteArray::number(values[f]) + (f + 1 < std::size(kFields) ? ",\n" : "\n");
        }
        text += i + 1 < motors.size() ? "    },\n" : "    }\n";
    }
    text += "}\n";
    return text;
}

std::optional<QVector<LeRobotMotor>> loadLeRobotCalibration(const QString &path,
                                                            util::FileError *error)
{
    const auto data =
        util::readFile(path, util::kMaxJsonFileBytes,
                       LeRobotCalibrationTr::tr("the file is too large for a calibration"), error);
    if (!data)
        return std::nullopt;
    return leRobotCalibrationFromJson(*data, path, error);
}

bool saveLeRobotCalibration(const QVector<LeRobotMotor> &motors, const QString &path,
                            util::FileError *error)
{
    const QByteArray json = leRobotCalibrationToJson(motors);
    // What is saved can be loaded: a value no file may hold (a limit past 4096 that another
    // program wrote to a servo) is said instead.
    util::FileError why;
    if (!leRobotCalibrationFromJson(json, path, &why)) {
        util::report(error, why.inFile(path, util::FileError::Action::CheckingSave));
        return false;
    }
    return util::writeFileAtomically(path, json, error);
}

void keepDriveModes(QVector<LeRobotMotor> &motors, const QString &path)
{
    util::FileError ignored;
    const auto existing =
        QFileInfo::exists(path) ? loadLeRobotCalibration(path, &ignored) : std::nullopt;
    if (!existing)
        return;
    for (LeRobotMotor &motor : motors) {
        for (const LeRobotMotor &before : *existing) {
            if (before.name == motor.name)
                motor.driveMode = before.driveMode;
        }
    }
}

const LeRobotMotor *leRobotMotorWithId(const QVector<LeRobotMotor> &motors, int id)
{
    const auto motor = std::find_if(motors.begin(), motors.end(),
                                    [id](const LeRobotMotor &m) { return m.id == id; });
    return motor == motors.end() ? nullptr : &*motor;
}

QVector<LeRobotMotor> updatedLeRobotCalibration(QVector<LeRobotMotor> file,
                                                const QVector<LeRobotMotor> &calibrated)
{
    for (const LeRobotMotor &motor : calibrated) {
        for (LeRobotMotor &kept : file) {
            if (kept.id != motor.id)
                continue;
            kept.homingOffset = motor.homingOffset;
            kept.rangeMin = motor.rangeMin;
            kept.rangeMax = motor.rangeMax;
        }
    }
    return file;
}

bool updateLeRobotCalibrationFile(const QVector<LeRobotMotor> &calibrated, const QString &path,
                                  util::FileError *error)
{
    const auto file = loadLeRobotCalibration(path, error);
    if (!file)
        return false;
    for (const LeRobotMotor &motor : calibrated) {
        if (!leRobotMotorWithId(*file, motor.id)) {
            util::report(error,
                         util::FileError(util::FileError::Code::MissingField,
                                         LeRobotCalibrationTr::tr(
                                             "no joint has ID %1 (%2): it is not this arm's "
                                             "file")
                                             .arg(motor.id)
                                             .arg(motor.name))
                             .withField(QString::number(motor.id))
                             .inFile(path, util::FileError::Action::CheckingSave));
            return false;
        }
    }
    return saveLeRobotCalibration(updatedLeRobotCalibration(*file, calibrated), path, error);
}

QString leRobotCalibrationFolder()
{
    if (const QString folder = environment("HF_LEROBOT_CALIBRATION"); !folder.isEmpty())
        return QDir::cleanPath(folder);
    if (const QString home = environment("HF_LEROBOT_HOME"); !home.isEmpty())
        return QDir::cleanPath(home + QStringLiteral("/calibration"));
    QString huggingFace = environment("HF_HOME");
    if (huggingFace.isEmpty()) {
        QString cache = environment("XDG_CACHE_HOME");
        if (cache.isEmpty())
            cache = QDir::homePath() + QStringLiteral("/.cache");
        huggingFace = cache + QStringLiteral("/huggingface");
    }
    return QDir::cleanPath(huggingFace + QStringLiteral("/lerobot/calibration"));
}

QStringList leRobotArmFolders(const QString &templateName)
{
    const QString name = templateName.toLower();
    QString arm;
    if (name.contains(QLatin1String("so-101")) || name.contains(QLatin1String("so101")))
        arm = QStringLiteral("so101");
    else if (name.contains(QLatin1String("so-100")) || name.contains(QLatin1String("so100")))
        arm = QStringLiteral("so100");
    else
        return {};
    if (name.contains(QLatin1String("leader")))
        return {QStringLiteral("teleoperators/%1_leader").arg(arm),
                QStringLiteral("teleoperators/so_leader")};
    return {QStringLiteral("robots/%1_follower").arg(arm), QStringLiteral("robots/so_follower")};
}

QString leRobotArmFolder(const QString &templateName)
{
    const QStringList folders = leRobotArmFolders(templateName);
    if (folders.isEmpty())
        return {};
    const QDir root(leRobotCalibrationFolder());
    for (const QString &folder : folders) {
        if (root.exists(folder))
            return root.filePath(folder);
    }
    return root.filePath(folders.first());
}

} // namespace feetech
