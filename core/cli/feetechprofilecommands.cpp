// servoctl feetech save and load: a servo's settings to and from a JSON profile.
#include "cli/feetechcommand.h"

#include "profile/profile.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace cli {

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

} // namespace

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

// Refuses, before anything is sent, a file that is no valid profile for any Feetech family.
void FeetechCommand::checkProfileFile(const QString &path)
{
    QHash<QString, QString> errors;
    for (const feetech::Family family : feetech::kAllFamilies) {
        QString error;
        const QString key = feetech::familyKey(family);
        if (profile::load(path, key,
                          feetech::profileDefinitions(feetech::RegisterTable::forFamily(family)),
                          &error))
            return;
        errors.insert(key, error);
    }
    // Name the problem as the family the file claims would see it.
    QString named;
    QFile file(path);
    if (file.open(QIODevice::ReadOnly))
        named = QJsonDocument::fromJson(file.read(1024 * 1024))
                    .object()
                    .value(QStringLiteral("family"))
                    .toString();
    throw UsageError {errors.value(named, errors.value(QStringLiteral("sts")))};
}

int FeetechCommand::load(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 1, Tr::tr("one FILE"));
    const QString path = operands.first();
    checkProfileFile(path);
    auto target = identifyServoToWrite(what);
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QString error;
    const auto loaded = profile::load(path, feetech::familyKey(*servo.model.family),
                                      feetech::profileDefinitions(servo.table()), &error);
    if (!loaded)
        throw UsageError {error};
    if (!loaded->model.isEmpty() && loaded->model != servo.model.name) {
        m_output.err << "servoctl: "
                     << Tr::tr("note: the profile was saved from a %1, this servo is a %2")
                            .arg(loaded->model, servo.model.name)
                     << '\n';
        m_output.err.flush();
    }
    const auto memory = target->device->read(servo, {});
    if (!memory)
        return fail(target->device->error());
    const QHash<QString, qint32> current = valuesByKey(decodeMemory(servo.table(), *memory));
    QVector<model::WriteItem> items;
    for (const profile::ProfileValue &value : loaded->values) {
        const auto device = current.constFind(value.key);
        if (device == current.constEnd() || *device != value.raw)
            items.append({value.key, value.raw});
    }
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
