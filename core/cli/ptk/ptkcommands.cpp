// servoctl ptk commands: a PTK session driven to completion on the command line's event loop.
#include "ptkcommands.h"

#include "exitcode.h"
#include "hex.h"
#include "profile.h"
#include "ptksession.h"
#include "servoctltr.h"
#include "unixsignals.h"

#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <csignal>

namespace cli {

namespace {

const QString kFamily = QStringLiteral("ptk");
// Long enough for a full sweep with every retry, or an Apply with its gaps and read-back.
constexpr int kCommandTimeoutMs = 15000;

QString knownKeys()
{
    QStringList known;
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
        known.append(QLatin1String(meta.key));
    return known.join(QStringLiteral(", "));
}

QJsonValue userValue(const ptk::ParameterInfo &meta, quint16 wire)
{
    if (meta.isSwitch)
        return wire != 0;
    return ptk::toUserValue(meta.parameter, wire);
}

QString userText(const ptk::ParameterInfo &meta, quint16 wire)
{
    if (meta.isSwitch)
        return wire != 0 ? QStringLiteral("on") : QStringLiteral("off");
    return QString::number(ptk::toUserValue(meta.parameter, wire));
}

QJsonObject valuesObject(const ptk::ParameterSet &values)
{
    QJsonObject object;
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
        if (const auto wire = values.value(meta.parameter))
            object.insert(QLatin1String(meta.key), userValue(meta, *wire));
    }
    return object;
}

void merge(ptk::ParameterSet &into, const ptk::ParameterSet &from)
{
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
        if (const auto wire = from.value(meta.parameter))
            into.set(meta.parameter, *wire);
    }
}

// One PTK session on the port the arguments name, run to the end of each step.
class PtkDevice
{
public:
    PtkDevice(const Arguments &args, const Output &output)
        : m_output(output)
    {
        if (!args.has(QStringLiteral("port")))
            throw UsageError {ServoctlTr::tr("ptk commands need --port PATH (see servoctl ports)")};
        m_port = args.value(QStringLiteral("port"));
        m_baud = args.has(QStringLiteral("baud"))
            ? qint32(integerOption(args, QStringLiteral("baud"), 1200, 4000000))
            : 115200;
        m_echo = echoModeOption(args);
        m_trace = args.flag(QStringLiteral("trace"));
    }

    ptk::Session &session() { return *m_session; }
    const QString &error() const { return m_error; }

    // Opens the port without background polling (monitor turns it on).
    bool open(bool polling)
    {
        m_session = std::make_unique<ptk::Session>();
        QObject::connect(m_session.get(), &ptk::Session::packetLogged,
                         [this](const seriallink::PacketLogEntry &entry) { trace(entry); });
        m_session->setPolling(polling);
        m_session->open(m_port, m_baud, m_echo);
        if (!m_session->status().message.isEmpty()
            && m_session->status().state == seriallink::ConnectionState::Disconnected) {
            m_error = m_session->status().message;
            return false;
        }
        return true;
    }

    // Opens the port without polling and reads all thirteen values; nothing (and error()) when
    // the port or a query failed.
    std::optional<ptk::ParameterSet> openAndRead()
    {
        if (!open(false))
            return std::nullopt;
        return readAll();
    }

    // All thirteen values, or nothing (and error()) when a query went unanswered.
    std::optional<ptk::ParameterSet> readAll()
    {
        return collect(&ptk::Session::readFinished, std::nullopt, [this] { m_session->readAll(); });
    }

    // Writes the full sequence; returns the values read back (nothing when the link failed).
    std::optional<ptk::ParameterSet> apply(const ptk::ParameterSet &values)
    {
        return collect(&ptk::Session::applyFinished, ptk::ReadSource::ReadBack,
                       [this, values] { m_session->apply(values); });
    }

private:
    // Runs `work` to `finished`, gathering the values read (only those from `source` if given).
    template<typename Signal, typename Work>
    std::optional<ptk::ParameterSet> collect(Signal finished, std::optional<ptk::ReadSource> source,
                                             Work work)
    {
        ptk::ParameterSet values;
        const QMetaObject::Connection collecting =
            QObject::connect(m_session.get(), &ptk::Session::valuesRead,
                             [&](const ptk::ParameterSet &read, ptk::ReadSource from) {
                                 if (!source || from == *source)
                                     merge(values, read);
                             });
        bool ok = false;
        run(finished, work, [&](bool success, const QString &message) {
            ok = success;
            m_error = message;
        });
        QObject::disconnect(collecting);
        if (!ok)
            return std::nullopt;
        return values;
    }

    // Starts `work` and runs the event loop until `finished` fires or the guard time passes.
    template<typename Signal, typename Work, typename Done>
    void run(Signal finished, Work work, Done done)
    {
        QEventLoop loop;
        bool answered = false;
        const QMetaObject::Connection connection =
            QObject::connect(m_session.get(), finished, &loop, [&](bool ok, const QString &text) {
                answered = true;
                done(ok, text);
                loop.quit();
            });
        QTimer::singleShot(0, &loop, work);
        QTimer::singleShot(kCommandTimeoutMs, &loop, &QEventLoop::quit);
        loop.exec();
        QObject::disconnect(connection);
        if (!answered)
            done(false, ServoctlTr::tr("the servo did not finish in time"));
    }

    void trace(const seriallink::PacketLogEntry &entry)
    {
        if (m_trace)
            printTrace(m_output, entry);
    }

    const Output &m_output;
    QString m_port;
    qint32 m_baud = 115200;
    seriallink::EchoMode m_echo = seriallink::EchoMode::Auto;
    bool m_trace = false;
    std::unique_ptr<ptk::Session> m_session;
    QString m_error;
};

class PtkCommand
{
public:
    PtkCommand(const Arguments &args, const Output &output)
        : m_args(args)
        , m_output(output)
    { }

    int run(const QStringList &rest)
    {
        if (rest.isEmpty())
            throw UsageError {
                ServoctlTr::tr("ptk needs a command: read, write, save, load or monitor")};
        const QString command = rest.first();
        const QStringList operands = rest.mid(1);
        if (m_args.has(QStringLiteral("rate")))
            throw UsageError {
                ServoctlTr::tr("ptk takes no --rate: the servo is polled every 50 ms")};
        // A Feetech option (--id, --ids, --settings...) means the wrong servo family was named:
        // nothing is sent on a guess.
        static const QStringList kPtkOptions {QStringLiteral("port"), QStringLiteral("baud"),
                                              QStringLiteral("echo"), QStringLiteral("duration")};
        for (const QString &name : m_args.valueNames()) {
            if (!kPtkOptions.contains(name))
                throw UsageError {ServoctlTr::tr("ptk takes no --%1").arg(name)};
        }
        if (command != QLatin1String("monitor")) {
            if (m_args.has(QStringLiteral("duration")))
                throw UsageError {ServoctlTr::tr("only ptk monitor takes --duration")};
        }
        if (command == QLatin1String("read"))
            return read(operands);
        if (command == QLatin1String("write"))
            return write(operands);
        if (command == QLatin1String("save"))
            return save(operands);
        if (command == QLatin1String("load"))
            return load(operands);
        if (command == QLatin1String("monitor"))
            return monitor(operands);
        throw UsageError {
            ServoctlTr::tr("unknown ptk command \"%1\": use read, write, save, load or "
                           "monitor")
                .arg(command)};
    }

private:
    int fail(const QString &message)
    {
        m_output.err << "servoctl: " << message << '\n';
        m_output.err.flush();
        return ExitDeviceFailure;
    }

    void printValues(const ptk::ParameterSet &values)
    {
        if (m_output.json) {
            m_output.out << QJsonDocument(valuesObject(values)).toJson(QJsonDocument::Indented);
        } else {
            for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
                const auto wire = values.value(meta.parameter);
                if (!wire)
                    continue;
                m_output.out << QString::fromLatin1(meta.key).leftJustified(18)
                             << userText(meta, *wire);
                if (*meta.unit && !meta.isSwitch)
                    m_output.out << ' ' << QString::fromUtf8(meta.unit);
                m_output.out << '\n';
            }
        }
        m_output.out.flush();
    }

    int read(const QStringList &operands)
    {
        if (!operands.isEmpty())
            throw UsageError {ServoctlTr::tr("ptk read takes no arguments")};
        PtkDevice device(m_args, m_output);
        const auto values = device.openAndRead();
        if (!values)
            return fail(device.error());
        printValues(*values);
        return ExitOk;
    }

    // Reads the servo, changes `changes`, writes the full sequence and compares the read-back.
    int program(const ptk::ParameterSet &changes)
    {
        PtkDevice device(m_args, m_output);
        auto values = device.openAndRead();
        if (!values)
            return fail(device.error());
        merge(*values, changes);
        const auto readBack = device.apply(*values);
        if (!readBack)
            return fail(device.error());
        QJsonArray mismatches;
        QStringList described;
        for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
            const quint16 wrote = *values->value(meta.parameter);
            const auto read = readBack->value(meta.parameter);
            if (read && *read == wrote)
                continue;
            mismatches.append(QJsonObject {
                {QStringLiteral("key"), QLatin1String(meta.key)},
                {QStringLiteral("written"), userValue(meta, wrote)},
                {QStringLiteral("read"), read ? userValue(meta, *read) : QJsonValue()}});
            described.append(ServoctlTr::tr("%1: wrote %2, the servo holds %3")
                                 .arg(QLatin1String(meta.key), userText(meta, wrote),
                                      read ? userText(meta, *read) : ServoctlTr::tr("nothing")));
        }
        const bool verified = mismatches.isEmpty();
        if (m_output.json) {
            const QJsonObject result {{QStringLiteral("verified"), verified},
                                      {QStringLiteral("values"), valuesObject(*readBack)},
                                      {QStringLiteral("mismatches"), mismatches}};
            m_output.out << QJsonDocument(result).toJson(QJsonDocument::Indented);
        } else if (verified) {
            m_output.out << ServoctlTr::tr("written and verified") << '\n';
        }
        m_output.out.flush();
        if (!verified)
            return fail(ServoctlTr::tr("verification failed: %1")
                            .arg(described.join(QStringLiteral("; "))));
        return ExitOk;
    }

    int write(const QStringList &operands)
    {
        if (operands.isEmpty())
            throw UsageError {ServoctlTr::tr("ptk write needs NAME=VALUE arguments (names: %1)")
                                  .arg(knownKeys())};
        const ptk::ParameterSet changes = parsePtkAssignments(operands);
        return program(changes);
    }

    int save(const QStringList &operands)
    {
        if (operands.size() != 1)
            throw UsageError {ServoctlTr::tr("ptk save needs one FILE")};
        const QString path = operands.first();
        const QFileInfo target(path);
        if (!target.absoluteDir().exists())
            throw UsageError {ServoctlTr::tr("the folder of %1 does not exist")
                                  .arg(QDir::toNativeSeparators(path))};
        PtkDevice device(m_args, m_output);
        const auto values = device.openAndRead();
        if (!values)
            return fail(device.error());
        profile::Profile saved;
        saved.family = kFamily;
        saved.saved = QDateTime::currentDateTimeUtc();
        for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
            saved.values.append({QLatin1String(meta.key), *values->value(meta.parameter)});
        util::FileError error;
        if (!profile::save(path, saved, ptk::modelDefinitions(), &error))
            return fail(error.describe());
        if (m_output.json)
            printValues(*values);
        else
            m_output.out << ServoctlTr::tr("saved %1").arg(QDir::toNativeSeparators(path)) << '\n';
        m_output.out.flush();
        return ExitOk;
    }

    int load(const QStringList &operands)
    {
        if (operands.size() != 1)
            throw UsageError {ServoctlTr::tr("ptk load needs one FILE")};
        util::FileError error;
        const auto loaded =
            profile::load(operands.first(), kFamily, ptk::modelDefinitions(), &error);
        if (!loaded)
            throw UsageError {error.describe()};
        ptk::ParameterSet changes;
        for (const profile::ProfileValue &value : loaded->values)
            changes.set(ptk::findParameter(value.key)->parameter, quint16(value.raw));
        return program(changes);
    }

    int monitor(const QStringList &operands)
    {
        if (!operands.isEmpty())
            throw UsageError {ServoctlTr::tr("ptk monitor takes no arguments")};
        const std::optional<double> duration = durationOption(m_args);
        const bool csv = m_args.flag(QStringLiteral("csv"));
        if (csv && m_output.json)
            throw UsageError {ServoctlTr::tr("choose --csv or --json, not both")};

        PtkDevice device(m_args, m_output);
        if (!device.open(true))
            return fail(device.error());
        if (csv) {
            QStringList header {QStringLiteral("time_s")};
            for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
                header.append(QLatin1String(meta.key));
            m_output.out << header.join(u',') << '\n';
        }
        QEventLoop loop;
        QElapsedTimer clock;
        clock.start();
        ptk::ParameterSet sweep;
        int rows = 0;
        int answered = 0;
        // One row per full refresh: all eight queries answered since the last row.
        QObject::connect(&device.session(), &ptk::Session::valuesRead, &loop,
                         [&](const ptk::ParameterSet &read, ptk::ReadSource) {
                             merge(sweep, read);
                             if (++answered < int(ptk::queryLayouts().size())
                                 || !sweep.isComplete())
                                 return;
                             answered = 0;
                             ++rows;
                             printRow(double(clock.elapsed()) / 1000.0, sweep, csv);
                         });
        streamWithoutWaiting(m_output);
        runUntilInterrupted(loop, duration);
        sayDroppedLines(m_output);
        if (rows == 0) {
            const QString message = device.session().status().message;
            return fail(message.isEmpty() ? ServoctlTr::tr("the servo did not answer") : message);
        }
        return ExitOk;
    }

    void printRow(double seconds, const ptk::ParameterSet &values, bool csv)
    {
        const QString time = QString::number(seconds, 'f', 3);
        if (m_output.json) {
            // One JSON document per line, so a monitor can be piped and read as it runs.
            const QJsonObject row {{QStringLiteral("time_s"), seconds},
                                   {QStringLiteral("values"), valuesObject(values)}};
            m_output.out << QJsonDocument(row).toJson(QJsonDocument::Compact) << '\n';
        } else if (csv) {
            QStringList cells {time};
            for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
                cells.append(QString::number(
                    ptk::toUserValue(meta.parameter, *values.value(meta.parameter))));
            m_output.out << cells.join(u',') << '\n';
        } else {
            QStringList cells {time};
            for (const ptk::ParameterInfo &meta : ptk::parameterInfos())
                cells.append(QStringLiteral("%1=%2").arg(
                    QLatin1String(meta.key), userText(meta, *values.value(meta.parameter))));
            m_output.out << cells.join(u' ') << '\n';
        }
        m_output.out.flush();
    }

    const Arguments &m_args;
    const Output &m_output;
};

} // namespace

int runPtkCommand(const Arguments &args, const QStringList &rest, const Output &output)
{
    return PtkCommand(args, output).run(rest);
}

ptk::ParameterSet parsePtkAssignments(const QStringList &assignments)
{
    QString error;
    const auto values = ptk::parseAssignments(assignments, &error);
    if (!values)
        throw UsageError {error};
    return *values;
}

} // namespace cli
