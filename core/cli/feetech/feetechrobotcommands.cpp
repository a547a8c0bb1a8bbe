// servoctl feetech identify and load --ids: the commands for arms of several servos.
#include "feetechcommand.h"

#include <QCoreApplication>
#include <QDir>
#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

} // namespace

namespace cli {

namespace {

QJsonObject outcomeJson(const feetech::ProgramOutcome &outcome)
{
    return {{QStringLiteral("id"), int(outcome.id)},
            {QStringLiteral("status"), feetech::statusKey(outcome.status)},
            {QStringLiteral("changed"), QJsonArray::fromStringList(outcome.changed)},
            {QStringLiteral("error"),
             outcome.error.isEmpty() ? QJsonValue() : QJsonValue(outcome.error)},
            {QStringLiteral("left_out"), QJsonArray::fromStringList(outcome.leftOut)}};
}

} // namespace

int FeetechCommand::identify(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    auto target = identifyServoToWrite(what);
    if (!target)
        return ExitDeviceFailure;
    if (!m_output.json) {
        m_output.out << Tr::tr("moving servo %1 a little each way, slowly…").arg(target->servo.id)
                     << '\n';
        m_output.out.flush();
    }
    return report(*target, [&target] { target->device->session().identifyJoint(target->servo); });
}

std::optional<QVector<model::WriteItem>>
FeetechCommand::changedOn(FeetechDevice &device, const ServoInfo &servo,
                          const QVector<model::WriteItem> &wanted, QString *error,
                          std::optional<qint64> *torque)
{
    const auto memory = device.read(servo, {});
    if (!memory) {
        *error = device.error();
        return std::nullopt;
    }
    const QHash<QString, qint32> current = valuesByKey(decodeMemory(servo.table(), *memory));
    if (torque && current.contains(QStringLiteral("torque_enable")))
        *torque = current.value(QStringLiteral("torque_enable"));
    return feetech::changedValues(wanted, [&current](const QString &key) -> std::optional<qint64> {
        const auto found = current.constFind(key);
        if (found == current.constEnd())
            return std::nullopt;
        return *found;
    });
}

// One servo of a batch: every failure becomes its entry, never the end of the batch.
feetech::ProgramOutcome FeetechCommand::programOne(FeetechDevice &device, quint8 id,
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
    const auto items = wanted ? changedOn(device, *servo, *wanted, &error, &torque) : std::nullopt;
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
            outcome.error =
                Tr::tr("verification failed: %1").arg(written.described.join(QStringLiteral("; ")));
        else
            outcome.status = feetech::ProgramOutcome::Status::Ok;
    } catch (const UsageError &refused) {
        outcome.error = refused.message;
    }
    return outcome;
}

int FeetechCommand::loadMany(const feetech::SettingsFile &file, const QString &path)
{
    QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
    for (int i = 0; i < ids.size(); ++i) {
        if (ids.indexOf(ids.at(i)) != i)
            throw UsageError {Tr::tr("--ids names servo %1 twice").arg(ids.at(i))};
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
    m_output.out << Tr::tr("%1 to %n servo(s):", nullptr, int(outcomes.size()))
                        .arg(QDir::toNativeSeparators(path))
                 << '\n';
    const QString idHeader = Tr::tr("ID");
    const QString statusHeader = Tr::tr("status");
    m_output.out << idHeader.leftJustified(5) << statusHeader.leftJustified(22)
                 << Tr::tr("changed / error") << '\n';
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
