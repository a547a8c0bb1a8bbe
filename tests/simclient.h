// Test helpers: a QSerialPort client on a simulator's pty, and simulator start-up in a temp dir.
#pragma once

#include "hex.h"
#include "linktypes.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "ptksession.h"
#include "simulatorthread.h"
#include "virtualptkservo.h"

#include <QFile>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

namespace testsupport {

// Collects every byte the simulator sends; waits by polling the event loop for a condition,
// never for a fixed time.
class PortClient
{
public:
    bool open(const QString &path, qint32 baud)
    {
        m_port.setPortName(path);
        if (!m_port.open(QIODevice::ReadWrite))
            return false;
        QObject::connect(&m_port, &QSerialPort::readyRead,
                         [this] { m_received += m_port.readAll(); });
        return setBaud(baud);
    }
    bool setBaud(qint32 baud) { return m_port.setBaudRate(baud); }
    void close() { m_port.close(); }

    void send(const QByteArray &bytes)
    {
        m_port.write(bytes);
        m_port.flush();
    }
    // Sends and waits until at least `count` bytes have come back; returns what came.
    QByteArray exchange(const QByteArray &request, int count, int timeoutMs = 2000)
    {
        m_received.clear();
        send(request);
        waitFor(count, timeoutMs);
        return m_received;
    }
    bool waitFor(int count, int timeoutMs = 2000)
    {
        return QTest::qWaitFor([&] { return m_received.size() >= count; }, timeoutMs);
    }
    QByteArray &received() { return m_received; }
    QSerialPort &port() { return m_port; }

private:
    QSerialPort m_port;
    QByteArray m_received;
};

// A simulator on its own thread with a client connected to its link.
struct ConnectedSimulator
{
    sim::SimulatorThread simulator;
    PortClient client;
    QString error;

    bool start(const sim::SimulatorOptions &options, qint32 baud)
    {
        if (!simulator.start(options, &error))
            return false;
        if (!client.open(simulator.linkPath(), baud)) {
            error = client.port().errorString();
            return false;
        }
        return true;
    }
};

// The connection states a spy on a statusChanged signal saw, in order.
inline QVector<seriallink::ConnectionState> connectionStates(const QSignalSpy &spy)
{
    QVector<seriallink::ConnectionState> states;
    for (const QList<QVariant> &arguments : spy)
        states.append(arguments.at(0).value<seriallink::ConnectionStatus>().state);
    return states;
}

// Lines of a simulator log with the timestamps cut off ("in AF FA ...").
inline QStringList logLines(const QString &path)
{
    QFile file(path);
    QStringList lines;
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return lines;
    for (const QByteArray &line : file.readAll().split('\n')) {
        const int space = line.indexOf(' ');
        if (space > 0)
            lines.append(QString::fromLatin1(line.mid(space + 1)));
    }
    return lines;
}

inline QStringList logLinesStartingWith(const QString &path, const QString &prefix)
{
    QStringList matching;
    for (const QString &line : logLines(path)) {
        if (line.startsWith(prefix))
            matching.append(line);
    }
    return matching;
}

// A simulated PTK servo on `name` in `dir`, logging to `name`.log.
// The device the end-to-end tests meet: servosim's own wire timing, or with
// SERVOBENCH_TEST_DEVICE=instant a device that answers the moment a frame is complete, as
// virtual ports, emulators and USB CDC devices do. CTest runs the timing-sensitive tests both
// ways (tests/CMakeLists.txt).
inline bool instantTestDevice()
{
    return qEnvironmentVariable("SERVOBENCH_TEST_DEVICE") == QLatin1String("instant");
}

inline sim::SimulatorOptions ptkOptions(const QTemporaryDir &dir, const QString &name,
                                        bool echo = false)
{
    sim::SimulatorOptions options;
    options.instant = instantTestDevice();
    options.kind = sim::SimulatorOptions::Kind::Ptk;
    options.linkPath = dir.filePath(name);
    options.logPath = dir.filePath(name + QStringLiteral(".log"));
    options.echo = echo;
    return options;
}

// PTK timing fast enough that a test runs in well under a second, slow enough to keep PTK's
// order.
inline ptk::SessionTiming ptkTestTiming()
{
    ptk::SessionTiming timing;
    timing.pollInterval = std::chrono::milliseconds(5);
    timing.writeGap = std::chrono::milliseconds(5);
    timing.reconnectInterval = std::chrono::milliseconds(50);
    timing.engine.replyTimeout = std::chrono::milliseconds(20);
    return timing;
}

// What the simulated PTK servo holds now, looked at in the simulator's thread.
inline ptk::ParameterSet ptkServoValues(sim::SimulatorThread &simulator)
{
    ptk::ParameterSet values;
    simulator.call([&](sim::Simulator &s) { values = s.ptkServo()->values(); });
    return values;
}

// The frames of a simulator log whose lines start with `direction` ("in", "out"), in order, as
// bytes; the direction and any note cut off.
inline QVector<QByteArray> framesLogged(const QString &logPath, const QString &direction)
{
    QVector<QByteArray> frames;
    for (const QString &line : logLinesStartingWith(logPath, direction + u' ')) {
        const QString hex =
            line.mid(direction.size() + 1).section(QStringLiteral("  #"), 0, 0).trimmed();
        if (const auto bytes = util::parseHex(hex))
            frames.append(*bytes);
    }
    return frames;
}

// The commands of the PTK queries a simulator log shows the servo received, in order.
inline QVector<quint8> ptkQueriesReceived(const QString &logPath)
{
    QVector<quint8> commands;
    for (const QByteArray &frame : framesLogged(logPath, QStringLiteral("in"))) {
        if (frame.size() == ptk::kRequestSize && ptk::findQuery(quint8(frame.at(4))))
            commands.append(quint8(frame.at(4)));
    }
    return commands;
}

// The PTK write frames a simulator log shows the servo received, in order, as hex.
inline QStringList ptkWritesReceived(const QString &logPath)
{
    QStringList writes;
    for (const QByteArray &frame : framesLogged(logPath, QStringLiteral("in"))) {
        if (frame.size() == ptk::kRequestSize && ptk::findWrite(quint8(frame.at(4))))
            writes.append(util::toHex(frame));
    }
    return writes;
}

// The hex of the full N1..N12 sequence that programs `values`.
inline QStringList ptkWriteFrames(const ptk::ParameterSet &values)
{
    QStringList frames;
    if (const auto sequence = ptk::writeSequence(values)) {
        for (const ptk::Request &request : *sequence)
            frames.append(util::toHex(ptk::encodeRequest(request)));
    }
    return frames;
}

} // namespace testsupport
