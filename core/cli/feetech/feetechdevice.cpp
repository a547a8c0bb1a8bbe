// servoctl feetech's bus session driver and the servo output every command prints.
#include "feetechdevice.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTimer>

#include <algorithm>

namespace cli {

namespace {

// Long enough for the slowest flow: a factory reset that looks for the servo at every rate, or
// a reboot that waits for the servo to come back.
constexpr double kOperationTimeoutSeconds = 30;
// Addresses 0-8 name the servo: firmware, byte order, model, ID, baud code, response level.
constexpr int kIdentitySize = 9;

QJsonValue familyJson(const ServoInfo &servo)
{
    if (!servo.model.family)
        return QJsonValue(QJsonValue::Null);
    return feetech::familyKey(*servo.model.family);
}

} // namespace

QString baudNumberText(qint32 baud)
{
    return ServoctlTr::tr("%1 bps").arg(baud);
}

QString baudList()
{
    QStringList rates;
    for (const qint32 rate : feetech::baudRates())
        rates.append(QString::number(rate));
    return rates.join(QStringLiteral(", "));
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

QString servoSummary(const ServoInfo &servo)
{
    const QString family = servo.model.family ? feetech::familyName(*servo.model.family)
                                              : ServoctlTr::tr("unknown model, raw bytes only");
    return ServoctlTr::tr("servo %1 at %2: %3 (%4), firmware %5")
        .arg(servo.id)
        .arg(baudNumberText(servo.baud), servo.model.name, family, servo.firmware());
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

FeetechDevice::FeetechDevice(const Arguments &args, const Output &output)
    : m_output(output)
{
    if (!args.has(QStringLiteral("port")))
        throw UsageError {ServoctlTr::tr("feetech commands need --port PATH (see servoctl ports)")};
    m_port = args.value(QStringLiteral("port"));
    m_echo = echoModeOption(args);
    m_trace = args.flag(QStringLiteral("trace"));
}

FeetechDevice::FeetechDevice(const QString &port, const Arguments &args, const Output &output)
    : m_output(output)
    , m_port(port)
    , m_echo(echoModeOption(args))
    , m_trace(args.flag(QStringLiteral("trace")))
{ }

bool FeetechDevice::open(qint32 baud)
{
    m_session = std::make_unique<feetech::Session>();
    QObject::connect(m_session.get(), &feetech::Session::packetLogged,
                     [this](const seriallink::PacketLogEntry &entry) { trace(entry); });
    // The guard watches whatever a command drives; what it says goes to stderr at once.
    QObject::connect(m_session.get(), &feetech::Session::guardEvent,
                     [this](const feetech::GuardEvent &event) {
                         m_output.err << "servoctl: " << event.message << '\n';
                         m_output.err.flush();
                     });
    m_session->open(m_port, baud, m_echo);
    if (m_session->status().state != seriallink::ConnectionState::Connected) {
        m_error = m_session->status().message;
        if (m_error.isEmpty())
            m_error =
                ServoctlTr::tr("%1 could not be opened").arg(QDir::toNativeSeparators(m_port));
        return false;
    }
    return true;
}

std::optional<ServoInfo> FeetechDevice::identify(quint8 id, qint32 baud,
                                                 std::chrono::microseconds *latency)
{
    const auto pinged = operate(feetech::operations::ping(id, baud));
    if (!pinged || !pinged->ok) {
        m_error = ServoctlTr::tr("%1 (at %2; servoctl feetech scan --baud all looks at every rate)")
                      .arg(pinged ? pinged->message : m_error, baudNumberText(baud));
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
        m_error = ServoctlTr::tr("servo %1 answers PING but its identity (addresses 0-8) could not "
                                 "be read: %2")
                      .arg(id)
                      .arg(m_error);
        return std::nullopt;
    }
    return info;
}

std::optional<Memory> FeetechDevice::read(const ServoInfo &servo,
                                          const QVector<feetech::Block> &blocks)
{
    Memory memory;
    const auto result =
        operate(feetech::operations::read(servo, blocks, feetech::ReadSource::Read), &memory);
    if (!result || !result->ok) {
        if (result)
            m_error = result->message;
        return std::nullopt;
    }
    return memory;
}

std::optional<OperationResult> FeetechDevice::operate(const feetech::BusOperation &operation,
                                                      Memory *memory)
{
    if (m_interrupted) {
        m_error = ServoctlTr::tr("interrupted: nothing more was sent");
        return std::nullopt;
    }
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
                                   [memory](quint8, qint32, int address, const QByteArray &bytes,
                                            feetech::ReadSource,
                                            quint8) { memory->insert(address, bytes); });
    }
    // Submitted from inside the loop: a refusal is emitted before submit() returns.
    QTimer::singleShot(0, &loop, [this, operation] { m_session->submit(operation); });
    const feetech::Operation kind = operation.kind;
    runUntilInterrupted(loop, kOperationTimeoutSeconds, [this, &loop, kind] {
        if (m_interrupted) {
            loop.quit();
            return;
        }
        m_interrupted = true;
        m_session->cancel(kind);
    });
    QObject::disconnect(finished);
    QObject::disconnect(reading);
    if (m_interrupted) {
        m_error = result ? ServoctlTr::tr("interrupted: %1").arg(result->message)
                         : ServoctlTr::tr("interrupted again before the operation ended: check the "
                                          "servo's torque and EEPROM lock");
        return std::nullopt;
    }
    if (!result)
        m_error = ServoctlTr::tr("the servo did not finish in time");
    return result;
}

bool FeetechDevice::scan(const feetech::ScanOptions &options,
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
    QTimer::singleShot(0, &loop,
                       [this, options] { m_session->submit(feetech::operations::scan(options)); });
    // Ctrl-C ends the scan cleanly, so what was found so far is still reported.
    runUntilInterrupted(loop, std::nullopt,
                        [this] { m_session->cancel(feetech::Operation::Scan); });
    QObject::disconnect(finding);
    QObject::disconnect(finished);
    return completed;
}

void FeetechDevice::trace(const seriallink::PacketLogEntry &entry)
{
    if (m_trace)
        printTrace(m_output, entry);
}

} // namespace cli
