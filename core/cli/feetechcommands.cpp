// servoctl feetech commands: a Feetech bus session driven to completion on the command line's
// event loop, one operation at a time.
#include "cli/feetechcommands.h"

#include "cli/servoctl.h"
#include "feetech/feetechsession.h"
#include "feetech/servoparameters.h"
#include "profile/profile.h"
#include "util/hex.h"

#include <QDateTime>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QTimer>

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>

namespace cli {

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

using feetech::OperationResult;
using feetech::ServoInfo;

constexpr qint32 kDefaultBaud = 1000000;
constexpr double kDefaultMonitorRate = 50.0;
// Long enough for the slowest flow: a factory reset that looks for the servo at every rate, or
// a reboot that waits for the servo to come back.
constexpr int kOperationTimeoutMs = 30000;
// Addresses 0-8 name the servo: firmware, byte order, model, ID, baud code, response level.
constexpr int kIdentitySize = 9;

// Register bytes by the address their READ started at.
using Memory = QMap<int, QByteArray>;

QString baudText(qint32 baud)
{
    return Tr::tr("%1 bps").arg(baud);
}

QString baudList()
{
    QStringList rates;
    for (const qint32 rate : feetech::baudRates())
        rates.append(QString::number(rate));
    return rates.join(QStringLiteral(", "));
}

QJsonValue familyJson(const ServoInfo &servo)
{
    if (!servo.model.family)
        return QJsonValue(QJsonValue::Null);
    return feetech::familyKey(*servo.model.family);
}

QJsonObject servoJson(const ServoInfo &servo)
{
    return {{QStringLiteral("id"), servo.id},
            {QStringLiteral("baud"), servo.baud},
            {QStringLiteral("model"), servo.model.name},
            {QStringLiteral("model_number"), servo.modelNumber()},
            {QStringLiteral("family"), familyJson(servo)},
            {QStringLiteral("firmware"), servo.firmware()}};
}

// "servo 1 at 1000000 bps: STS3215 (STS), firmware 3.10"
QString servoSummary(const ServoInfo &servo)
{
    const QString family = servo.model.family ? feetech::familyName(*servo.model.family)
                                              : Tr::tr("unknown model, raw bytes only");
    return Tr::tr("servo %1 at %2: %3 (%4), firmware %5")
        .arg(servo.id)
        .arg(baudText(servo.baud), servo.model.name, family, servo.firmware());
}

QString familyText(const ServoInfo &servo)
{
    return servo.model.family ? feetech::familyName(*servo.model.family) : servo.model.name;
}

QVector<feetech::DecodedRegister> decodeMemory(const feetech::RegisterTable &table,
                                               const Memory &memory)
{
    QVector<feetech::DecodedRegister> decoded;
    for (auto it = memory.cbegin(); it != memory.cend(); ++it)
        decoded += feetech::decodeRegisters(table, it.key(), it.value());
    std::sort(decoded.begin(), decoded.end(),
              [](const feetech::DecodedRegister &a, const feetech::DecodedRegister &b) {
                  return a.reg->address < b.reg->address;
              });
    return decoded;
}

QHash<QString, qint32> valuesByKey(const QVector<feetech::DecodedRegister> &decoded)
{
    QHash<QString, qint32> values;
    for (const feetech::DecodedRegister &item : decoded)
        values.insert(item.reg->key, item.value);
    return values;
}

QJsonObject registerJson(const feetech::DecodedRegister &item)
{
    return {{QStringLiteral("key"), item.reg->key},
            {QStringLiteral("address"), item.reg->address},
            {QStringLiteral("size"), item.reg->size},
            {QStringLiteral("value"), item.value},
            {QStringLiteral("raw"), int(item.raw)}};
}

// The value in register units, right-aligned, and what it means where that says more ("8 V",
// "Position").
QString valueText(const feetech::Register &reg, qint32 value)
{
    const QString number = QString::number(value);
    const QString shown = feetech::displayValue(reg, value);
    const QString column = number.rightJustified(6);
    return shown == number ? column : column + QStringLiteral("  ") + shown;
}

void printJson(QTextStream &out, const QJsonValue &value)
{
    const QJsonDocument document =
        value.isArray() ? QJsonDocument(value.toArray()) : QJsonDocument(value.toObject());
    out << document.toJson(QJsonDocument::Indented);
    out.flush();
}

// One Feetech session on the port the arguments name, run to the end of each operation.
class FeetechDevice
{
public:
    FeetechDevice(const Arguments &args, const Output &output)
        : m_output(output)
    {
        if (!args.has(QStringLiteral("port")))
            throw UsageError {Tr::tr("feetech commands need --port PATH (see servoctl ports)")};
        m_port = args.value(QStringLiteral("port"));
        m_echo = echoModeOption(args);
        m_trace = args.flag(QStringLiteral("trace"));
    }

    feetech::Session &session() { return *m_session; }
    const QString &error() const { return m_error; }

    bool open(qint32 baud)
    {
        m_session = std::make_unique<feetech::Session>();
        QObject::connect(m_session.get(), &feetech::Session::packetLogged,
                         [this](const seriallink::PacketLogEntry &entry) { trace(entry); });
        m_session->open(m_port, baud, m_echo);
        if (m_session->status().state != seriallink::ConnectionState::Connected) {
            m_error = m_session->status().message;
            if (m_error.isEmpty())
                m_error = Tr::tr("%1 could not be opened").arg(QDir::toNativeSeparators(m_port));
            return false;
        }
        return true;
    }

    // PING, then READ of addresses 0-8: who answers at `id`, or nothing (and error()).
    std::optional<ServoInfo> identify(quint8 id, qint32 baud,
                                      std::chrono::microseconds *latency = nullptr)
    {
        const auto pinged = operate([this, id, baud] { m_session->ping(id, baud); });
        if (!pinged || !pinged->ok) {
            m_error = Tr::tr("%1 (at %2; servoctl feetech scan --baud all looks at every rate)")
                          .arg(pinged ? pinged->message : m_error, baudText(baud));
            return std::nullopt;
        }
        if (latency)
            *latency = pinged->latency;
        ServoInfo unknown;
        unknown.id = id;
        unknown.baud = baud;
        const auto memory = read(unknown, {{0, kIdentitySize}});
        const auto info =
            memory ? feetech::servoInfoFromIdentity(id, baud, memory->value(0)) : std::nullopt;
        if (!info) {
            m_error = Tr::tr("servo %1 answers PING but its identity (addresses 0-8) could not "
                             "be read: %2")
                          .arg(id)
                          .arg(m_error);
            return std::nullopt;
        }
        return info;
    }

    // The blocks (all of the servo's table when empty), or nothing (and error()).
    std::optional<Memory> read(const ServoInfo &servo, const QVector<feetech::Block> &blocks)
    {
        Memory memory;
        const auto result = operate(
            [this, servo, blocks] { m_session->read(servo, blocks, feetech::ReadSource::Read); },
            &memory);
        if (!result || !result->ok) {
            if (result)
                m_error = result->message;
            return std::nullopt;
        }
        return memory;
    }

    // Runs one session operation to its operationFinished; `readBack` gathers what it read.
    // Nothing (and error()) when it did not finish in time.
    std::optional<OperationResult> operate(const std::function<void()> &start,
                                           Memory *memory = nullptr)
    {
        QEventLoop loop;
        std::optional<OperationResult> result;
        const QMetaObject::Connection finished =
            QObject::connect(m_session.get(), &feetech::Session::operationFinished, &loop,
                             [&](const OperationResult &outcome) {
                                 result = outcome;
                                 loop.quit();
                             });
        QMetaObject::Connection reading;
        if (memory) {
            reading = QObject::connect(m_session.get(), &feetech::Session::memoryRead, &loop,
                                       [memory](quint8, qint32, int address,
                                                const QByteArray &bytes, feetech::ReadSource,
                                                quint8) { memory->insert(address, bytes); });
        }
        // Started from inside the loop: a refusal is emitted before start() returns.
        QTimer::singleShot(0, &loop, start);
        QTimer::singleShot(kOperationTimeoutMs, &loop, &QEventLoop::quit);
        loop.exec();
        QObject::disconnect(finished);
        QObject::disconnect(reading);
        if (!result)
            m_error = Tr::tr("the servo did not finish in time");
        return result;
    }

    // Runs a scan to its end (or to Ctrl-C); false (and error()) when it did not complete.
    bool scan(const feetech::ScanOptions &options,
              const std::function<void(const ServoInfo &)> &found)
    {
        QEventLoop loop;
        bool completed = false;
        const QMetaObject::Connection finding =
            QObject::connect(m_session.get(), &feetech::Session::servoFound, &loop, found);
        const QMetaObject::Connection finished =
            QObject::connect(m_session.get(), &feetech::Session::scanFinished, &loop,
                             [&](bool complete, const QString &message) {
                                 completed = complete;
                                 m_error = message;
                                 loop.quit();
                             });
        QTimer::singleShot(0, &loop, [this, options] { m_session->scan(options); });
        // Ctrl-C ends the scan cleanly, so what was found so far is still reported.
        runUntilInterrupted(loop, std::nullopt, [this] { m_session->cancelScan(); });
        QObject::disconnect(finding);
        QObject::disconnect(finished);
        return completed;
    }

private:
    void trace(const seriallink::PacketLogEntry &entry)
    {
        if (m_trace)
            printTrace(m_output, entry);
    }

    const Output &m_output;
    QString m_port;
    seriallink::EchoMode m_echo = seriallink::EchoMode::Auto;
    bool m_trace = false;
    std::unique_ptr<feetech::Session> m_session;
    QString m_error;
};

struct Assignment
{
    QString key;
    QString value;
};

class FeetechCommand
{
public:
    FeetechCommand(const Arguments &args, const Output &output)
        : m_args(args)
        , m_output(output)
    { }

    int run(const QStringList &rest)
    {
        if (rest.isEmpty())
            throw UsageError {Tr::tr("feetech needs a command (try servoctl --help)")};
        const QString command = rest.first();
        const QStringList operands = rest.mid(1);
        using Handler = int (FeetechCommand::*)(const QString &, const QStringList &);
        static const QVector<std::pair<const char *, Handler>> kCommands {
            {"scan", &FeetechCommand::scan},
            {"ping", &FeetechCommand::ping},
            {"read", &FeetechCommand::read},
            {"get", &FeetechCommand::get},
            {"set", &FeetechCommand::set},
            {"save", &FeetechCommand::save},
            {"load", &FeetechCommand::load},
            {"set-id", &FeetechCommand::setId},
            {"set-baud", &FeetechCommand::setBaud},
            {"calibrate-middle", &FeetechCommand::calibrateMiddle},
            {"factory-reset", &FeetechCommand::factoryReset},
            {"reboot", &FeetechCommand::reboot},
            {"monitor", &FeetechCommand::monitor},
        };
        for (const auto &[name, handler] : kCommands) {
            if (command == QLatin1String(name))
                return (this->*handler)(QStringLiteral("feetech ") + command, operands);
        }
        QStringList names;
        for (const auto &entry : kCommands)
            names.append(QLatin1String(entry.first));
        throw UsageError {Tr::tr("unknown feetech command \"%1\": use %2")
                              .arg(command, names.join(QStringLiteral(", ")))};
    }

private:
    int fail(const QString &message)
    {
        m_output.err << "servoctl: " << message << '\n';
        m_output.err.flush();
        return ExitDeviceFailure;
    }

    // Options `what` accepts besides --port, --baud and --echo.
    void allowOptions(const QString &what, const QStringList &allowed) const
    {
        static const QStringList kGlobal {QStringLiteral("port"), QStringLiteral("baud"),
                                          QStringLiteral("echo")};
        for (const QString &name : m_args.valueNames()) {
            if (!allowed.contains(name) && !kGlobal.contains(name))
                throw UsageError {Tr::tr("%1 takes no --%2").arg(what, name)};
        }
        for (const QString &flag : {QStringLiteral("thorough"), QStringLiteral("csv")}) {
            if (m_args.flag(flag) && !allowed.contains(flag))
                throw UsageError {Tr::tr("%1 takes no --%2").arg(what, flag)};
        }
    }

    static void expectOperands(const QString &what, const QStringList &operands, int count,
                               const QString &names)
    {
        if (operands.size() == count)
            return;
        if (count == 0)
            throw UsageError {Tr::tr("%1 takes no arguments").arg(what)};
        throw UsageError {Tr::tr("%1 needs %2").arg(what, names)};
    }

    // The servo's rate on the bus (--baud, 1000000 when not given).
    qint32 busBaud() const
    {
        if (!m_args.has(QStringLiteral("baud")))
            return kDefaultBaud;
        return parseBaud(QStringLiteral("--baud"), m_args.value(QStringLiteral("baud")));
    }

    static qint32 parseBaud(const QString &what, const QString &text)
    {
        const auto value = util::parseInteger(text);
        if (!value || *value <= 0 || *value > std::numeric_limits<qint32>::max()
            || !feetech::baudCode(qint32(*value)))
            throw UsageError {
                Tr::tr("%1: \"%2\" is not a Feetech baud rate (%3)").arg(what, text, baudList())};
        return qint32(*value);
    }

    quint8 servoId(const QString &what) const
    {
        if (!m_args.has(QStringLiteral("id")))
            throw UsageError {Tr::tr("%1 needs --id N").arg(what)};
        return quint8(integerOption(m_args, QStringLiteral("id"), 0, feetech::kMaxServoId));
    }

    static void checkFolder(const QString &path)
    {
        if (!QFileInfo(path).absoluteDir().exists())
            throw UsageError {
                Tr::tr("the folder of %1 does not exist").arg(QDir::toNativeSeparators(path))};
    }

    // A device on --port with the servo at --id identified; nothing and a message when it does
    // not answer.
    struct Target
    {
        std::unique_ptr<FeetechDevice> device;
        ServoInfo servo;
        std::chrono::microseconds latency {0};
    };
    // The servo --id at --baud (usage errors are thrown before the port is opened).
    std::optional<Target> identifyServo(const QString &what, QString *error)
    {
        const quint8 id = servoId(what);
        const qint32 baud = busBaud();
        Target target;
        target.device = std::make_unique<FeetechDevice>(m_args, m_output);
        if (!target.device->open(baud)) {
            *error = target.device->error();
            return std::nullopt;
        }
        const auto servo = target.device->identify(id, baud, &target.latency);
        if (!servo) {
            *error = target.device->error();
            return std::nullopt;
        }
        target.servo = *servo;
        return target;
    }

    // ---- scan and reading

    int scan(const QString &what, const QStringList &operands)
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
                    throw UsageError {Tr::tr("--ids: a scan covers one range of IDs, such as "
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
                                .arg(Tr::tr("id"), 3)
                                .arg(Tr::tr("baud"), -7)
                                .arg(Tr::tr("model"), -20)
                                .arg(Tr::tr("number"), 6)
                                .arg(Tr::tr("family"), -6)
                                .arg(Tr::tr("firmware"))
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
            m_output.out.flush();
        });
        if (m_output.json) {
            QJsonArray array;
            for (const ServoInfo &servo : std::as_const(found))
                array.append(servoJson(servo));
            printJson(m_output.out, array);
        }
        if (!completed)
            return fail(device.error());
        if (found.isEmpty())
            return fail(Tr::tr("no servo answered (try --baud all, or check power and wiring)"));
        return ExitOk;
    }

    int ping(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 0, {});
        QString error;
        const auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const double latencyMs = double(target->latency.count()) / 1000.0;
        if (m_output.json) {
            printJson(
                m_output.out,
                QJsonObject {{QStringLiteral("servo"), servoJson(target->servo)},
                             {QStringLiteral("latency_us"), qint64(target->latency.count())}});
        } else {
            m_output.out << Tr::tr("%1; answered in %2 ms")
                                .arg(servoSummary(target->servo))
                                .arg(latencyMs, 0, 'f', 2)
                         << '\n';
            m_output.out.flush();
        }
        return ExitOk;
    }

    int read(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 0, {});
        QString error;
        const auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
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
            m_output.out << Tr::tr("no register table is known for this model: the bytes are "
                                   "shown as they are, and nothing can be written")
                         << '\n';
        m_output.out << QStringLiteral("%1  %2  %3  %4")
                            .arg(Tr::tr("addr"), 4)
                            .arg(Tr::tr("key"), -28)
                            .arg(Tr::tr("value"), 6)
                            .arg(Tr::tr("meaning"))
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

    int get(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        if (operands.isEmpty())
            throw UsageError {Tr::tr("%1 needs the register KEYs to read").arg(what)};
        for (const QString &key : operands) {
            if (key.isEmpty() || key.contains(u'='))
                throw UsageError {Tr::tr("%1: \"%2\" is not a register key").arg(what, key)};
        }
        QString error;
        const auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const ServoInfo &servo = target->servo;
        QVector<const feetech::Register *> registers;
        QVector<feetech::Block> blocks;
        for (const QString &key : operands) {
            const feetech::Register *reg = servo.table().find(key);
            if (!reg)
                throw UsageError {Tr::tr("%1 servos have no register \"%2\" (servoctl feetech "
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
            m_output.out << reg->key.leftJustified(width + 2)
                         << valueText(*reg, values.value(reg->key)) << '\n';
        m_output.out.flush();
        return ExitOk;
    }

    // ---- writing

    // Writes `items` (register units), reads them back and compares: exit 0 only when every
    // value reads back as written.
    int program(Target &target, const QVector<model::WriteItem> &items,
                const QJsonObject &extra = {})
    {
        const ServoInfo &servo = target.servo;
        QString error;
        const auto writes = feetech::encodeWrites(servo.table(), items, &error);
        if (!writes)
            throw UsageError {error};
        Memory readBack;
        const auto result = target.device->operate(
            [&target, writes] { target.device->session().write(target.servo, *writes); },
            &readBack);
        if (!result)
            return fail(target.device->error());
        if (!result->ok)
            return fail(result->message);
        const QHash<QString, qint32> read = valuesByKey(decodeMemory(servo.table(), readBack));
        QJsonObject values;
        QJsonArray mismatches;
        QStringList described;
        for (const model::WriteItem &item : items) {
            const auto found = read.constFind(item.key);
            if (found != read.constEnd())
                values.insert(item.key, *found);
            if (found != read.constEnd() && *found == item.value)
                continue;
            mismatches.append(
                QJsonObject {{QStringLiteral("key"), item.key},
                             {QStringLiteral("written"), qint64(item.value)},
                             {QStringLiteral("read"),
                              found != read.constEnd() ? QJsonValue(*found) : QJsonValue()}});
            described.append(
                Tr::tr("%1: wrote %2, the servo holds %3")
                    .arg(item.key)
                    .arg(item.value)
                    .arg(found != read.constEnd() ? QString::number(*found) : Tr::tr("nothing")));
        }
        const bool verified = mismatches.isEmpty();
        if (m_output.json) {
            QJsonObject report = extra;
            report.insert(QStringLiteral("servo"), servoJson(servo));
            report.insert(QStringLiteral("verified"), verified);
            report.insert(QStringLiteral("values"), values);
            report.insert(QStringLiteral("mismatches"), mismatches);
            printJson(m_output.out, report);
        } else if (verified) {
            m_output.out << Tr::tr("written to servo %1 and verified: %n register(s)", nullptr,
                                   int(items.size()))
                                .arg(servo.id)
                         << '\n';
            m_output.out.flush();
        }
        if (!verified)
            return fail(
                Tr::tr("verification failed: %1").arg(described.join(QStringLiteral("; "))));
        return ExitOk;
    }

    int set(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        if (operands.isEmpty())
            throw UsageError {Tr::tr("%1 needs KEY=VALUE arguments").arg(what)};
        QVector<Assignment> assignments;
        for (const QString &operand : operands) {
            const int eq = operand.indexOf(u'=');
            if (eq <= 0)
                throw UsageError {Tr::tr("\"%1\" is not KEY=VALUE").arg(operand)};
            const Assignment assignment {operand.left(eq).trimmed(), operand.mid(eq + 1)};
            if (assignment.key == u"id")
                throw UsageError {Tr::tr("the ID changes how the servo is reached: use "
                                         "servoctl feetech set-id --id N NEW")};
            if (assignment.key == u"baud_rate")
                throw UsageError {Tr::tr("the baud rate changes how the servo is reached: use "
                                         "servoctl feetech set-baud --id N BAUD")};
            for (const Assignment &earlier : std::as_const(assignments)) {
                if (earlier.key == assignment.key)
                    throw UsageError {Tr::tr("%1 is given twice").arg(assignment.key)};
            }
            assignments.append(assignment);
        }
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const ServoInfo &servo = target->servo;
        if (!servo.hasTable())
            return fail(Tr::tr("servo %1 is of an unknown model (%2); nothing is written to it")
                            .arg(servo.id)
                            .arg(servo.model.name));
        // Everything is checked against this servo's table before the first write goes out.
        QVector<model::WriteItem> items;
        for (const Assignment &assignment : std::as_const(assignments)) {
            const feetech::Register *reg = servo.table().find(assignment.key);
            if (!reg)
                throw UsageError {Tr::tr("%1 servos have no register \"%2\" (servoctl feetech "
                                         "read lists them)")
                                      .arg(familyText(servo), assignment.key)};
            if (!reg->writable())
                throw UsageError {Tr::tr("%1 is read-only").arg(reg->key)};
            const auto value = feetech::parseValue(*reg, assignment.value, &error);
            if (!value)
                throw UsageError {error};
            items.append({reg->key, *value});
        }
        return program(*target, items);
    }

    // ---- profiles

    // The servo's profile values as read now; registers holding a value outside their range
    // are left out with a warning, since a profile could not be loaded with them.
    std::optional<profile::Profile> takeProfile(Target &target, QString *error)
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

    QJsonObject profileJson(const profile::Profile &saved) const
    {
        QJsonObject parameters;
        for (const profile::ProfileValue &value : saved.values)
            parameters.insert(value.key, qint64(value.raw));
        return parameters;
    }

    int save(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 1, Tr::tr("one FILE"));
        const QString path = operands.first();
        checkFolder(path);
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const ServoInfo &servo = target->servo;
        if (!servo.hasTable())
            return fail(Tr::tr("servo %1 is of an unknown model (%2): no profile can be saved")
                            .arg(servo.id)
                            .arg(servo.model.name));
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
    static void checkProfileFile(const QString &path)
    {
        QHash<QString, QString> errors;
        for (const feetech::Family family : feetech::kAllFamilies) {
            QString error;
            const QString key = feetech::familyKey(family);
            if (profile::load(
                    path, key,
                    feetech::profileDefinitions(feetech::RegisterTable::forFamily(family)), &error))
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

    int load(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 1, Tr::tr("one FILE"));
        const QString path = operands.first();
        checkProfileFile(path);
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const ServoInfo &servo = target->servo;
        if (!servo.hasTable())
            return fail(Tr::tr("servo %1 is of an unknown model (%2); nothing is written to it")
                            .arg(servo.id)
                            .arg(servo.model.name));
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

    // ---- guided flows

    // Runs one flow and reports it: its message, the servo as it is reached afterwards.
    int report(Target &target, const std::function<void()> &start,
               const std::function<void(QJsonObject &, const Memory &)> &more = {})
    {
        Memory readBack;
        const auto result = target.device->operate(start, &readBack);
        if (!result)
            return fail(target.device->error());
        if (!result->ok)
            return fail(result->message);
        if (m_output.json) {
            QJsonObject object {{QStringLiteral("ok"), true},
                                {QStringLiteral("message"), result->message},
                                {QStringLiteral("servo"), servoJson(result->servo)}};
            if (more)
                more(object, readBack);
            printJson(m_output.out, object);
        } else {
            m_output.out << result->message << '\n';
            if (more) {
                QJsonObject object;
                more(object, readBack);
                for (auto it = object.constBegin(); it != object.constEnd(); ++it)
                    m_output.out << it.key() << ": " << it.value().toVariant().toString() << '\n';
            }
            m_output.out.flush();
        }
        return ExitOk;
    }

    // Nothing to do: the servo already is as asked.
    int alreadyDone(const ServoInfo &servo, const QString &message)
    {
        if (m_output.json)
            printJson(m_output.out,
                      QJsonObject {{QStringLiteral("ok"), true},
                                   {QStringLiteral("message"), message},
                                   {QStringLiteral("servo"), servoJson(servo)}});
        else
            m_output.out << message << '\n';
        m_output.out.flush();
        return ExitOk;
    }

    int setId(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 1, Tr::tr("the NEW ID"));
        const auto newId = util::parseInteger(operands.first());
        if (!newId || *newId < 0 || *newId > feetech::kMaxServoId)
            throw UsageError {Tr::tr("%1: \"%2\" is not an ID (0 to %3)")
                                  .arg(what, operands.first())
                                  .arg(feetech::kMaxServoId)};
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        if (*newId == target->servo.id)
            return alreadyDone(
                target->servo,
                Tr::tr("servo %1 already has ID %1; nothing written").arg(target->servo.id));
        // No list of IDs in use: the session's PING of the new ID refuses an occupied one.
        return report(*target, [&target, newId] {
            target->device->session().changeId(target->servo, int(*newId), {});
        });
    }

    int setBaud(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 1, Tr::tr("the new BAUD rate in bits per second"));
        const qint32 newBaud = parseBaud(what, operands.first());
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const ServoInfo &servo = target->servo;
        if (newBaud == servo.baud)
            return alreadyDone(servo,
                               Tr::tr("servo %1 already runs at %2; nothing written")
                                   .arg(servo.id)
                                   .arg(baudText(servo.baud)));
        if (const feetech::Register *reg = servo.table().find(u"baud_rate")) {
            if (servo.hasTable() && *feetech::baudCode(newBaud) > reg->maximum)
                throw UsageError {Tr::tr("%1 servos do not support %2")
                                      .arg(familyText(servo), baudText(newBaud))};
        }
        return report(*target, [&target, newBaud] {
            target->device->session().changeBaud(target->servo, newBaud);
        });
    }

    int calibrateMiddle(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 0, {});
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const feetech::RegisterTable &table = target->servo.table();
        return report(
            *target, [&target] { target->device->session().calibrateMiddle(target->servo); },
            [&table](QJsonObject &object, const Memory &readBack) {
                const QHash<QString, qint32> values = valuesByKey(decodeMemory(table, readBack));
                if (values.contains(QStringLiteral("position_offset")))
                    object.insert(QStringLiteral("position_offset"),
                                  values.value(QStringLiteral("position_offset")));
            });
    }

    int factoryReset(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id"), QStringLiteral("backup")});
        expectOperands(what, operands, 0, {});
        const quint8 id = servoId(what);
        QString backup = m_args.value(QStringLiteral("backup"));
        if (m_args.has(QStringLiteral("backup"))) {
            if (backup.isEmpty())
                throw UsageError {Tr::tr("--backup needs a FILE")};
            checkFolder(backup);
        } else {
            backup = QDir::current().filePath(
                QStringLiteral("servo-%1-backup-%2.json")
                    .arg(id)
                    .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"))));
        }
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        const ServoInfo &servo = target->servo;
        if (!servo.hasTable())
            return fail(Tr::tr("servo %1 is of an unknown model (%2): no backup can be saved, so "
                               "it is not reset")
                            .arg(servo.id)
                            .arg(servo.model.name));
        // The backup first: without it on disk, nothing is reset.
        const auto saved = takeProfile(*target, &error);
        if (!saved
            || !profile::save(backup, *saved, feetech::profileDefinitions(servo.table()), &error))
            return fail(
                Tr::tr("the backup could not be saved, so the servo was not reset: %1").arg(error));
        if (!m_output.json) {
            m_output.out << Tr::tr("backup of servo %1 saved to %2")
                                .arg(servo.id)
                                .arg(QDir::toNativeSeparators(backup))
                         << '\n';
            m_output.out.flush();
        }
        return report(
            *target, [&target] { target->device->session().factoryReset(target->servo); },
            [this, backup](QJsonObject &object, const Memory &) {
                if (m_output.json)
                    object.insert(QStringLiteral("backup"), backup);
            });
    }

    int reboot(const QString &what, const QStringList &operands)
    {
        allowOptions(what, {QStringLiteral("id")});
        expectOperands(what, operands, 0, {});
        QString error;
        auto target = identifyServo(what, &error);
        if (!target)
            return fail(error);
        return report(*target, [&target] { target->device->session().reboot(target->servo); });
    }

    // Streams the feedback of --ids until --duration has passed or Ctrl-C; one line per sample.
    int monitor(const QString &what, const QStringList &operands)
    {
        allowOptions(what,
                     {QStringLiteral("ids"), QStringLiteral("rate"), QStringLiteral("duration"),
                      QStringLiteral("csv")});
        expectOperands(what, operands, 0, {});
        if (!m_args.has(QStringLiteral("ids")))
            throw UsageError {Tr::tr("%1 needs --ids LIST (such as 1,2,5-7)").arg(what)};
        QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
        for (int i = 0; i < ids.size(); ++i) {
            if (ids.indexOf(ids.at(i)) != i)
                throw UsageError {Tr::tr("--ids names servo %1 twice").arg(ids.at(i))};
        }
        const std::optional<double> duration = durationOption(m_args);
        const double rate = monitorRate();
        const bool csv = m_args.flag(QStringLiteral("csv"));
        if (csv && m_output.json)
            throw UsageError {Tr::tr("choose --csv or --json, not both")};
        const qint32 baud = busBaud();

        FeetechDevice device(m_args, m_output);
        if (!device.open(baud))
            return fail(device.error());
        feetech::TelemetryOptions options;
        options.rateHz = rate;
        options.logEveryFrame = m_args.flag(QStringLiteral("trace"));
        for (const quint8 id : std::as_const(ids)) {
            const auto servo = device.identify(id, baud);
            if (!servo)
                return fail(device.error());
            if (!servo->hasTable())
                return fail(Tr::tr("servo %1 is of an unknown model (%2): its feedback cannot "
                                   "be decoded")
                                .arg(id)
                                .arg(servo->modelNumber()));
            options.servos.append(*servo);
        }

        feetech::Session &session = device.session();
        QEventLoop loop;
        const qint64 startUs = feetech::steadyMicroseconds();
        qint64 printed = 0;
        if (csv)
            m_output.out << feetech::telemetryCsvHeader() << '\n';
        QObject::connect(&session, &feetech::Session::telemetry, &loop,
                         [&](const QVector<feetech::FeedbackSample> &samples) {
                             for (const feetech::FeedbackSample &sample : samples)
                                 printSample(sample, startUs, csv, options.servos);
                             printed += samples.size();
                             m_output.out.flush();
                         });
        // A servo that stops answering (or comes back) is said on stderr as it happens.
        QHash<quint8, bool> missing;
        feetech::TelemetryStats last;
        QObject::connect(&session, &feetech::Session::telemetryStats, &loop,
                         [&](const feetech::TelemetryStats &stats) {
                             last = stats;
                             for (const feetech::ServoTelemetry &servo : stats.servos) {
                                 if (missing.value(servo.id) == servo.missing)
                                     continue;
                                 missing.insert(servo.id, servo.missing);
                                 m_output.err
                                     << (servo.missing
                                             ? Tr::tr("servoctl: servo %1 stopped answering")
                                             : Tr::tr("servoctl: servo %1 answers again"))
                                            .arg(servo.id)
                                     << '\n';
                                 m_output.err.flush();
                             }
                         });
        QObject::connect(&session, &feetech::Session::statusChanged, &loop,
                         [&](const seriallink::ConnectionStatus &status) {
                             if (status.state != seriallink::ConnectionState::Connected)
                                 loop.quit(); // unplugged: nothing more will come
                         });
        QTimer::singleShot(0, &loop, [&session, options] { session.startTelemetry(options); });
        runUntilInterrupted(loop, duration);
        const bool linkLost = session.status().state != seriallink::ConnectionState::Connected;
        session.stopTelemetry(); // flushes the last samples through the connection above
        m_output.err << Tr::tr("servoctl: %1 samples in %2 s (%3 per second); %4 missed")
                            .arg(printed)
                            .arg(last.elapsedSeconds, 0, 'f', 2)
                            .arg(last.elapsedSeconds > 0 ? double(printed) / last.elapsedSeconds
                                                         : 0.0,
                                 0, 'f', 1)
                            .arg(last.missed)
                     << '\n';
        m_output.err.flush();
        if (linkLost)
            return fail(session.status().message);
        if (printed == 0)
            return fail(Tr::tr("no servo answered the telemetry requests"));
        return ExitOk;
    }

    // --rate HZ (1 to 1000) or "max"; 50 when not given.
    double monitorRate() const
    {
        if (!m_args.has(QStringLiteral("rate")))
            return kDefaultMonitorRate;
        const QString text = m_args.value(QStringLiteral("rate"));
        if (text == u"max")
            return 0.0;
        bool ok = false;
        const double rate = text.toDouble(&ok);
        if (!ok || rate < 1.0 || rate > 1000.0)
            throw UsageError {
                Tr::tr("--rate must be a number of samples per second from 1 to 1000, or max")};
        return rate;
    }

    void printSample(const feetech::FeedbackSample &sample, qint64 startUs, bool csv,
                     const QVector<ServoInfo> &servos)
    {
        if (csv) {
            m_output.out << feetech::telemetryCsvRow(sample, startUs) << '\n';
            return;
        }
        const double seconds = double(sample.steadyUs - startUs) / 1e6;
        const auto servo = std::find_if(servos.begin(), servos.end(),
                                        [&sample](const auto &s) { return s.id == sample.id; });
        const QString status = servo != servos.end()
            ? feetech::servoStatusText(servo->table(), sample.servoStatus)
            : QString::number(sample.servoStatus);
        if (m_output.json) {
            // One JSON document per line, so the stream can be piped and read as it runs.
            QJsonObject row {{QStringLiteral("time_s"), seconds},
                             {QStringLiteral("id"), sample.id}};
            for (const feetech::Quantity quantity : feetech::kAllQuantities) {
                const auto value = sample.value(quantity);
                row.insert(feetech::quantityKey(quantity),
                           value ? QJsonValue(*value) : QJsonValue());
            }
            row.insert(QStringLiteral("status"), sample.servoStatus);
            row.insert(QStringLiteral("status_bits"), status);
            row.insert(QStringLiteral("moving"), sample.moving);
            m_output.out << QJsonDocument(row).toJson(QJsonDocument::Compact) << '\n';
            return;
        }
        QStringList cells {QString::number(seconds, 'f', 3),
                           QStringLiteral("id=%1").arg(sample.id)};
        for (const feetech::Quantity quantity : feetech::kAllQuantities) {
            const auto value = sample.value(quantity);
            if (value)
                cells.append(QStringLiteral("%1=%2").arg(feetech::quantityKey(quantity),
                                                         QString::number(*value)));
        }
        cells.append(QStringLiteral("moving=%1").arg(sample.moving ? 1 : 0));
        cells.append(QStringLiteral("status=%1").arg(status));
        m_output.out << cells.join(QLatin1Char(' ')) << '\n';
    }

    const Arguments &m_args;
    const Output &m_output;
};

} // namespace

int runFeetechCommand(const Arguments &args, const QStringList &rest, const Output &output)
{
    return FeetechCommand(args, output).run(rest);
}

} // namespace cli
