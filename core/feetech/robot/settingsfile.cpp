// Settings files for programming servos: profile or robot template, values per servo, the diff.
#include "settingsfile.h"

#include "jsonfile.h"
#include "profile.h"
#include "servoparameters.h"

#include <QCoreApplication>
#include <QDir>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace {

struct SettingsFileTr
{
    Q_DECLARE_TR_FUNCTIONS(SettingsFile)
};

} // namespace

namespace feetech {

namespace {

const QString kRobotMarker = QStringLiteral("servobench-robot");
const QString kPositionOffsetKey = QStringLiteral("position_offset");

} // namespace

std::optional<SettingsFile> SettingsFile::load(const QString &path, util::FileError *error)
{
    const QString shown = QDir::toNativeSeparators(path);
    const auto read =
        util::readFile(path, util::kMaxJsonFileBytes,
                       SettingsFileTr::tr("the file is too large for a profile or a robot "
                                          "template"),
                       error);
    if (!read)
        return std::nullopt;
    return fromJson(*read, shown, error);
}

std::optional<SettingsFile> SettingsFile::fromJson(const QByteArray &json, const QString &source,
                                                   util::FileError *error)
{
    SettingsFile settings;
    settings.m_source = source;
    const QJsonObject object = QJsonDocument::fromJson(json).object();
    if (object.value(QStringLiteral("format")).toString() == kRobotMarker) {
        settings.m_robot = robotTemplateFromJson(json, source, error);
        if (!settings.m_robot)
            return std::nullopt;
        return settings;
    }
    // A profile: valid for one family at least, its problem named as the family it claims
    // (STS when it claims none) would see it.
    QHash<QString, util::FileError> errors;
    for (const Family family : kAllFamilies) {
        util::FileError why;
        const QString key = familyKey(family);
        if (profile::parse(json, key, profileDefinitions(RegisterTable::forFamily(family)), &why)) {
            settings.m_profile = json;
            return settings;
        }
        errors.insert(key, why);
    }
    const QString claimed = object.value(QStringLiteral("family")).toString();
    util::FileError why = errors.value(claimed, errors.value(familyKey(Family::Sts)));
    util::report(error, why.inFile(source));
    return std::nullopt;
}

SettingsFile SettingsFile::fromTemplate(const RobotTemplate &robot)
{
    SettingsFile settings;
    settings.m_source = robot.name;
    settings.m_robot = robot;
    return settings;
}

std::optional<QVector<model::WriteItem>> SettingsFile::valuesFor(const ServoInfo &servo,
                                                                 QString *error) const
{
    if (!servo.hasTable()) {
        *error =
            SettingsFileTr::tr("servo %1 is of an unknown model (%2); nothing is written to it")
                .arg(servo.id)
                .arg(servo.model.name);
        return std::nullopt;
    }
    QVector<model::WriteItem> values;
    if (m_robot) {
        const RobotJoint *joint = nullptr;
        for (const RobotJoint &candidate : m_robot->joints) {
            if (candidate.id == servo.id)
                joint = &candidate;
        }
        if (!joint) {
            *error =
                SettingsFileTr::tr("%1 has no joint with ID %2").arg(m_robot->name).arg(servo.id);
            return std::nullopt;
        }
        const auto model = ModelTable::builtIn().findByName(joint->model);
        if (!model || model->major != servo.model.major || model->minor != servo.model.minor) {
            *error = SettingsFileTr::tr("joint %1 of %2 is a %3, but servo %4 is a %5")
                         .arg(joint->name, m_robot->name, joint->model)
                         .arg(servo.id)
                         .arg(servo.model.name);
            return std::nullopt;
        }
        for (auto it = joint->settings.cbegin(); it != joint->settings.cend(); ++it)
            values.append({it.key(), it.value()});
        return values;
    }
    const QString family = familyKey(*servo.model.family);
    util::FileError why;
    const auto loaded = profile::parse(m_profile, family, profileDefinitions(servo.table()), &why);
    if (!loaded) {
        *error = SettingsFileTr::tr("%1 does not fit servo %2: %3")
                     .arg(m_source)
                     .arg(servo.id)
                     .arg(why.describe());
        return std::nullopt;
    }
    for (const profile::ProfileValue &value : loaded->values)
        values.append({value.key, value.raw});
    return values;
}

std::optional<QVector<model::WriteItem>>
SettingsFile::batchValuesFor(const ServoInfo &servo, QStringList *leftOut, QString *error) const
{
    auto values = valuesFor(servo, error);
    if (!values || m_robot)
        return values; // a template's joint holds that servo's own calibration
    const auto isOffset = [](const model::WriteItem &item) {
        return item.key == kPositionOffsetKey;
    };
    if (values->removeIf(isOffset) > 0 && !leftOut->contains(kPositionOffsetKey))
        leftOut->append(kPositionOffsetKey);
    return values;
}

QString torqueRefusal(const ServoInfo &servo, const QVector<model::WriteItem> &changed,
                      std::optional<qint64> torque)
{
    // The phase register changes how the position reads, so the servo would chase its goal.
    static const QStringList moving {kPositionOffsetKey, QStringLiteral("min_angle_limit"),
                                     QStringLiteral("max_angle_limit"),
                                     QStringLiteral("goal_position"), QStringLiteral("phase")};
    const bool moves = std::any_of(changed.cbegin(), changed.cend(),
                                   [](const auto &item) { return moving.contains(item.key); });
    const auto off = servo.hasTable() ? servo.table().torqueValue(TorqueMode::Off) : std::nullopt;
    if (!moves || (torque && off && *torque == *off))
        return {};
    return SettingsFileTr::tr(
        "torque is on: switch it off before changing the position offset, limits or "
        "phase");
}

QVector<model::WriteItem>
changedValues(const QVector<model::WriteItem> &wanted,
              const std::function<std::optional<qint64>(const QString &key)> &current,
              const QMap<QString, quint32> &cleared)
{
    QVector<model::WriteItem> changed;
    for (const model::WriteItem &item : wanted) {
        if (current(item.key) != std::optional<qint64>(item.value))
            changed.append(item);
    }
    for (auto it = cleared.cbegin(); it != cleared.cend(); ++it) {
        const auto held = current(it.key());
        if (held && (quint64(*held) & it.value()))
            changed.append({it.key(), qint64(quint64(*held) & ~quint64(it.value()))});
    }
    return changed;
}

QMap<QString, quint32> SettingsFile::clearedBitsFor(const ServoInfo &servo) const
{
    if (!m_robot)
        return {};
    for (const RobotJoint &joint : m_robot->joints) {
        if (joint.id == servo.id)
            return joint.clearedBits;
    }
    return {};
}

QString leftOutNote(const QVector<ProgramOutcome> &outcomes)
{
    QStringList keys;
    for (const ProgramOutcome &outcome : outcomes) {
        for (const QString &key : outcome.leftOut) {
            if (!keys.contains(key))
                keys.append(key);
        }
    }
    if (keys.isEmpty())
        return {};
    return SettingsFileTr::tr(
               "Not copied from the profile: %1 (each servo's own calibration, not a setting "
               "to copy; use a robot template or Load calibration for it).")
        .arg(keys.join(QStringLiteral(", ")));
}

QString statusKey(ProgramOutcome::Status status)
{
    switch (status) {
    case ProgramOutcome::Status::Ok:
        return QStringLiteral("ok");
    case ProgramOutcome::Status::Unchanged:
        return QStringLiteral("unchanged");
    case ProgramOutcome::Status::Failed:
        break;
    }
    return QStringLiteral("failed");
}

QString statusText(ProgramOutcome::Status status)
{
    switch (status) {
    case ProgramOutcome::Status::Ok:
        return SettingsFileTr::tr("written and verified");
    case ProgramOutcome::Status::Unchanged:
        return SettingsFileTr::tr("unchanged");
    case ProgramOutcome::Status::Failed:
        break;
    }
    return SettingsFileTr::tr("failed");
}

} // namespace feetech
