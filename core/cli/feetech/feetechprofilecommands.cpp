// servoctl feetech save and load: a servo's settings to and from a JSON profile or a robot
// template, and load --ids for the servos of an arm.
#include "feetechprofilecommands.h"

#include "profile.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace cli {

namespace {

QJsonObject profileJson(const profile::Profile &saved)
{
    QJsonObject parameters;
    for (const profile::ProfileValue &value : saved.values)
        parameters.insert(value.key, qint64(value.raw));
    return parameters;
}

// Refuses, before anything is sent, a file that is neither a robot template nor a valid
// profile for any Feetech family.
feetech::SettingsFile checkSettingsFile(const QString &path)
{
    util::FileError error;
    auto file = feetech::SettingsFile::load(path, &error);
    if (!file)
        throw UsageError {error.describe()};
    return *file;
}

QJsonObject outcomeJson(const feetech::ProgramOutcome &outcome)
{
    return {{QStringLiteral("id"), int(outcome.id)},
            {QStringLiteral("status"), feetech::statusKey(outcome.status)},
            {QStringLiteral("changed"), QJsonArray::fromStringList(outcome.changed)},
            {QStringLiteral("error"),
             outcome.error.isEmpty() ? QJsonValue() : QJsonValue(outcome.error)},
            {QStringLiteral("left_out"), QJsonArray::fromStringList(outcome.leftOut)}};
}

// The values of `wanted` that `servo` does not hold yet (it is read whole), and the bits of
// `cleared` it has set, cleared; nothing and *error when it cannot be read.
std::optional<QVector<model::WriteItem>> changedOn(FeetechDevice &device, const ServoInfo &servo,
                                                   const QVector<model::WriteItem> &wanted,
                                                   const QMap<QString, quint32> &cleared,
                                                   QString *error,
                                                   std::optional<qint64> *torque = nullptr)
{
    const auto memory = device.read(servo, {});
    if (!memory) {
        *error = device.error();
        return std::nullopt;
    }
    const QHash<QString, qint32> current = valuesByKey(decodeMemory(servo.table(), *memory));
    if (torque && current.contains(QStringLiteral("torque_enable")))
        *torque = current.value(QStringLiteral("torque_enable"));
    return feetech::changedValues(
        wanted,
        [&current](const QString &key) -> std::optional<qint64> {
            const auto found = current.constFind(key);
            if (found == current.constEnd())
                return std::nullopt;
            return *found;
        },
        cleared);
}

} // namespace

int FeetechProfileCommands::save(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 1, ServoctlTr::tr("one FILE"));
    const QString path = operands.first();
    checkFolder(path);
    auto target = identifyKnownServo(
        what, ServoctlTr::tr("servo %1 is of an unknown model (%2): no profile can be saved"));
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QString error;
    const auto saved = takeProfile(*target, &error);
    if (!saved)
        return fail(error);
    util::FileError notSaved;
    if (!profile::save(path, *saved, feetech::profileDefinitions(servo.table()), &notSaved))
        return fail(notSaved.describe());
    if (m_output.json)
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("servo"), servoJson(servo)},
                               {QStringLiteral("file"), path},
                               {QStringLiteral("values"), profileJson(*saved)}});
    else
        m_output.out << ServoctlTr::tr("saved servo %1 (%2) to %3")
                            .arg(servo.id)
                            .arg(servo.model.name, QDir::toNativeSeparators(path))
                     << '\n';
    m_output.out.flush();
    return ExitOk;
}

int FeetechProfileCommands::load(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id"), QStringLiteral("ids")});
    expectOperands(what, operands, 1, ServoctlTr::tr("one FILE"));
    if (m_args.has(QStringLiteral("id")) && m_args.has(QStringLiteral("ids")))
        throw UsageError {ServoctlTr::tr("%1 takes --id N or --ids LIST, not both").arg(what)};
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
                                          feetech::profileDefinitions(servo.table()));
        if (loaded && !loaded->model.isEmpty() && loaded->model != servo.model.name) {
            m_output.err << "servoctl: "
                         << ServoctlTr::tr(
                                "note: the profile was saved from a %1, this servo is a %2")
                                .arg(loaded->model, servo.model.name)
                         << '\n';
            m_output.err.flush();
        }
    }
    std::optional<qint64> torque;
    const auto changed =
        changedOn(*target->device, servo, *wanted, file.clearedBitsFor(servo), &error, &torque);
    if (!changed)
        return fail(error);
    const QVector<model::WriteItem> &items = *changed;
    // A new offset, limit or goal under torque would move the horn: refused, as in a batch.
    const QString refused = feetech::torqueRefusal(servo, items, torque);
    if (!refused.isEmpty())
        return fail(ServoctlTr::tr("servo %1: %2").arg(servo.id).arg(refused));
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
            m_output.out << ServoctlTr::tr(
                                "servo %1 already holds every value of %2; nothing written")
                                .arg(servo.id)
                                .arg(QDir::toNativeSeparators(path))
                         << '\n';
            m_output.out.flush();
        }
        return ExitOk;
    }
    return program(*target, items, extra);
}

// One servo of a batch: every failure becomes its entry, never the end of the batch.
feetech::ProgramOutcome FeetechProfileCommands::programOne(FeetechDevice &device, quint8 id,
                                                           const feetech::SettingsFile &file)
{
    feetech::ProgramOutcome outcome;
    outcome.id = id;
    outcome.baud = busBaud();
    const auto servo = device.identify(id, outcome.baud);
    if (!servo) {
        outcome.error = device.error();
        return outcome;
    }
    QString error;
    const auto wanted = file.batchValuesFor(*servo, &outcome.leftOut, &error);
    std::optional<qint64> torque;
    const auto items = wanted
        ? changedOn(device, *servo, *wanted, file.clearedBitsFor(*servo), &error, &torque)
        : std::nullopt;
    if (!items) {
        outcome.error = error;
        return outcome;
    }
    for (const model::WriteItem &item : *items)
        outcome.changed.append(item.key);
    outcome.error = feetech::torqueRefusal(*servo, *items, torque);
    if (!outcome.error.isEmpty())
        return outcome;
    if (items->isEmpty()) {
        outcome.status = feetech::ProgramOutcome::Status::Unchanged;
        return outcome;
    }
    try {
        const Programmed written = writeVerified(device, *servo, *items);
        if (!written.failure.isEmpty())
            outcome.error = written.failure;
        else if (!written.mismatches.isEmpty())
            outcome.error = ServoctlTr::tr("verification failed: %1")
                                .arg(written.described.join(QStringLiteral("; ")));
        else
            outcome.status = feetech::ProgramOutcome::Status::Ok;
    } catch (const UsageError &refused) {
        outcome.error = refused.message;
    }
    return outcome;
}

int FeetechProfileCommands::loadMany(const feetech::SettingsFile &file, const QString &path)
{
    QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
    for (int i = 0; i < ids.size(); ++i) {
        if (ids.indexOf(ids.at(i)) != i)
            throw UsageError {ServoctlTr::tr("--ids names servo %1 twice").arg(ids.at(i))};
    }
    FeetechDevice device(m_args, m_output);
    if (!device.open(busBaud()))
        return fail(device.error());
    QVector<feetech::ProgramOutcome> outcomes;
    for (const quint8 id : std::as_const(ids))
        outcomes.append(programOne(device, id, file));
    const bool anyFailed =
        std::any_of(outcomes.cbegin(), outcomes.cend(), [](const feetech::ProgramOutcome &o) {
            return o.status == feetech::ProgramOutcome::Status::Failed;
        });
    if (m_output.json) {
        QJsonArray entries;
        for (const feetech::ProgramOutcome &outcome : std::as_const(outcomes))
            entries.append(outcomeJson(outcome));
        printJson(m_output.out, entries);
        return anyFailed ? ExitDeviceFailure : ExitOk;
    }
    m_output.out << ServoctlTr::tr("%1 to %n servo(s):", nullptr, int(outcomes.size()))
                        .arg(QDir::toNativeSeparators(path))
                 << '\n';
    const QString idHeader = ServoctlTr::tr("ID");
    const QString statusHeader = ServoctlTr::tr("status");
    m_output.out << idHeader.leftJustified(5) << statusHeader.leftJustified(22)
                 << ServoctlTr::tr("changed / error") << '\n';
    for (const feetech::ProgramOutcome &outcome : std::as_const(outcomes)) {
        const QString detail = outcome.status == feetech::ProgramOutcome::Status::Failed
            ? outcome.error
            : outcome.changed.join(QStringLiteral(", "));
        m_output.out << QString::number(outcome.id).leftJustified(5)
                     << feetech::statusText(outcome.status).leftJustified(22) << detail << '\n';
    }
    const QString leftOut = leftOutNote(outcomes);
    if (!leftOut.isEmpty())
        m_output.out << leftOut << '\n';
    m_output.out.flush();
    return anyFailed ? ExitDeviceFailure : ExitOk;
}

} // namespace cli
