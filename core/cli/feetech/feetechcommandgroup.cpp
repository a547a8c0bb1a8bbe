// servoctl feetech: what every command group shares (options, the target servo, writing with
// read-back).
#include "feetechcommandgroup.h"

#include "hex.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <limits>

namespace cli {

int FeetechCommandGroup::fail(const QString &message)
{
    m_output.err << "servoctl: " << message << '\n';
    m_output.err.flush();
    return ExitDeviceFailure;
}

// Options `what` accepts besides --port, --baud and --echo.
void FeetechCommandGroup::allowOptions(const QString &what, const QStringList &allowed) const
{
    static const QStringList kGlobal {QStringLiteral("port"), QStringLiteral("baud"),
                                      QStringLiteral("echo")};
    for (const QString &name : m_args.valueNames()) {
        if (!allowed.contains(name) && !kGlobal.contains(name))
            throw UsageError {ServoctlTr::tr("%1 takes no --%2").arg(what, name)};
    }
    for (const QString &flag :
         {QStringLiteral("thorough"), QStringLiteral("csv"), QStringLiteral("dry-run"),
          QStringLiteral("move-test"), QStringLiteral("check"), QStringLiteral("release")}) {
        if (m_args.flag(flag) && !allowed.contains(flag))
            throw UsageError {ServoctlTr::tr("%1 takes no --%2").arg(what, flag)};
    }
}

void FeetechCommandGroup::expectOperands(const QString &what, const QStringList &operands,
                                         int count, const QString &names)
{
    if (operands.size() == count)
        return;
    if (count == 0)
        throw UsageError {ServoctlTr::tr("%1 takes no arguments").arg(what)};
    throw UsageError {ServoctlTr::tr("%1 needs %2").arg(what, names)};
}

// The servo's rate on the bus (--baud, 1000000 when not given).
qint32 FeetechCommandGroup::busBaud() const
{
    if (!m_args.has(QStringLiteral("baud")))
        return kDefaultBaud;
    return parseBaud(QStringLiteral("--baud"), m_args.value(QStringLiteral("baud")));
}

qint32 FeetechCommandGroup::parseBaud(const QString &what, const QString &text)
{
    const auto value = util::parseInteger(text);
    if (!value || *value <= 0 || *value > std::numeric_limits<qint32>::max()
        || !feetech::baudCode(qint32(*value)))
        throw UsageError {ServoctlTr::tr("%1: \"%2\" is not a Feetech baud rate (%3)")
                              .arg(what, text, baudList())};
    return qint32(*value);
}

quint8 FeetechCommandGroup::servoId(const QString &what) const
{
    if (!m_args.has(QStringLiteral("id")))
        throw UsageError {ServoctlTr::tr("%1 needs --id N").arg(what)};
    return quint8(integerOption(m_args, QStringLiteral("id"), 0, feetech::kMaxServoId));
}

void FeetechCommandGroup::checkFolder(const QString &path)
{
    if (!QFileInfo(path).absoluteDir().exists())
        throw UsageError {
            ServoctlTr::tr("the folder of %1 does not exist").arg(QDir::toNativeSeparators(path))};
}

// The servo --id at --baud (usage errors are thrown before the port is opened); nothing, once
// the failure is printed, when the port cannot be opened or the servo does not answer.
std::optional<FeetechCommandGroup::Target> FeetechCommandGroup::identifyServo(const QString &what)
{
    const quint8 id = servoId(what);
    const qint32 baud = busBaud();
    Target target;
    target.device = std::make_unique<FeetechDevice>(m_args, m_output);
    if (!target.device->open(baud)) {
        fail(target.device->error());
        return std::nullopt;
    }
    const auto servo = target.device->identify(id, baud, &target.latency);
    if (!servo) {
        fail(target.device->error());
        return std::nullopt;
    }
    target.servo = *servo;
    noteIfUnlocked(target);
    return target;
}

void FeetechCommandGroup::noteIfUnlocked(Target &target)
{
    // A servo whose EEPROM lock is open (another program such as LeRobot leaves lock = 0 on
    // every servo it configures; a write cut short does too) keeps whatever anything writes
    // into its EEPROM: the user should know, once per servo and command, and how to lock it.
    // A servo that does not answer this read is left to the command.
    const ServoInfo &servo = target.servo;
    if (m_unlockedNoted.contains(servo.id))
        return;
    const feetech::Register *lock = servo.hasTable() ? servo.table().find(u"lock") : nullptr;
    if (!lock)
        return;
    const auto memory = target.device->read(servo, {{lock->address, lock->size}});
    if (!memory)
        return;
    const qint32 value = valuesByKey(decodeMemory(servo.table(), *memory)).value(lock->key, 1);
    if (value != 0)
        return;
    m_unlockedNoted.insert(servo.id);
    m_output.err << "servoctl: "
                 << ServoctlTr::tr(
                        "note: servo %1's EEPROM is unlocked (lock = 0), as some programs "
                        "(LeRobot among them) leave it: a setting written to it now survives "
                        "a power cut. servoctl locks it again after each of its own EEPROM "
                        "writes; to lock it now: servoctl feetech lock --id %1")
                        .arg(servo.id)
                 << '\n';
    m_output.err.flush();
}

std::optional<FeetechCommandGroup::Target>
FeetechCommandGroup::identifyKnownServo(const QString &what, const QString &unknownModel)
{
    auto target = identifyServo(what);
    if (target && !target->servo.hasTable()) {
        fail(unknownModel.arg(target->servo.id).arg(target->servo.model.name));
        return std::nullopt;
    }
    return target;
}

std::optional<FeetechCommandGroup::Target>
FeetechCommandGroup::identifyServoToWrite(const QString &what)
{
    auto target = identifyKnownServo(
        what, ServoctlTr::tr("servo %1 is of an unknown model (%2); nothing is written to it"));
    if (target && sharesItsId(*target->device, target->servo))
        return std::nullopt;
    return target;
}

bool FeetechCommandGroup::sharesItsId(FeetechDevice &device, const ServoInfo &servo)
{
    // Two servos at one ID would both take whatever is written, and garble every read-back.
    const auto shared = device.operate(feetech::operations::checkSharedId(servo));
    if (shared && shared->ok && !shared->servo.sharedId)
        return false;
    fail(shared ? shared->message : device.error());
    return true;
}

// Writes `items` (register units), reads them back and compares: exit 0 only when every
// value reads back as written.
int FeetechCommandGroup::program(Target &target, const QVector<model::WriteItem> &items,
                                 const QJsonObject &extra)
{
    const ServoInfo &servo = target.servo;
    const Programmed written = writeVerified(*target.device, servo, items);
    if (!written.failure.isEmpty())
        return fail(written.failure);
    const bool verified = written.mismatches.isEmpty();
    if (m_output.json) {
        QJsonObject report = extra;
        report.insert(QStringLiteral("servo"), servoJson(servo));
        report.insert(QStringLiteral("verified"), verified);
        report.insert(QStringLiteral("values"), written.values);
        report.insert(QStringLiteral("mismatches"), written.mismatches);
        printJson(m_output.out, report);
    } else if (verified) {
        m_output.out << ServoctlTr::tr("written to servo %1 and verified: %n register(s)", nullptr,
                                       int(items.size()))
                            .arg(servo.id)
                     << '\n';
        m_output.out.flush();
    }
    if (!verified)
        return fail(ServoctlTr::tr("verification failed: %1")
                        .arg(written.described.join(QStringLiteral("; "))));
    return ExitOk;
}

FeetechCommandGroup::Programmed
FeetechCommandGroup::writeVerified(FeetechDevice &device, const ServoInfo &servo,
                                   const QVector<model::WriteItem> &items)
{
    QString error;
    const auto writes = feetech::encodeWrites(servo.table(), items, &error);
    if (!writes)
        throw UsageError {error};
    Programmed written;
    Memory readBack;
    const auto result = device.operate(feetech::operations::write(servo, *writes), &readBack);
    if (!result || !result->ok) {
        written.failure = result ? result->message : device.error();
        return written;
    }
    const QHash<QString, qint32> read = valuesByKey(decodeMemory(servo.table(), readBack));
    for (const model::WriteItem &item : items) {
        const auto found = read.constFind(item.key);
        if (found != read.constEnd())
            written.values.insert(item.key, *found);
        if (found != read.constEnd() && *found == item.value)
            continue;
        written.mismatches.append(
            QJsonObject {{QStringLiteral("key"), item.key},
                         {QStringLiteral("written"), qint64(item.value)},
                         {QStringLiteral("read"),
                          found != read.constEnd() ? QJsonValue(*found) : QJsonValue()}});
        written.described.append(ServoctlTr::tr("%1: wrote %2, the servo holds %3")
                                     .arg(item.key)
                                     .arg(item.value)
                                     .arg(found != read.constEnd() ? QString::number(*found)
                                                                   : ServoctlTr::tr("nothing")));
    }
    return written;
}

// --ids LIST: the joints, each once.
QVector<quint8> FeetechCommandGroup::jointIds(const QString &what) const
{
    if (!m_args.has(QStringLiteral("ids")))
        throw UsageError {ServoctlTr::tr("%1 needs --ids LIST (such as 1-6)").arg(what)};
    const QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
    if (ids.isEmpty())
        throw UsageError {ServoctlTr::tr("--ids names no servo")};
    for (int i = 0; i < ids.size(); ++i) {
        if (ids.indexOf(ids.at(i)) != i)
            throw UsageError {ServoctlTr::tr("--ids names servo %1 twice").arg(ids.at(i))};
    }
    return ids;
}

// The servo's profile values as read now; registers holding a value outside their range
// are left out with a warning, since a profile could not be loaded with them.
std::optional<profile::Profile> FeetechCommandGroup::takeProfile(Target &target, QString *error)
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
                         << ServoctlTr::tr(
                                "%1 = %2 is outside its range (%3 to %4) and is left out "
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

} // namespace cli
