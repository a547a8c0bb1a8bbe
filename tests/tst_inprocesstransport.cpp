// Tests of the in-process port and its transport: bytes both ways with the host's rate, bytes
// sent ahead arriving at their time, close, a second host, a device that stops and returns, and
// a bus client on simulated servos reached through it (wire-timed, and with
// SERVOBENCH_TEST_DEVICE=instant at once).
#include "busclient.h"
#include "feetechbus.h"
#include "feetechpacket.h"
#include "inprocessport.h"
#include "inprocesstransport.h"
#include "porttransport.h"
#include "serialtransport.h"
#include "servolist.h"

#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <atomic>
#include <chrono>

using seriallink::InProcessPort;
using seriallink::InProcessTransport;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k500k = 500000;

// Every byte a transport delivers, in order.
QByteArray receivedBytes(const QSignalSpy &spy)
{
    QByteArray bytes;
    for (const QList<QVariant> &arguments : spy)
        bytes += arguments.at(0).toByteArray();
    return bytes;
}

// A device on a thread of its own behind an in-process port: it answers each chunk of bytes
// with the same bytes reversed, and remembers the rate it heard them at.
class EchoDevice
{
public:
    explicit EchoDevice(const QString &name)
    {
        m_port = new InProcessPort;
        QString error;
        m_opened = m_port->open(name, &error);
        m_port->moveToThread(&m_thread);
        QObject::connect(m_port, &InProcessPort::received, m_port, [this](const QByteArray &bytes) {
            m_heardBaud = m_port->hostBaudRate();
            m_heardBytes += bytes.size();
            QByteArray reversed(bytes.size(), '\0');
            std::reverse_copy(bytes.cbegin(), bytes.cend(), reversed.begin());
            m_port->write(reversed);
        });
        m_thread.start();
    }
    ~EchoDevice()
    {
        stopOffering();
        QMetaObject::invokeMethod(
            m_port, [this] { delete m_port; }, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }
    EchoDevice(const EchoDevice &) = delete;
    EchoDevice &operator=(const EchoDevice &) = delete;

    bool opened() const { return m_opened; }
    QString name() const { return m_port->portName(); }
    qint32 heardBaud() const { return m_heardBaud; }
    int heardBytes() const { return m_heardBytes; }
    bool hasHost() const { return m_port->hasHost(); }
    // The device stops: its port is no longer offered.
    void stopOffering()
    {
        QMetaObject::invokeMethod(
            m_port, [this] { m_port->close(); }, Qt::BlockingQueuedConnection);
    }
    // It comes back under `name`.
    void offerAgain(const QString &name)
    {
        QMetaObject::invokeMethod(
            m_port, [this, name] { m_opened = m_port->open(name, nullptr); },
            Qt::BlockingQueuedConnection);
    }
    // Sends `bytes` to the host unasked, from the device's thread.
    void send(const QByteArray &bytes)
    {
        QMetaObject::invokeMethod(
            m_port, [this, bytes] { m_port->write(bytes); }, Qt::BlockingQueuedConnection);
    }
    // Hands `bytes` over now, for the host to have `after` from now.
    void sendAhead(const QByteArray &bytes, std::chrono::milliseconds after)
    {
        QMetaObject::invokeMethod(
            m_port,
            [this, bytes, after] {
                m_port->writeAt(bytes, std::chrono::steady_clock::now() + after);
            },
            Qt::BlockingQueuedConnection);
    }

private:
    QThread m_thread;
    InProcessPort *m_port = nullptr;
    bool m_opened = false;
    std::atomic<qint32> m_heardBaud {0};
    std::atomic<int> m_heardBytes {0};
};

} // namespace

class TestInProcessTransport : public QObject
{
    Q_OBJECT

private slots:
    void bytesGoToTheDeviceAtTheRateSetAndItsAnswerComesBack()
    {
        EchoDevice device(QStringLiteral("echo both ways"));
        QVERIFY(device.opened());
        InProcessTransport transport;
        QSignalSpy received(&transport, &InProcessTransport::received);
        QSignalSpy written(&transport, &InProcessTransport::bytesWritten);
        QString error;
        QVERIFY2(transport.open(device.name(), k1M, &error), qPrintable(error));
        QVERIFY(transport.isOpen());
        QCOMPARE(transport.portName(), device.name());
        QCOMPARE(transport.baudRate(), k1M);

        transport.write(QByteArrayLiteral("\x01\x02\x03"));
        // As from a serial port: the write is reported from the event loop, not inside it.
        QCOMPARE(written.size(), 0);
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x03\x02\x01"));
        QCOMPARE(written.size(), 1);
        QCOMPARE(written.at(0).at(0).toLongLong(), 3);
        QCOMPARE(device.heardBaud(), k1M);

        // Each byte is heard at the rate it was sent at.
        QVERIFY(transport.setBaudRate(k500k));
        QCOMPARE(transport.baudRate(), k500k);
        transport.write(QByteArrayLiteral("\x0A\x0B"));
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x03\x02\x01\x0B\x0A"));
        QCOMPARE(device.heardBaud(), k500k);
        QVERIFY(!transport.setBaudRate(0));
    }

    void inputWaitingIsDeliveredOrDiscardedOnRequest()
    {
        EchoDevice device(QStringLiteral("echo waiting"));
        InProcessTransport transport;
        QVERIFY(transport.open(device.name(), k1M, nullptr));
        QSignalSpy received(&transport, &InProcessTransport::received);
        // Sent and waiting for this thread: a timeout asks for it before giving up.
        device.send(QByteArrayLiteral("\x11\x22"));
        transport.deliverPendingInput();
        QCOMPARE(receivedBytes(received), QByteArrayLiteral("\x11\x22"));
        // Before a new request whatever waits is taken away, never delivered later.
        device.send(QByteArrayLiteral("\x33"));
        QCOMPARE(transport.discardInput(), QByteArrayLiteral("\x33"));
        device.send(QByteArrayLiteral("\x44"));
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x11\x22\x44"));
    }

    void bytesSentAheadArriveAtTheirTimeAndNotBefore()
    {
        EchoDevice device(QStringLiteral("echo ahead"));
        InProcessTransport transport;
        QVERIFY(transport.open(device.name(), k1M, nullptr));
        QSignalSpy received(&transport, &InProcessTransport::received);
        // Handed over together: the first is due at once, the second not for a minute.
        device.sendAhead(QByteArrayLiteral("\x0D"), std::chrono::minutes(1));
        device.sendAhead(QByteArrayLiteral("\x0C"), std::chrono::milliseconds(0));
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x0C"));
        transport.deliverPendingInput();
        QCOMPARE(transport.discardInput(), QByteArray());
        QCOMPARE(receivedBytes(received), QByteArrayLiteral("\x0C"));
        // Closed, the port drops what had not arrived yet.
        transport.close();
        QVERIFY(transport.open(device.name(), k1M, nullptr));
        transport.write(QByteArrayLiteral("\x01\x02"));
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x0C\x02\x01"));
    }

    void aClosedTransportNeitherSendsNorHears()
    {
        EchoDevice device(QStringLiteral("echo closed"));
        InProcessTransport transport;
        QVERIFY(transport.open(device.name(), k1M, nullptr));
        QTRY_VERIFY(device.hasHost());
        QSignalSpy received(&transport, &InProcessTransport::received);
        transport.close();
        QVERIFY(!transport.isOpen());
        QVERIFY(!device.hasHost());
        transport.write(QByteArrayLiteral("\x01"));
        device.send(QByteArrayLiteral("\x02"));
        // Opened again, it hears what is sent from then on, and only that.
        QVERIFY(transport.open(device.name(), k1M, nullptr));
        transport.write(QByteArrayLiteral("\x05\x06"));
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x06\x05"));
        QCOMPARE(device.heardBytes(), 2);
    }

    void aPortHasOneHostAtATime()
    {
        EchoDevice device(QStringLiteral("echo one host"));
        InProcessTransport first;
        InProcessTransport second;
        QVERIFY(first.open(device.name(), k1M, nullptr));
        QString error;
        QVERIFY(!second.open(device.name(), k1M, &error));
        QVERIFY(!second.isOpen());
        QVERIFY2(error.contains(device.name()), qPrintable(error));
        first.close();
        QVERIFY2(second.open(device.name(), k1M, &error), qPrintable(error));
    }

    void aNameTakenIsOfferedWithANumber()
    {
        EchoDevice device(QStringLiteral("echo twice"));
        EchoDevice other(QStringLiteral("echo twice"));
        QVERIFY(device.opened() && other.opened());
        QCOMPARE(device.name(), QStringLiteral("echo twice"));
        QVERIFY(other.name() != device.name());
        QVERIFY(other.name().startsWith(device.name()));
        QVERIFY(!InProcessPort().open(QString(), nullptr));
    }

    void onlyThePortsOfThisProgramOpenInProcess()
    {
        EchoDevice device(QStringLiteral("echo chosen"));
        std::unique_ptr<seriallink::PortTransport> inProcess(
            seriallink::PortTransport::forPort(device.name()));
        QVERIFY(qobject_cast<InProcessTransport *>(inProcess.get()));
        std::unique_ptr<seriallink::PortTransport> serial(
            seriallink::PortTransport::forPort(QStringLiteral("/dev/ttyNothing")));
        QVERIFY(qobject_cast<seriallink::SerialTransport *>(serial.get()));
        QString error;
        InProcessTransport never;
        QVERIFY(!never.open(QStringLiteral("never offered"), k1M, &error));
        QVERIFY2(error.contains(QStringLiteral("never offered")), qPrintable(error));
    }

    void aDeviceThatStopsIsAPortLostUntilItReturns()
    {
        EchoDevice device(QStringLiteral("echo stops"));
        const QString name = device.name();
        InProcessTransport transport;
        QSignalSpy failed(&transport, &InProcessTransport::failed);
        QVERIFY(transport.open(name, k1M, nullptr));
        device.stopOffering();
        QTRY_COMPARE(failed.size(), 1);
        QVERIFY(failed.at(0).at(0).toString().contains(name));
        QVERIFY(failed.at(0).at(1).toBool()); // lost: looked for again
        // Still a port of this program: it opens in process once it is back.
        QVERIFY(InProcessPort::isKnown(name));
        transport.close();
        QString error;
        QVERIFY(!transport.open(name, k1M, &error));
        QVERIFY2(error.contains(name), qPrintable(error));
        device.offerAgain(name);
        QVERIFY2(transport.open(name, k1M, &error), qPrintable(error));
        QSignalSpy received(&transport, &InProcessTransport::received);
        transport.write(QByteArrayLiteral("\x07\x08"));
        QTRY_COMPARE(receivedBytes(received), QByteArrayLiteral("\x08\x07"));
        QCOMPARE(failed.size(), 1);
    }

    // The bus client cannot tell the port from a pseudo-terminal's: it connects, scans at two
    // rates (the simulator answers only at a servo's own) and reads a servo.
    void aBusClientScansAndReadsSimulatedServosInProcess()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        sim::SimulatorOptions options = testsupport::feetechBusOptions(
            dir, QStringLiteral("bus"),
            {{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k500k}});
        options.inProcess = true;
        options.linkPath = QStringLiteral("Simulated test bus");
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options, &error), qPrintable(error));
        QCOMPARE(simulator.linkPath(), QStringLiteral("Simulated test bus"));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("bus"))));

        feetech::BusClient client(testsupport::patientTiming());
        const int index = testsupport::connectScanAndRead(client, simulator.linkPath(), 3, 1);
        QVERIFY(index >= 0);
        QCOMPARE(client.servos()->count(), 1);
        QSignalSpy finished(&client, &feetech::BusClient::scanFinished);
        feetech::ScanOptions options500k;
        options500k.lastId = 3;
        options500k.bauds = {k500k, k1M};
        client.scan(options500k);
        QVERIFY(finished.wait(20000));
        QVERIFY(client.servos()->indexOf({2, k500k}) >= 0);
        QVERIFY(client.servos()->indexOf({1, k1M}) >= 0);
        QCOMPARE(client.link()->counters().timeouts, 0);

        // The simulator stops: the link is lost, and comes back with it.
        simulator.stop();
        QTRY_COMPARE_WITH_TIMEOUT(client.link()->status().state, seriallink::ConnectionState::Lost,
                                  10000);
        QVERIFY2(simulator.start(options, &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(client.link()->status().state,
                                  seriallink::ConnectionState::Connected, 10000);
    }
};

QTEST_GUILESS_MAIN(TestInProcessTransport)
#include "tst_inprocesstransport.moc"
