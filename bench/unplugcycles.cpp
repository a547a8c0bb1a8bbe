// Unplug cycles: each kind of work cut by the simulator going away, then the reconnection and
// what the client shows checked against the simulator; threads, open files and memory measured.
#include "unplugcycles.h"

#include "operationwait.h"

#include "busclient.h"
#include "processmemory.h"
#include "ptkclient.h"
#include "servoctl.h"
#include "simulatorthread.h"
#include "virtualptkservo.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QEventLoop>
#include <QJsonArray>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTextStream>
#include <QTimer>

#include <functional>

namespace unplug {

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kServos = 6;
constexpr int kWaitMs = 10000; // what counts as a hang
constexpr int kMaxExamples = 5;
using Connection = seriallink::ConnectionState;

// Runs the event loop until `done` or the time is up; whether it was done.
bool waitUntil(const std::function<bool()> &done, int timeoutMs = kWaitMs)
{
    const QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        if (deadline.hasExpired())
            return false;
        QEventLoop loop;
        QTimer::singleShot(2, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

void pause(int milliseconds)
{
    waitUntil([] { return false; }, milliseconds);
}

int entriesIn(const QString &path)
{
    return int(QDir(path).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot).size());
}

// A simulator that can be unplugged (stopped) and plugged in again on the same path, its EEPROM
// kept in a state file as a real servo keeps it.
class Bench
{
public:
    explicit Bench(sim::SimulatorOptions::Kind kind)
    {
        m_options.kind = kind;
        m_options.linkPath = m_dir.filePath(QStringLiteral("port"));
        if (kind == sim::SimulatorOptions::Kind::Ptk) {
            m_options.echo = true;
        } else {
            m_options.statePath = m_dir.filePath(QStringLiteral("eeprom.json"));
            for (int id = 1; id <= kServos; ++id)
                m_options.servos.append({quint8(id), QStringLiteral("STS3215"), k1M});
        }
    }
    bool plugIn()
    {
        QString error;
        return m_simulator.start(m_options, &error);
    }
    void unplug() { m_simulator.stop(); }
    QString port() const { return m_options.linkPath; }
    sim::SimulatorThread &simulator() { return m_simulator; }

private:
    QTemporaryDir m_dir;
    sim::SimulatorOptions m_options;
    sim::SimulatorThread m_simulator;
};

// ---- PTK, through ptk::Client

QString ptkShowsWhatItHolds(ptk::Client &client, Bench &bench)
{
    ptk::ParameterSet held;
    bench.simulator().call([&](sim::Simulator &s) { held = s.ptkServo()->values(); });
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
        const auto shown = client.model()->deviceValue(QLatin1String(meta.key));
        const auto truth = held.value(meta.parameter);
        if (shown && truth && *shown != *truth)
            return QStringLiteral("%1 shows %2, the servo holds %3")
                .arg(QLatin1String(meta.key))
                .arg(*shown)
                .arg(*truth);
    }
    return {};
}

// A full read of the eight queries; whether it came.
bool readAll(ptk::Client &client)
{
    bool read = false;
    const auto done = QObject::connect(&client, &ptk::Client::readFinished,
                                       [&read](bool ok, const QString &) { read = ok; });
    client.readAll();
    const bool gotIt = waitUntil([&] { return read; });
    QObject::disconnect(done);
    return gotIt;
}

// Cut in the middle of polling or an Apply, then back.
QString ptkCycle(ptk::Client &client, Bench &bench, bool apply)
{
    if (apply) {
        const qint64 gain = client.model()->deviceValue(QStringLiteral("gain")).value_or(20);
        client.model()->edit(QStringLiteral("gain"), gain == 20 ? 21 : 20);
        bool ended = false;
        int written = 0;
        const auto progress = QObject::connect(&client, &ptk::Client::applyProgress,
                                               [&written](int done, int) { written = done; });
        const auto finished = QObject::connect(&client, &ptk::Client::applyFinished,
                                               [&ended](bool, const QString &) { ended = true; });
        QString error;
        if (!client.apply(&error))
            return QStringLiteral("Apply refused: ") + error;
        const int cutAfter = 2 + QRandomGenerator::global()->bounded(8); // of twelve frames
        waitUntil([&] { return written >= cutAfter; });
        bench.unplug();
        const bool hung = !waitUntil([&] { return ended; });
        QObject::disconnect(progress);
        QObject::disconnect(finished);
        if (hung)
            return QStringLiteral("the Apply never ended after the port went");
    } else {
        const qint64 before = client.counters().repliesOk;
        waitUntil([&] { return client.counters().repliesOk > before + 3; });
        bench.unplug();
    }
    if (!waitUntil([&] { return client.status().state == Connection::Lost; }))
        return QStringLiteral("the lost port was not noticed");
    if (!bench.plugIn())
        return QStringLiteral("the simulator did not start again");
    if (!waitUntil([&] { return client.status().state == Connection::Connected; }))
        return QStringLiteral("no reconnection");
    if (!readAll(client))
        return QStringLiteral("no full read after reconnecting");
    return ptkShowsWhatItHolds(client, bench);
}

// ---- Feetech, through feetech::BusClient

std::optional<feetech::OperationResult>
operate(const std::function<feetech::OperationReply *()> &start)
{
    return soak::runOperation(start, kWaitMs);
}

bool scan(feetech::BusClient &client)
{
    bool finished = false;
    const auto connection = QObject::connect(&client, &feetech::BusClient::scanFinished,
                                             [&finished] { finished = true; });
    feetech::ScanOptions options;
    options.lastId = 10;
    client.scan(options);
    const bool ended = waitUntil([&] { return finished; });
    QObject::disconnect(connection);
    return ended && client.servos()->count() == kServos;
}

QString feetechShowsWhatItHolds(feetech::BusClient &client, Bench &bench, int index)
{
    if (!operate([&] { return client.readServo(index); }))
        return QStringLiteral("no full read after reconnecting");
    const feetech::Servo &servo = client.servos()->at(index);
    QString wrong;
    bench.simulator().call([&](sim::Simulator &s) {
        s.advanceNow();
        const sim::VirtualFeetechServo *held = s.feetechBus()->findServo(servo.info.id);
        for (const model::Definition &definition : servo.parameters->definitions()) {
            const feetech::Register *reg = servo.info.table().find(definition.key);
            const auto shown = servo.parameters->deviceValue(definition.key);
            // EEPROM settings only: present values move between the read and this look.
            if (!held || !reg || reg->storage != feetech::Storage::Eeprom || !shown)
                continue;
            if (*shown != held->value(definition.key) && wrong.isEmpty())
                wrong = QStringLiteral("%1 shows %2, the servo holds %3")
                            .arg(definition.key)
                            .arg(*shown)
                            .arg(held->value(definition.key));
        }
    });
    return wrong;
}

QString feetechCycle(feetech::BusClient &client, Bench &bench, Work work)
{
    const int cutAfterMs = QRandomGenerator::global()->bounded(1, 30);
    std::optional<feetech::OperationResult> result;
    bool ended = false;
    switch (work) {
    case Work::FeetechScan: {
        const auto connection = QObject::connect(&client, &feetech::BusClient::scanFinished,
                                                 [&ended] { ended = true; });
        feetech::ScanOptions options;
        client.scan(options);
        pause(cutAfterMs);
        bench.unplug();
        const bool hung = !waitUntil([&] { return ended; });
        QObject::disconnect(connection);
        if (hung)
            return QStringLiteral("the scan never ended after the port went");
        break;
    }
    case Work::FeetechApply:
    case Work::FeetechFlow: {
        feetech::Refusal refusal;
        feetech::OperationReply *reply = nullptr;
        if (work == Work::FeetechApply) {
            const qint64 now = client.servos()
                                   ->parameters(0)
                                   ->deviceValue(QStringLiteral("max_temperature"))
                                   .value_or(70);
            client.servos()->parameters(0)->edit(QStringLiteral("max_temperature"),
                                                 now == 70 ? 71 : 70);
            reply = client.apply(0, &refusal);
        } else {
            reply = client.commands()->reboot(0, &refusal);
        }
        if (!reply)
            return QStringLiteral("refused: ") + refusal.describe();
        const auto connection =
            QObject::connect(reply, &feetech::OperationReply::finished, [&ended] { ended = true; });
        pause(cutAfterMs / 10);
        bench.unplug();
        const bool hung = !waitUntil([&] { return ended; });
        QObject::disconnect(connection);
        if (hung)
            return QStringLiteral("the operation never ended after the port went");
        break;
    }
    case Work::FeetechStream: {
        feetech::Refusal refusal;
        if (!client.telemetry()->subscribe(&client, {0, 1, 2, 3, 4, 5}, 50.0, &refusal))
            return QStringLiteral("the stream did not start: ") + refusal.describe();
        qint64 samples = 0;
        const auto connection = QObject::connect(
            client.telemetry(), &feetech::TelemetryHub::samplesReceived,
            [&samples](const QVector<feetech::FeedbackSample> &batch) { samples += batch.size(); });
        waitUntil([&] { return samples > 30; });
        bench.unplug();
        if (!waitUntil([&] { return client.link()->status().state == Connection::Lost; })) {
            QObject::disconnect(connection);
            return QStringLiteral("the lost port was not noticed");
        }
        if (!bench.plugIn() || !waitUntil([&] { return client.link()->isConnected(); })) {
            QObject::disconnect(connection);
            return QStringLiteral("no reconnection");
        }
        // The stream is started again, as the Monitor page's Start does.
        client.telemetry()->subscribe(&client, {0, 1, 2, 3, 4, 5}, 50.0);
        samples = 0;
        const bool flowing = waitUntil([&] { return samples > 30; });
        client.telemetry()->unsubscribe(&client);
        QObject::disconnect(connection);
        return flowing ? QString() : QStringLiteral("no samples after reconnecting");
    }
    default:
        break;
    }
    if (!waitUntil([&] { return client.link()->status().state == Connection::Lost; }))
        return QStringLiteral("the lost port was not noticed");
    if (!bench.plugIn())
        return QStringLiteral("the simulator did not start again");
    if (!waitUntil([&] { return client.link()->isConnected(); }))
        return QStringLiteral("no reconnection");
    if (work == Work::FeetechScan && !scan(client))
        return QStringLiteral("the scan after reconnecting did not find the six servos");
    return feetechShowsWhatItHolds(client, bench, 0);
}

// ---- servoctl, in this process

QString servoctlCycle(Bench &bench, Work work)
{
    QStringList arguments {QStringLiteral("--port"), bench.port(), QStringLiteral("feetech")};
    if (work == Work::ServoctlMonitor)
        arguments << QStringLiteral("monitor") << QStringLiteral("--ids") << QStringLiteral("1-6")
                  << QStringLiteral("--duration") << QStringLiteral("5");
    else
        arguments << QStringLiteral("set") << QStringLiteral("--id") << QStringLiteral("1")
                  << QStringLiteral("max_temperature=69");
    const int cutAfterMs = work == Work::ServoctlMonitor
        ? 200 + QRandomGenerator::global()->bounded(300)
        : QRandomGenerator::global()->bounded(1, 20);
    QTimer::singleShot(cutAfterMs, [&bench] { bench.unplug(); });
    QString out;
    QString err;
    QTextStream outStream(&out);
    QTextStream errStream(&err);
    const QDeadlineTimer deadline(kWaitMs);
    const int code = cli::runServoctl(arguments, outStream, errStream);
    errStream.flush();
    if (deadline.hasExpired())
        return QStringLiteral("servoctl took longer than %1 s").arg(kWaitMs / 1000);
    waitUntil([&bench] { return !bench.simulator().isRunning(); }, 1000);
    if (!bench.plugIn())
        return QStringLiteral("the simulator did not start again");
    if (work == Work::ServoctlMonitor && code == 0)
        return QStringLiteral("monitor exited 0 although the port went");
    if (code != 0 && err.trimmed().isEmpty())
        return QStringLiteral("exit %1 without a message").arg(code);
    if (work == Work::ServoctlSet && code == 0) {
        // Reported written: the servo (its EEPROM kept across the unplug) must hold it.
        qint32 held = -1;
        bench.simulator().call([&held](sim::Simulator &s) {
            if (const auto *servo = s.feetechBus()->findServo(1))
                held = servo->value(u"max_temperature");
        });
        if (held != 69)
            return QStringLiteral("set reported done, the servo holds %1").arg(held);
    }
    return {};
}

} // namespace

QVector<Work> allWork()
{
    return {Work::PtkPolling,  Work::PtkApply,      Work::FeetechScan,     Work::FeetechApply,
            Work::FeetechFlow, Work::FeetechStream, Work::ServoctlMonitor, Work::ServoctlSet};
}

QString workName(Work work)
{
    switch (work) {
    case Work::PtkPolling:
        return QStringLiteral("ptk-polling");
    case Work::PtkApply:
        return QStringLiteral("ptk-apply");
    case Work::FeetechScan:
        return QStringLiteral("feetech-scan");
    case Work::FeetechApply:
        return QStringLiteral("feetech-apply");
    case Work::FeetechFlow:
        return QStringLiteral("feetech-reboot-flow");
    case Work::FeetechStream:
        return QStringLiteral("feetech-stream");
    case Work::ServoctlMonitor:
        return QStringLiteral("servoctl-monitor");
    case Work::ServoctlSet:
        return QStringLiteral("servoctl-set");
    }
    return {};
}

Resources resourcesNow()
{
    Resources now;
    now.threads = entriesIn(QStringLiteral("/proc/self/task"));
    now.openFiles = entriesIn(QStringLiteral("/proc/self/fd"));
    if (const auto memory = util::processMemory())
        now.residentMb = memory->residentMb;
    return now;
}

QJsonObject CycleReport::toJson() const
{
    const auto resources = [](const Resources &r) {
        return QJsonObject {{QStringLiteral("threads"), r.threads},
                            {QStringLiteral("open_files"), r.openFiles},
                            {QStringLiteral("resident_mb"), r.residentMb}};
    };
    return {{QStringLiteral("work"), workName(work)},
            {QStringLiteral("cycles"), cycles},
            {QStringLiteral("problems"), problems},
            {QStringLiteral("examples"), QJsonArray::fromStringList(examples)},
            {QStringLiteral("after_first_cycle"), resources(first)},
            {QStringLiteral("after_last_cycle"), resources(last)}};
}

CycleReport runCycles(Work work, int cycles)
{
    CycleReport report;
    report.work = work;
    const bool ptk = work == Work::PtkPolling || work == Work::PtkApply;
    Bench bench(ptk ? sim::SimulatorOptions::Kind::Ptk : sim::SimulatorOptions::Kind::Feetech);
    const auto problem = [&report](int cycle, const QString &text) {
        ++report.problems;
        if (report.examples.size() < kMaxExamples)
            report.examples.append(QStringLiteral("cycle %1: %2").arg(cycle).arg(text));
    };
    if (!bench.plugIn()) {
        problem(0, QStringLiteral("the simulator did not start"));
        return report;
    }
    std::unique_ptr<ptk::Client> ptkClient;
    std::unique_ptr<feetech::BusClient> busClient;
    ptk::SessionTiming ptkTiming;
    ptkTiming.reconnectInterval = std::chrono::milliseconds(50);
    feetech::SessionTiming busTiming;
    busTiming.reconnectInterval = std::chrono::milliseconds(50);
    if (ptk) {
        ptkClient = std::make_unique<ptk::Client>(ptkTiming);
        ptkClient->connectTo(bench.port());
        if (!waitUntil([&] { return ptkClient->isConnected(); }) || !readAll(*ptkClient))
            problem(0, QStringLiteral("no first connection and read"));
    } else if (work != Work::ServoctlMonitor && work != Work::ServoctlSet) {
        busClient = std::make_unique<feetech::BusClient>(busTiming);
        busClient->connectTo(bench.port(), k1M);
        if (!waitUntil([&] { return busClient->link()->isConnected(); }) || !scan(*busClient))
            problem(0, QStringLiteral("no first connection and scan"));
        else
            feetechShowsWhatItHolds(*busClient, bench, 0);
    }
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        QString wrong;
        if (ptkClient)
            wrong = ptkCycle(*ptkClient, bench, work == Work::PtkApply);
        else if (busClient)
            wrong = feetechCycle(*busClient, bench, work);
        else
            wrong = servoctlCycle(bench, work);
        if (!wrong.isEmpty())
            problem(cycle, wrong);
        ++report.cycles;
        if (cycle == 1)
            report.first = resourcesNow();
    }
    report.last = resourcesNow();
    return report;
}

} // namespace unplug
