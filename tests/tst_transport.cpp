// Tests of the serial transport on a simulator's pty, and of its table of port error messages.
#include "feetechbus.h"

#include "serialtransport.h"

#include <QSignalSpy>
#include <QtTest>

using seriallink::SerialTransport;

namespace {

constexpr qint32 k1M = 1000000;

// Every byte a transport delivers, in order.
QByteArray receivedBytes(const QSignalSpy &spy)
{
    QByteArray bytes;
    for (const QList<QVariant> &arguments : spy)
        bytes += arguments.at(0).toByteArray();
    return bytes;
}

} // namespace

class TestTransport : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    const QByteArray m_reply = feetech::status(1, 0);

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
    }

    void cleanup() { m_simulator.reset(); }

    void openAndCloseThePort()
    {
        SerialTransport transport;
        QString error;
        QVERIFY2(transport.open(m_simulator->linkPath(), k1M, &error), qPrintable(error));
        QVERIFY(transport.isOpen());
        QCOMPARE(transport.baudRate(), k1M);
        QCOMPARE(transport.portName(), m_simulator->linkPath());
        transport.close();
        QVERIFY(!transport.isOpen());
        // Closed means released: the port opens again (QSerialPort holds it exclusively).
        QVERIFY2(transport.open(m_simulator->linkPath(), k1M, &error), qPrintable(error));
    }

    void openingAMissingPathSaysWhichPortIsMissing()
    {
        SerialTransport transport;
        const QString missing = m_dir.filePath(QStringLiteral("ttyNothing"));
        QString error;
        QVERIFY(!transport.open(missing, k1M, &error));
        QVERIFY(!transport.isOpen());
        QCOMPARE(error,
                 seriallink::portErrorMessage(QSerialPort::DeviceNotFoundError, missing, {}));
    }

    void writtenBytesAreAnsweredAndTheAnswerIsReceived()
    {
        SerialTransport transport;
        QVERIFY(transport.open(m_simulator->linkPath(), k1M, nullptr));
        QSignalSpy written(&transport, &SerialTransport::bytesWritten);
        QSignalSpy received(&transport, &SerialTransport::received);
        QSignalSpy failed(&transport, &SerialTransport::failed);
        const QByteArray request = feetech::ping(1);
        transport.write(request);
        QTRY_COMPARE_WITH_TIMEOUT(receivedBytes(received), m_reply, 10000);
        qint64 total = 0;
        for (const QList<QVariant> &arguments : written)
            total += arguments.at(0).toLongLong();
        QCOMPARE(total, qint64(request.size()));
        QVERIFY(failed.isEmpty());
        QCOMPARE(testsupport::feetechFramesReceived(logPath()), QVector<QByteArray> {request});
    }

    void setBaudRateChangesTheRateTheFarSideSees()
    {
        SerialTransport transport;
        QVERIFY(transport.open(m_simulator->linkPath(), k1M, nullptr));
        QVERIFY(transport.setBaudRate(500000));
        QCOMPARE(transport.baudRate(), 500000);
        // The servo listens at 1 Mbps only: at 500 kbps a PING goes unanswered, back at 1 Mbps
        // it is answered.
        QSignalSpy received(&transport, &SerialTransport::received);
        transport.write(feetech::ping(1));
        QTRY_COMPARE_WITH_TIMEOUT(testsupport::feetechFramesReceived(logPath()).size(), 1, 10000);
        QVERIFY(transport.setBaudRate(k1M));
        transport.write(feetech::ping(1));
        QTRY_COMPARE_WITH_TIMEOUT(receivedBytes(received), m_reply, 10000);
        // The simulator logs a reply once it has handed it over: the log may come a moment later.
        QTRY_COMPARE_WITH_TIMEOUT(
            testsupport::logLinesStartingWith(logPath(), QStringLiteral("out ")).size(), 1, 10000);
    }

    void discardInputNeverCostsTheBytesStillOnTheirWay()
    {
        SerialTransport transport;
        QVERIFY(transport.open(m_simulator->linkPath(), k1M, nullptr));
        QSignalSpy written(&transport, &SerialTransport::bytesWritten);
        QSignalSpy received(&transport, &SerialTransport::received);
        QSignalSpy failed(&transport, &SerialTransport::failed);
        transport.write(feetech::ping(1));
        QVERIFY(written.wait(10000));
        // No event processing from here until the simulator has sent its reply: the bytes then
        // wait in the kernel, unannounced, when a new request discards the input.
        QDeadlineTimer deadline(10000);
        while (testsupport::framesLogged(logPath(), QStringLiteral("out")).isEmpty()
               && !deadline.hasExpired())
            QThread::yieldCurrentThread();
        const QByteArray discarded = transport.discardInput();
        // They are not flushed (an empty read would then look like a lost device): what the
        // discard could not see arrives with the next read.
        QTRY_COMPARE_WITH_TIMEOUT(discarded + receivedBytes(received), m_reply, 10000);
        QVERIFY(failed.isEmpty());
        QVERIFY(transport.isOpen());
    }

    void deliverPendingInputHandsOverWhatHasArrivedWithoutTheEventLoop()
    {
        SerialTransport transport;
        QVERIFY(transport.open(m_simulator->linkPath(), k1M, nullptr));
        QSignalSpy written(&transport, &SerialTransport::bytesWritten);
        QSignalSpy received(&transport, &SerialTransport::received);
        transport.write(feetech::ping(1));
        QVERIFY(written.wait(10000));
        // No event processing from here: only the explicit look delivers the reply.
        QDeadlineTimer deadline(10000);
        while (receivedBytes(received) != m_reply && !deadline.hasExpired()) {
            QThread::yieldCurrentThread();
            transport.deliverPendingInput();
        }
        QCOMPARE(receivedBytes(received), m_reply);
    }

    void aVanishingFarSideIsReportedAsLost()
    {
        SerialTransport transport;
        QVERIFY(transport.open(m_simulator->linkPath(), k1M, nullptr));
        QSignalSpy failed(&transport, &SerialTransport::failed);
        m_simulator.reset();
        QTRY_VERIFY_WITH_TIMEOUT(!failed.isEmpty(), 10000);
        const QString message = failed.first().at(0).toString();
        QVERIFY2(message.contains(transport.portName()), qPrintable(message));
        QCOMPARE(failed.first().at(1).toBool(), true);
    }

    void everyPortErrorIsOneSentenceNamingThePort_data()
    {
        QTest::addColumn<QSerialPort::SerialPortError>("error");
        QTest::newRow("not found") << QSerialPort::DeviceNotFoundError;
        QTest::newRow("permission") << QSerialPort::PermissionError;
        QTest::newRow("open") << QSerialPort::OpenError;
        QTest::newRow("not open") << QSerialPort::NotOpenError;
        QTest::newRow("write") << QSerialPort::WriteError;
        QTest::newRow("read") << QSerialPort::ReadError;
        QTest::newRow("resource") << QSerialPort::ResourceError;
        QTest::newRow("unsupported") << QSerialPort::UnsupportedOperationError;
        QTest::newRow("timeout") << QSerialPort::TimeoutError;
        QTest::newRow("unknown") << QSerialPort::UnknownError;
    }

    void everyPortErrorIsOneSentenceNamingThePort()
    {
        QFETCH(QSerialPort::SerialPortError, error);
        const QString port = QStringLiteral("/dev/ttyUSB7");
        const QString message =
            seriallink::portErrorMessage(error, port, QStringLiteral("Input/output error"));
        QVERIFY2(message.contains(port), qPrintable(message));
        QVERIFY2(!message.contains(u'\n'), qPrintable(message));
        // Each error its own words.
        QSet<QString> others;
        for (const auto other : {QSerialPort::DeviceNotFoundError, QSerialPort::PermissionError,
                                 QSerialPort::OpenError, QSerialPort::NotOpenError,
                                 QSerialPort::WriteError, QSerialPort::ReadError,
                                 QSerialPort::ResourceError, QSerialPort::UnsupportedOperationError,
                                 QSerialPort::TimeoutError, QSerialPort::UnknownError}) {
            if (other != error)
                others.insert(seriallink::portErrorMessage(other, port, {}));
        }
        QVERIFY(!others.contains(seriallink::portErrorMessage(error, port, {})));
    }

    void noErrorHasNoMessage()
    {
        QVERIFY(seriallink::portErrorMessage(QSerialPort::NoError, QStringLiteral("/dev/ttyS0"), {})
                    .isEmpty());
    }

    void onlyErrorsOfAVanishedDeviceCountAsLost_data()
    {
        QTest::addColumn<QSerialPort::SerialPortError>("error");
        QTest::addColumn<bool>("lost");
        QTest::newRow("resource") << QSerialPort::ResourceError << true;
        QTest::newRow("not found") << QSerialPort::DeviceNotFoundError << true;
        QTest::newRow("read") << QSerialPort::ReadError << true;
        QTest::newRow("write") << QSerialPort::WriteError << true;
        QTest::newRow("permission") << QSerialPort::PermissionError << false;
        QTest::newRow("open") << QSerialPort::OpenError << false;
        QTest::newRow("unsupported") << QSerialPort::UnsupportedOperationError << false;
        QTest::newRow("timeout") << QSerialPort::TimeoutError << false;
        QTest::newRow("unknown") << QSerialPort::UnknownError << false;
    }

    void onlyErrorsOfAVanishedDeviceCountAsLost()
    {
        QFETCH(QSerialPort::SerialPortError, error);
        QFETCH(bool, lost);
        QCOMPARE(seriallink::isLostError(error), lost);
    }
};

QTEST_GUILESS_MAIN(TestTransport)
#include "tst_transport.moc"
