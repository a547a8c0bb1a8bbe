// servoctl feetech scan, ping, read, get and set: finding servos and their registers.
#include "feetechregistercommands.h"

#include "servoctltr.h"
#include "sharedidcheck.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>

namespace cli {

namespace {

struct Assignment
{
    QString key;
    QString value;
};

// What a scan row warns of: a shared ID, error bits in the servo's answer.
QStringList scanWarnings(const ServoInfo &servo)
{
    QStringList warnings;
    if (servo.sharedId)
        warnings.append(feetech::sharedIdRefusal(servo.id));
    const QStringList errors = feetech::statusBitNames(servo.statusBits);
    if (!errors.isEmpty())
        warnings.append(
            ServoctlTr::tr("servo %1 answers with error bits 0x%2 (%3): servoctl doctor says "
                           "why")
                .arg(servo.id)
                .arg(servo.statusBits, 2, 16, QLatin1Char('0'))
                .arg(errors.join(QStringLiteral(", "))));
    return warnings;
}

} // namespace

int FeetechRegisterCommands::scan(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("ids"), QStringLiteral("thorough")});
    expectOperands(what, operands, 0, {});
    feetech::ScanOptions options;
    if (m_args.value(QStringLiteral("baud")) == QLatin1String("all"))
        options.bauds = feetech::baudRates();
    else
        options.bauds = {busBaud()};
    if (m_args.has(QStringLiteral("ids"))) {
        QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
        std::sort(ids.begin(), ids.end());
        for (int i = 1; i < ids.size(); ++i) {
            if (ids.at(i) != ids.at(i - 1) + 1)
                throw UsageError {ServoctlTr::tr("--ids: a scan covers one range of IDs, such as "
                                                 "0-20")};
        }
        options.firstId = ids.first();
        options.lastId = ids.last();
    }
    options.skipSilentRates = !m_args.flag(QStringLiteral("thorough"));

    FeetechDevice device(m_args, m_output);
    if (!device.open(options.bauds.first()))
        return fail(device.error());
    QVector<ServoInfo> found;
    if (!m_output.json) {
        m_output.out << QStringLiteral("%1  %2  %3  %4  %5  %6")
                            .arg(ServoctlTr::tr("id"), 3)
                            .arg(ServoctlTr::tr("baud"), -7)
                            .arg(ServoctlTr::tr("model"), -20)
                            .arg(ServoctlTr::tr("number"), 6)
                            .arg(ServoctlTr::tr("family"), -6)
                            .arg(ServoctlTr::tr("firmware"))
                     << '\n';
        m_output.out.flush();
    }
    const bool completed = device.scan(options, [&](const ServoInfo &servo) {
        found.append(servo);
        if (m_output.json)
            return;
        // Rows as they are found: a slow scan shows its progress.
        m_output.out << QStringLiteral("%1  %2  %3  %4  %5  %6")
                            .arg(servo.id, 3)
                            .arg(servo.baud, -7)
                            .arg(servo.model.name, -20)
                            .arg(servo.modelNumber(), 6)
                            .arg(servo.model.family ? feetech::familyKey(*servo.model.family)
                                                    : QStringLiteral("-"),
                                 -6)
                            .arg(servo.firmware())
                     << '\n';
        for (const QString &warning : scanWarnings(servo))
            m_output.out << QStringLiteral("     ! ") << warning << '\n';
        m_output.out.flush();
    });
    if (m_output.json) {
        // A servo asked again after a late answer is found after its neighbours: the list
        // comes in the tree's order, fastest rate first, then by ID.
        std::stable_sort(found.begin(), found.end(), [](const ServoInfo &a, const ServoInfo &b) {
            return a.baud != b.baud ? a.baud > b.baud : a.id < b.id;
        });
        QJsonArray array;
        for (const ServoInfo &servo : std::as_const(found)) {
            QJsonObject row = servoJson(servo);
            row.insert(QStringLiteral("shared_id"), servo.sharedId);
            row.insert(QStringLiteral("error_bits"), servo.statusBits);
            row.insert(QStringLiteral("errors"),
                       QJsonArray::fromStringList(feetech::statusBitKeys(servo.statusBits)));
            array.append(row);
        }
        printJson(m_output.out, array);
    }
    if (!completed)
        return fail(device.error());
    if (found.isEmpty())
        return fail(
            ServoctlTr::tr("no servo answered (try --baud all, or check power and wiring)"));
    const auto shared = std::find_if(found.cbegin(), found.cend(),
                                     [](const ServoInfo &servo) { return servo.sharedId; });
    if (shared != found.cend())
        return fail(feetech::sharedIdRefusal(shared->id));
    return ExitOk;
}

int FeetechRegisterCommands::ping(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    const double latencyMs = double(target->latency.count()) / 1000.0;
    if (m_output.json) {
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("servo"), servoJson(target->servo)},
                               {QStringLiteral("latency_us"), qint64(target->latency.count())}});
    } else {
        m_output.out << ServoctlTr::tr("%1; answered in %2 ms")
                            .arg(servoSummary(target->servo))
                            .arg(latencyMs, 0, 'f', 2)
                     << '\n';
        m_output.out.flush();
    }
    return ExitOk;
}

int FeetechRegisterCommands::read(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    expectOperands(what, operands, 0, {});
    QString error;
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    const auto memory = target->device->read(servo, {});
    if (!memory)
        return fail(target->device->error());
    const QVector<feetech::DecodedRegister> decoded = decodeMemory(servo.table(), *memory);
    if (m_output.json) {
        QJsonArray registers;
        for (const feetech::DecodedRegister &item : decoded)
            registers.append(registerJson(item));
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("servo"), servoJson(servo)},
                               {QStringLiteral("registers"), registers}});
        return ExitOk;
    }
    m_output.out << servoSummary(servo) << '\n';
    if (!servo.hasTable())
        m_output.out << ServoctlTr::tr("no register table is known for this model: the bytes are "
                                       "shown as they are, and nothing can be written")
                     << '\n';
    m_output.out << QStringLiteral("%1  %2  %3  %4")
                        .arg(ServoctlTr::tr("addr"), 4)
                        .arg(ServoctlTr::tr("key"), -28)
                        .arg(ServoctlTr::tr("value"), 6)
                        .arg(ServoctlTr::tr("meaning"))
                 << '\n';
    for (const feetech::DecodedRegister &item : decoded) {
        m_output.out << QStringLiteral("%1  %2  %3")
                            .arg(item.reg->address, 4)
                            .arg(item.reg->key, -28)
                            .arg(valueText(*item.reg, item.value))
                     << '\n';
    }
    m_output.out.flush();
    return ExitOk;
}

int FeetechRegisterCommands::get(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    if (operands.isEmpty())
        throw UsageError {ServoctlTr::tr("%1 needs the register KEYs to read").arg(what)};
    for (const QString &key : operands) {
        if (key.isEmpty() || key.contains(u'='))
            throw UsageError {ServoctlTr::tr("%1: \"%2\" is not a register key").arg(what, key)};
    }
    QString error;
    auto target = identifyServo(what);
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QVector<const feetech::Register *> registers;
    QVector<feetech::Block> blocks;
    for (const QString &key : operands) {
        const feetech::Register *reg = servo.table().find(key);
        if (!reg)
            throw UsageError {ServoctlTr::tr("%1 servos have no register \"%2\" (servoctl feetech "
                                             "read lists them)")
                                  .arg(familyText(servo), key)};
        registers.append(reg);
        blocks.append({reg->address, reg->size});
    }
    const auto memory = target->device->read(servo, blocks);
    if (!memory)
        return fail(target->device->error());
    const QHash<QString, qint32> values = valuesByKey(decodeMemory(servo.table(), *memory));
    if (m_output.json) {
        QJsonObject object;
        for (const feetech::Register *reg : std::as_const(registers))
            object.insert(reg->key, values.value(reg->key));
        printJson(m_output.out, object);
        return ExitOk;
    }
    int width = 0;
    for (const feetech::Register *reg : std::as_const(registers))
        width = std::max(width, int(reg->key.size()));
    for (const feetech::Register *reg : std::as_const(registers))
        m_output.out << reg->key.leftJustified(width + 2) << valueText(*reg, values.value(reg->key))
                     << '\n';
    m_output.out.flush();
    return ExitOk;
}

int FeetechRegisterCommands::set(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("id")});
    if (operands.isEmpty())
        throw UsageError {ServoctlTr::tr("%1 needs KEY=VALUE arguments").arg(what)};
    QVector<Assignment> assignments;
    for (const QString &operand : operands) {
        const int eq = operand.indexOf(u'=');
        if (eq <= 0)
            throw UsageError {ServoctlTr::tr("\"%1\" is not KEY=VALUE").arg(operand)};
        const Assignment assignment {operand.left(eq).trimmed(), operand.mid(eq + 1)};
        if (assignment.key == u"id")
            throw UsageError {ServoctlTr::tr("the ID changes how the servo is reached: use "
                                             "servoctl feetech set-id --id N NEW")};
        if (assignment.key == u"baud_rate")
            throw UsageError {ServoctlTr::tr("the baud rate changes how the servo is reached: use "
                                             "servoctl feetech set-baud --id N BAUD")};
        for (const Assignment &earlier : std::as_const(assignments)) {
            if (earlier.key == assignment.key)
                throw UsageError {ServoctlTr::tr("%1 is given twice").arg(assignment.key)};
        }
        assignments.append(assignment);
    }
    auto target = identifyServoToWrite(what);
    if (!target)
        return ExitDeviceFailure;
    const ServoInfo &servo = target->servo;
    QString error;
    // Everything is checked against this servo's table before the first write goes out.
    QVector<model::WriteItem> items;
    for (const Assignment &assignment : std::as_const(assignments)) {
        const feetech::Register *reg = servo.table().find(assignment.key);
        if (!reg)
            throw UsageError {ServoctlTr::tr("%1 servos have no register \"%2\" (servoctl feetech "
                                             "read lists them)")
                                  .arg(familyText(servo), assignment.key)};
        if (!reg->writable())
            throw UsageError {ServoctlTr::tr("%1 is read-only").arg(reg->key)};
        const auto value = feetech::parseValue(*reg, assignment.value, &error);
        if (!value)
            throw UsageError {error};
        items.append({reg->key, *value});
    }
    return program(*target, items);
}

} // namespace cli
