// End to end over a real pty: the simulated PTK servo as a QSerialPort client sees it.
#include "simclient.h"
#include "specvectors.h"

#include "ptkframe.h"
#include "ptkparameters.h"
#include "simulatorthread.h"
#include "virtualptkservo.h"

#include <QtTest>

using specvectors::bytes;
using testsupport::PortClient;

class TestSimulatorPtk : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    sim::SimulatorOptions options(const QString &name)
    {
        return testsupport::ptkOptions(m_dir, name);
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void everyQueryGetsTheSeedsReplyBytes()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(options(QStringLiteral("queries")), 115200),
                 qPrintable(simulator.error));
        PortClient &client = simulator.client;
        for (const auto &exchange : specvectors::kPtkExchanges) {
            const QByteArray reply = client.exchange(bytes(exchange.query), ptk::kReplySize);
            QCOMPARE(reply, bytes(exchange.reply));
        }
    }

    void aLostRequestIsNeverHeardUntilTheFaultsAreCleared()
    {
        auto opts = options(QStringLiteral("lost"));
        sim::OptionError error;
        const auto lost = sim::FaultSettings::parse(QStringLiteral("lost=1"), &error);
        QVERIFY2(lost && lost->any(), qPrintable(error.describe()));
        opts.faults = *lost;
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(opts, 115200), qPrintable(simulator.error));
        const QByteArray query = bytes(specvectors::kPtkExchanges[0].query);
        QVERIFY(simulator.client.exchange(query, ptk::kReplySize, 300).isEmpty());
        QTRY_COMPARE(testsupport::logLinesStartingWith(opts.logPath, QStringLiteral("lost")).size(),
                     1);
        simulator.simulator.call([](sim::Simulator &running) { running.setFaults({}, 1); });
        QCOMPARE(simulator.client.exchange(query, ptk::kReplySize),
                 bytes(specvectors::kPtkExchanges[0].reply));
    }

    void aWriteIsNeverAnsweredAndTheNextReadShowsTheNewValue()
    {
        sim::SimulatorThread simulator;
        QString error;
        const auto opts = options(QStringLiteral("write"));
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        PortClient client;
        QVERIFY(client.open(simulator.linkPath(), 115200));
        // gain 20 (N1 write), then the gain/damping query (N2).
        const QByteArray write = ptk::encodeRequest({1, 20, 0});
        const QByteArray reply = client.exchange(write + ptk::encodeQuery(61), ptk::kReplySize);
        QCOMPARE(reply.size(), ptk::kReplySize); // the write got no reply of its own
        const auto decoded = ptk::decodeReply(reply);
        QVERIFY(decoded.has_value());
        QCOMPARE(decoded->word0, quint16(20));
        QCOMPARE(decoded->word1, quint16(12));
        QTRY_COMPARE(testsupport::logLinesStartingWith(opts.logPath, QStringLiteral("out")).size(),
                     1);
    }

    void echoModeSendsTheHostsBytesBackBeforeTheReply()
    {
        auto opts = options(QStringLiteral("echo"));
        opts.echo = true;
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(opts, 115200), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        const auto &exchange = specvectors::kPtkExchanges[0];
        const QByteArray received = client.exchange(bytes(exchange.query), 19);
        QCOMPARE(received, bytes(exchange.query) + bytes(exchange.reply));
    }

    void aHostAtTheWrongBaudGetsSilence()
    {
        auto opts = options(QStringLiteral("baud"));
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(opts, 57600), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        client.send(bytes(specvectors::kPtkExchanges[0].query));
        // Once the simulator has logged the frame, it has decided; then ask at the right rate.
        QTRY_COMPARE(testsupport::logLinesStartingWith(opts.logPath, QStringLiteral("in")).size(),
                     1);
        QVERIFY(client.setBaud(115200));
        const auto &exchange = specvectors::kPtkExchanges[1];
        const QByteArray received = client.exchange(bytes(exchange.query), ptk::kReplySize);
        QCOMPARE(received, bytes(exchange.reply)); // nothing came for the first query
        QCOMPARE(testsupport::logLinesStartingWith(opts.logPath, QStringLiteral("out")).size(), 1);
    }

    void badChecksumsAndUnknownCommandsAreIgnored()
    {
        auto opts = options(QStringLiteral("ignored"));
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(opts, 115200), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        QByteArray corrupted = bytes(specvectors::kPtkExchanges[0].query);
        corrupted[9] = char(corrupted[9] + 1);
        const QByteArray unknown = ptk::encodeQuery(0x99);
        const QByteArray good = bytes(specvectors::kPtkExchanges[2].query);
        const QByteArray received = client.exchange(corrupted + unknown + good, ptk::kReplySize);
        QCOMPARE(received, bytes(specvectors::kPtkExchanges[2].reply));
        QTRY_COMPARE(testsupport::logLinesStartingWith(opts.logPath, QStringLiteral("out")).size(),
                     1);
    }

    void startingValuesCanBeGiven()
    {
        auto opts = options(QStringLiteral("values"));
        opts.ptkValues = QStringLiteral("gain=7,min_pulse_us=900");
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(opts, 115200), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        const auto gain = ptk::decodeReply(client.exchange(ptk::encodeQuery(61), ptk::kReplySize));
        QVERIFY(gain.has_value());
        QCOMPARE(gain->word0, quint16(7));
        const auto pulses =
            ptk::decodeReply(client.exchange(ptk::encodeQuery(80), ptk::kReplySize));
        QVERIFY(pulses.has_value());
        QCOMPARE(pulses->word0, quint16(3600));
    }

    void badStartingValuesAreRefused()
    {
        auto opts = options(QStringLiteral("badvalues"));
        opts.ptkValues = QStringLiteral("gain=99");
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY(!simulator.start(opts, &error));
        QVERIFY(error.contains(QStringLiteral("gain")));
    }

    void theSameFaultSeedGivesTheSameByteStreamTwice()
    {
        const auto stream = [&](const QString &name, quint32 seed) {
            auto opts = options(name);
            opts.faults = *sim::FaultSettings::parse(
                QStringLiteral("drop=0.2,corrupt=0.2,truncate=0.1,noise=0.1,delay=3"), nullptr);
            QString error;
            opts.seed = seed;
            sim::SimulatorThread simulator;
            if (!simulator.start(opts, &error))
                return QByteArray("start failed");
            PortClient client;
            if (!client.open(simulator.linkPath(), 115200))
                return QByteArray("open failed");
            QByteArray queries;
            for (int round = 0; round < 5; ++round) {
                for (const auto &exchange : specvectors::kPtkExchanges)
                    queries += bytes(exchange.query);
            }
            client.send(queries);
            // Every query ends in one "out" or one "drop" line; wait for all forty.
            const bool done = QTest::qWaitFor(
                [&] {
                    const QStringList lines = testsupport::logLines(opts.logPath);
                    return lines.filter(QRegularExpression(QStringLiteral("^(out|drop) "))).size()
                        == 40;
                },
                10000);
            if (!done)
                return QByteArray("not all replies");
            // Then wait for exactly the bytes the log says went out.
            int sent = 0;
            for (const QString &line :
                 testsupport::logLinesStartingWith(opts.logPath, QStringLiteral("out ")))
                sent +=
                    line.section(QStringLiteral("  #"), 0, 0).split(u' ', Qt::SkipEmptyParts).size()
                    - 1;
            if (!client.waitFor(sent, 5000))
                return QByteArray("bytes missing");
            return client.received();
        };
        const QByteArray first = stream(QStringLiteral("seedA"), 42);
        const QByteArray second = stream(QStringLiteral("seedB"), 42);
        const QByteArray other = stream(QStringLiteral("seedC"), 43);
        QVERIFY(first.size() > 100);
        QCOMPARE(first, second);
        QVERIFY(first != other);
    }
};

QTEST_GUILESS_MAIN(TestSimulatorPtk)
#include "tst_simulatorptk.moc"
