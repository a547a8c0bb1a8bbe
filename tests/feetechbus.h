// Test support for a simulated Feetech bus: its options, test fixtures, scans and logged frames.
#pragma once

#include "busclient.h"
#include "busexchange.h"
#include "feetechpacket.h"
#include "feetechsession.h"
#include "linksession.h"
#include "motiontest.h"
#include "simclient.h"
#include "virtualfeetechservo.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

namespace testsupport {

// Motion-test timing short enough for tests to run in seconds; the behaviour does not depend
// on it.
inline feetech::MotionTiming quickMotionTiming()
{
    feetech::MotionTiming timing;
    timing.reachTimeout = std::chrono::milliseconds(5000);
    timing.dwell = std::chrono::milliseconds(50);
    timing.finalSamplesGrace = std::chrono::milliseconds(150);
    return timing;
}

// A sweep of servo `index` between 1800 and 2300 long enough to be running whenever a test
// looks (cancel it when done).
inline feetech::MotionPlan longSweep(int index)
{
    feetech::MotionPlan plan;
    plan.index = index;
    plan.from = 1800;
    plan.to = 2300;
    plan.legs = feetech::MotionPlan::kMaximumLegs;
    return plan;
}

// Servos with IDs 1, 2, ... of `models`, all at `baud`.
inline QVector<sim::FeetechServoSpec> servosAt(qint32 baud,
                                               std::initializer_list<QStringView> models)
{
    QVector<sim::FeetechServoSpec> servos;
    for (const QStringView model : models)
        servos.append({quint8(servos.size() + 1), model.toString(), baud});
    return servos;
}

// A simulated Feetech bus with `servos` on `name` in `dir`, logging to `name`.log.
inline sim::SimulatorOptions feetechBusOptions(const QTemporaryDir &dir, const QString &name,
                                               QVector<sim::FeetechServoSpec> servos)
{
    sim::SimulatorOptions options;
    options.kind = sim::SimulatorOptions::Kind::Feetech;
    options.instant = testsupport::instantTestDevice();
    options.linkPath = dir.filePath(name);
    options.logPath = dir.filePath(name + QStringLiteral(".log"));
    options.servos = std::move(servos);
    return options;
}

// Runs `work` on the simulated Feetech bus in the simulator's thread; what it returns.
template<typename Work>
auto onSimulatedBus(sim::SimulatorThread &simulator, Work work)
{
    decltype(work(std::declval<sim::VirtualFeetechBus &>())) result {};
    simulator.call([&](sim::Simulator &running) { result = work(*running.feetechBus()); });
    return result;
}

// The present position of the servo at `index` on a simulated bus.
inline int simulatedPosition(sim::SimulatorThread &simulator, int index)
{
    return onSimulatedBus(simulator, [index](sim::VirtualFeetechBus &bus) {
        return bus.servo(index).value(u"present_position");
    });
}

// Connects `client` to `link` at 1 Mbps and scans IDs up to `lastId` there: whether it was
// connected within 10 s and the scan finished within 20 s. Callers check what it found.
inline bool connectAndScan(feetech::BusClient &client, const QString &link, int lastId,
                           seriallink::EchoMode echo = seriallink::EchoMode::Auto)
{
    client.connectTo(link, 1000000, echo);
    if (!QTest::qWaitFor([&] { return client.link()->isConnected(); }, 10000)) {
        qWarning("not connected to %s within 10 s", qPrintable(link));
        return false;
    }
    feetech::ScanOptions options;
    options.lastId = lastId;
    QSignalSpy finished(&client, &feetech::BusClient::scanFinished);
    client.scan(options);
    if (finished.isEmpty() && !finished.wait(20000)) {
        qWarning("the scan of %s did not finish within 20 s", qPrintable(link));
        return false;
    }
    return true;
}

// connectAndScan, then a full read of servo `id` at 1 Mbps: its index, -1 when the servo was
// not found or not read within 10 s.
inline int connectScanAndRead(feetech::BusClient &client, const QString &link, int lastId,
                              quint8 id)
{
    if (!connectAndScan(client, link, lastId))
        return -1;
    const int index = client.servos()->indexOf({id, 1000000});
    if (index < 0)
        return -1;
    client.readServo(index);
    if (!QTest::qWaitFor([&] { return client.servos()->at(index).read; }, 10000)) {
        qWarning("servo %d was not read within 10 s", id);
        return -1;
    }
    return index;
}

// The frames a simulator log shows the bus received, in order, as bytes; frames the simulator
// ignored (bad checksum, not a frame) included.
inline QVector<QByteArray> feetechFramesReceived(const QString &logPath)
{
    return framesLogged(logPath, QStringLiteral("in"));
}

// Those frames decoded; one that does not decode (header, length, checksum) is left out.
inline QVector<feetech::Packet> feetechPacketsReceived(const QString &logPath)
{
    QVector<feetech::Packet> packets;
    for (const QByteArray &frame : feetechFramesReceived(logPath)) {
        if (const auto packet = feetech::decodePacket(frame))
            packets.append(*packet);
    }
    return packets;
}

// The instruction packets the bus received with instruction `code`, in order; only those to
// `id` when one is given.
inline QVector<feetech::Packet> feetechRequestsReceived(const QString &logPath,
                                                        feetech::Instruction code,
                                                        std::optional<quint8> id = std::nullopt)
{
    QVector<feetech::Packet> requests;
    for (const feetech::Packet &packet : feetechPacketsReceived(logPath)) {
        if (packet.code == quint8(code) && (!id || packet.id == *id))
            requests.append(packet);
    }
    return requests;
}

// Session timing patient enough for a loaded machine: tests that are not about how quickly the
// bus answers must not fail because a reply came a little late.
inline feetech::SessionTiming patientTiming()
{
    feetech::SessionTiming timing;
    timing.engine.replyTimeout = std::chrono::milliseconds(100);
    timing.probeAllowance = std::chrono::milliseconds(200);
    timing.minimumScanAllowance = std::chrono::milliseconds(20);
    timing.minimumTelemetryAllowance = std::chrono::milliseconds(20);
    return timing;
}

// Base of a test object whose tests run against a simulated Feetech bus on "bus" in a temporary
// directory of its own, logging to "bus.log" there. It declares no slots, so no tests.
class FeetechBusTest : public QObject
{
protected:
    sim::SimulatorOptions busOptions(QVector<sim::FeetechServoSpec> servos) const
    {
        return feetechBusOptions(m_dir, QStringLiteral("bus"), std::move(servos));
    }

    // Replaces the running simulator, if any; false and *error when the new one would not start.
    bool startSimulator(const sim::SimulatorOptions &options, QString *error)
    {
        m_simulator = std::make_unique<sim::SimulatorThread>();
        return m_simulator->start(options, error);
    }

    QString logPath() const { return m_dir.filePath(QStringLiteral("bus.log")); }

    // Writes `contents` to `name` in the test's directory: its path (empty when it failed).
    QString writeTestFile(const QString &name, const QByteArray &contents) const
    {
        const QString path = m_dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return {};
        file.write(contents);
        return path;
    }

    // Register `key` of simulated servo `id`, looked at in the simulator's thread; -1 without
    // that servo.
    qint32 simulatorValue(quint8 id, QStringView key)
    {
        qint32 value = -1;
        m_simulator->call([&](sim::Simulator &simulator) {
            if (sim::VirtualFeetechServo *servo = simulator.feetechBus()->findServo(id))
                value = servo->value(key);
        });
        return value;
    }

    // Runs `work` in the simulator's thread on the simulated servo with `id` that listens at
    // `baud` (IDs repeat across rates); false without that servo.
    bool withServo(quint8 id, qint32 baud,
                   const std::function<void(sim::VirtualFeetechServo &)> &work)
    {
        bool found = false;
        m_simulator->call([&](sim::Simulator &simulator) {
            sim::VirtualFeetechBus &bus = *simulator.feetechBus();
            for (int i = 0; i < bus.servoCount() && !found; ++i) {
                if (bus.servo(i).id() == id && bus.servo(i).baudRate() == baud) {
                    found = true;
                    work(bus.servo(i));
                }
            }
        });
        return found;
    }

    // Sets register `key` of simulated servo `id` as if the servo itself had changed it.
    void setSimulatorValue(quint8 id, QStringView key, qint32 value)
    {
        m_simulator->call([&](sim::Simulator &simulator) {
            if (sim::VirtualFeetechServo *servo = simulator.feetechBus()->findServo(id))
                servo->setValue(key, value);
        });
    }

    QTemporaryDir m_dir;
    std::unique_ptr<sim::SimulatorThread> m_simulator;
};

// Base of a test object whose tests drive a feetech::Session on the simulated bus.
class FeetechSessionTest : public FeetechBusTest
{
protected:
    // Starts the simulator with `options` and opens a new session on its link at 1 Mbps without
    // echo; m_found collects the servos its scans find, in ID order (a servo that answered late
    // is found in the scan's second look, after higher IDs). False and *error when the simulator
    // would not start.
    bool startSession(const sim::SimulatorOptions &options, QString *error)
    {
        if (!startSimulator(options, error))
            return false;
        m_session = std::make_unique<feetech::Session>();
        connect(m_session.get(), &feetech::Session::servoFound, this,
                [this](const feetech::ServoInfo &servo) {
                    const auto before = std::find_if(
                        m_found.begin(), m_found.end(),
                        [&servo](const feetech::ServoInfo &found) { return found.id > servo.id; });
                    m_found.insert(before, servo);
                });
        m_session->open(m_simulator->linkPath(), 1000000, seriallink::EchoMode::Off);
        return true;
    }

    // Closes the session, stops the simulator and deletes its log.
    void stopSession()
    {
        m_session.reset();
        m_simulator.reset();
        QFile::remove(logPath());
    }

    // Calls `start`, which starts an operation on the session, and waits up to 10 s for its
    // result; an empty result when none came. A refusal can come at once, before anything is
    // sent.
    feetech::OperationResult run(const std::function<void()> &start)
    {
        QSignalSpy finished(m_session.get(), &feetech::Session::operationFinished);
        start();
        if (finished.isEmpty() && !finished.wait(10000))
            return {};
        return finished.first().at(0).value<feetech::OperationResult>();
    }

    std::unique_ptr<feetech::Session> m_session;
    QVector<feetech::ServoInfo> m_found;
};

// Base of a test object whose tests drive the parts of a Feetech session (scan, guided flows,
// telemetry cycle) themselves, in the test thread: a link session on the simulated bus and the
// bus steps over it, with the timing in m_timing (patientTiming() unless a test says otherwise).
class FeetechLinkTest : public FeetechBusTest
{
protected:
    // Starts the simulator with `options` and opens the link on it at `baud` without echo,
    // Connected as a session would say; false and *error when either fails.
    bool startLink(const sim::SimulatorOptions &options, QString *error, qint32 baud = 1000000)
    {
        if (!startSimulator(options, error))
            return false;
        m_link = std::make_unique<seriallink::LinkSession>(
            m_format, [](const QByteArray &, const QByteArray &) { return QString(); });
        m_link->engine().setTiming(m_timing.engine);
        m_bus = std::make_unique<feetech::BusExchange>(*m_link, m_timing);
        if (!m_link->open(m_simulator->linkPath(), baud, seriallink::EchoMode::Off)) {
            *error = m_link->status().message;
            return false;
        }
        m_link->setState(seriallink::ConnectionState::Connected);
        return true;
    }

    // Closes the link, stops the simulator, deletes its log and puts the patient timing back.
    void stopLink()
    {
        m_bus.reset();
        m_link.reset();
        m_simulator.reset();
        QFile::remove(logPath());
        m_timing = patientTiming();
    }

    // Runs `steps` on the bus and waits up to 10 s for the run to end: whether every step
    // succeeded (false when it did not end), with the message of the failure in *message.
    bool runSteps(std::vector<feetech::Step> steps, QString *message = nullptr)
    {
        // Shared: a run that ends after the wait gave up must not write into this frame.
        auto outcome = std::make_shared<std::optional<std::pair<bool, QString>>>();
        m_bus->runSteps(std::move(steps), [outcome](bool ok, const QString &why) {
            *outcome = std::make_pair(ok, why);
        });
        if (!QTest::qWaitFor([&] { return outcome->has_value(); }, 10000)) {
            if (message)
                *message = QStringLiteral("the steps did not end within 10 s");
            return false;
        }
        if (message)
            *message = (*outcome)->second;
        return (*outcome)->first;
    }

    // Servo `id` at `baud` as it identifies itself; nothing when it does not answer.
    std::optional<feetech::ServoInfo> identify(quint8 id, qint32 baud)
    {
        auto servo = std::make_shared<feetech::ServoInfo>();
        servo->id = id;
        servo->baud = baud;
        if (!runSteps({m_bus->setBaud(baud), m_bus->identify(servo)}))
            return std::nullopt;
        return *servo;
    }

    feetech::SessionTiming m_timing = patientTiming();
    feetech::FrameFormat m_format; // the link's framer keeps a reference: declared first
    std::unique_ptr<seriallink::LinkSession> m_link;
    std::unique_ptr<feetech::BusExchange> m_bus;
};

} // namespace testsupport
