// Test support for a simulated Feetech bus: its options, test fixtures, scans and logged frames.
#pragma once

#include "feetech/busclient.h"
#include "feetech/feetechpacket.h"
#include "feetech/feetechsession.h"
#include "feetech/motiontest.h"
#include "sim/virtualfeetechservo.h"
#include "simclient.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>
#include <memory>

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
    options.linkPath = dir.filePath(name);
    options.logPath = dir.filePath(name + QStringLiteral(".log"));
    options.servos = std::move(servos);
    return options;
}

// Connects `client` to `link` at 1 Mbps and scans IDs up to `lastId` there: whether it was
// connected within 10 s and the scan finished within 20 s. Callers check what it found.
inline bool connectAndScan(feetech::BusClient &client, const QString &link, int lastId,
                           seriallink::EchoMode echo = seriallink::EchoMode::Auto)
{
    client.connectTo(link, 1000000, echo);
    if (!QTest::qWaitFor([&] { return client.isConnected(); }, 10000)) {
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
    const int index = client.indexOf(id, 1000000);
    if (index < 0)
        return -1;
    client.readServo(index);
    if (!QTest::qWaitFor([&] { return client.servo(index).read; }, 10000)) {
        qWarning("servo %d was not read within 10 s", id);
        return -1;
    }
    return index;
}

// The frames a simulator log shows the bus received, in order, as bytes; frames the simulator
// ignored (bad checksum, not a frame) included.
inline QVector<QByteArray> feetechFramesReceived(const QString &logPath)
{
    QVector<QByteArray> frames;
    for (const QString &line : logLinesStartingWith(logPath, QStringLiteral("in "))) {
        const QString hex = line.mid(3).section(QStringLiteral("  #"), 0, 0).trimmed();
        if (const auto bytes = util::parseHex(hex))
            frames.append(*bytes);
    }
    return frames;
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
    // echo; m_found collects the servos its scans find. False and *error when the simulator
    // would not start.
    bool startSession(const sim::SimulatorOptions &options, QString *error)
    {
        if (!startSimulator(options, error))
            return false;
        m_session = std::make_unique<feetech::Session>();
        connect(m_session.get(), &feetech::Session::servoFound, this,
                [this](const feetech::ServoInfo &servo) { m_found.append(servo); });
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

} // namespace testsupport
