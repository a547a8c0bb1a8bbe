// servoctl feetech save and load: a servo's settings to and from a JSON profile.
#include "feetechcommand.h"

#include "profile.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

} // namespace

namespace cli {

// The servo's profile values as read now; registers holding a value outside their range
// are left out with a warning, since a profile could not be loaded with them.
std::optional<profile::Profile> FeetechCommand::takeProfile(Target &target, QString *error)
{
    const ServoInfo &servo = target.servo;
    const QVector<model::Definition> definitions = feetech::profileDefinitions(servo.table());
    // The whole table: a few block READs rather than one per register.
    const auto memory = target.device->read(servo, {});
    if (!memory) {
        *error = target.device->error();
        return std::nullopt;
    }
    const QHash<QString, qint32> values = valuesByKey(decodeMemory(servo.table(), *memory));
    profile::Profile saved;
    saved.family = feetech::familyKey(*servo.model.family);
    saved.model = servo.model.name;
    // Whole seconds: what the file keeps.
    const QDateTime now = QDateTime::currentDateTimeUtc();
    saved.saved = now.addMSecs(-now.time().msec());
    for (const model::Definition &definition : definitions) {
        const auto value = values.constFind(definition.key);
        if (value == values.constEnd())
            continue;
        if (*value < definition.minimum || *value > definition.maximum) {
            m_output.err << "servoctl: "
                         << Tr::tr("%1 = %2 is outside its range (%3 to %4) and is left out "
                                   "of the profile")
                                .arg(definition.key)
                                .arg(*value)
                                .arg(definition.minimum)
                                .arg(definition.maximum)
                         << '\n';
            m_output.err.flush();
            continue;
        }
        saved.values.append({definition.key, *value});
    }
    return saved;
}

QJsonObject FeetechCommand::profileJson(const profile::Profile &saved) const
{
    QJsonObject parameters;
    for (const profile::ProfileValue &value : saved.values)
        parameters.insert(value.key, qint64(value.raw));
    return parameters;
}

int FeetechCommand::save(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 1, Tr::tr("one FILE"));
    const QString path = operands.first();
    checkFolder(path);
    auto target = identifyKnownServo(
        what, Tr::tr("servo %1 is of an unknown model (%2): no profile can be saved"));
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QString error;
    const auto saved = takeProfile(*target, &error);
    if (!saved)
        return fail(error);
    if (!profile::save(path, *saved, feetech::profileDefinitions(servo.table()), &error))
        return fail(error);
    if (m_output.json)
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("servo"), servoJson(servo)},
                               {QStringLiteral("file"), path},
                               {QStringLiteral("values"), profileJson(*saved)}});
    else
        m_output.out << Tr::tr("saved servo %1 (%2) to %3")
                            .arg(servo.id)
                            .arg(servo.model.name, QDir::toNativeSeparators(path))
                     << '\n';
    m_output.out.flush();
    return ExitOk;
}

// Refuses, before anything is sent, a file that is neither a robot template nor a valid
// profile for any Feetech family.
feetech::SettingsFile FeetechCommand::checkSettingsFile(const QString &path)
{
    QString error;
    auto file = feetech::SettingsFile::load(path, &error);
    if (!file)
        throw UsageError {error};
    return *file;
}

int FeetechCommand::load(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id"), QStringLiteral("ids")});
    expectOperands(what, operands, 1, Tr::tr("one FILE"));
    if (m_args.has(QStringLiteral("id")) && m_args.has(QStringLiteral("ids")))
        throw UsageError {Tr::tr("%1 takes --id N or --ids LIST, not both").arg(what)};
    const QString path = operands.first();
    const feetech::SettingsFile file = checkSettingsFile(path);
    if (m_args.has(QStringLiteral("ids")))
        return loadMany(file, path);
    auto target = identifyServoToWrite(what);
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QString error;
    const auto wanted = file.valuesFor(servo, &error);
    if (!wanted)
        throw UsageError {error};
    if (!file.isTemplate()) {
        const auto loaded = profile::load(path, feetech::familyKey(*servo.model.family),
                                          feetech::profileDefinitions(servo.table()), &error);
        if (loaded && !loaded->model.isEmpty() && loaded->model != servo.model.name) {
            m_output.err << "servoctl: "
                         << Tr::tr("note: the profile was saved from a %1, this servo is a %2")
                                .arg(loaded->model, servo.model.name)
                         << '\n';
            m_output.err.flush();
        }
    }
    std::optional<qint64> torque;
    const auto changed = changedOn(*target->device, servo, *wanted, &error, &torque);
    if (!changed)
        return fail(error);
    const QVector<model::WriteItem> &items = *changed;
    // A new offset, limit or goal under torque would move the horn: refused, as in a batch.
    const QString refused = feetech::torqueRefusal(servo, items, torque);
    if (!refused.isEmpty())
        return fail(Tr::tr("servo %1: %2").arg(servo.id).arg(refused));
    const QJsonObject extra {{QStringLiteral("file"), path},
                             {QStringLiteral("changed"), int(items.size())}};
    if (items.isEmpty()) {
        if (m_output.json) {
            QJsonObject report = extra;
            report.insert(QStringLiteral("servo"), servoJson(servo));
            report.insert(QStringLiteral("verified"), true);
            report.insert(QStringLiteral("values"), QJsonObject());
            report.insert(QStringLiteral("mismatches"), QJsonArray());
            printJson(m_output.out, report);
        } else {
            m_output.out << Tr::tr("servo %1 already holds every value of %2; nothing written")
                                .arg(servo.id)
                                .arg(QDir::toNativeSeparators(path))
                         << '\n';
            m_output.out.flush();
        }
        return ExitOk;
    }
    return program(*target, items, extra);
}

} // namespace cli
