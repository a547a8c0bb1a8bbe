// Tests the servosim executable: ready line, link lifetime, signals, argument errors, a --robot
// arm answering a scan, --hand sweeps and commands on standard input.
#include "feetechbus.h"
#include "simclient.h"
#include "specvectors.h"

#include "feetechpacket.h"

#include <QFileInfo>
#include <QProcess>
#include <QtTest>

#include <csignal>

namespace {

const QString kServosim = QStringLiteral(SERVOBENCH_BINARY_DIR "/app/servosim");

// Sends one command line to servosim's standard input and returns its reply line (empty when
// none came within 5 s).
QString command(QProcess &process, const QByteArray &line)
{
    process.write(line + '\n');
    if (!QTest::qWaitFor([&] { return process.canReadLine(); }, 5000))
        return {};
    return QString::fromUtf8(process.readLine()).trimmed();
}

// Starts servosim with `arguments` and waits for its ready line.
bool startServosim(QProcess &process, const QStringList &arguments)
{
    process.start(kServosim, arguments);
    if (!process.waitForStarted() || !QTest::qWaitFor([&] { return process.canReadLine(); }, 5000))
        return false;
    return process.readLine().startsWith("ready ");
}

quint16 littleEndianWord(const QByteArray &bytes, int at)
{
    return quint16(quint8(bytes.at(at)) | (quint8(bytes.at(at + 1)) << 8));
}

} // namespace

class TestServosim : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY2(QFileInfo::exists(kServosim), qPrintable(kServosim));
    }

    void printsReadyServesTheLinkAndRemovesItOnSigterm()
    {
        const QString link = m_dir.filePath(QStringLiteral("ptk"));
        QProcess process;
        process.start(kServosim, {QStringLiteral("ptk"), QStringLiteral("--link"), link});
        QVERIFY(process.waitForStarted());
        QTRY_VERIFY(process.canReadLine());
        QCOMPARE(QString::fromUtf8(process.readLine()).trimmed(), QStringLiteral("ready ") + link);
        QVERIFY(QFileInfo(link).isSymLink());

        testsupport::PortClient client;
        QVERIFY(client.open(link, 115200));
        const auto &exchange = specvectors::kPtkExchanges[4];
        QCOMPARE(client.exchange(specvectors::bytes(exchange.query), 9),
                 specvectors::bytes(exchange.reply));
        client.close();

        ::kill(pid_t(process.processId()), SIGTERM);
        QVERIFY(process.waitForFinished(5000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 0);
        QVERIFY(!QFileInfo(link).isSymLink());
    }

    void aClientCanReopenTheLinkAfterClosingIt()
    {
        const QString link = m_dir.filePath(QStringLiteral("reopen"));
        QProcess process;
        process.start(kServosim, {QStringLiteral("ptk"), QStringLiteral("--link"), link});
        QTRY_VERIFY(process.canReadLine());
        for (int round = 0; round < 3; ++round) {
            testsupport::PortClient client;
            QVERIFY(client.open(link, 115200));
            const auto &exchange = specvectors::kPtkExchanges[std::size_t(round)];
            QCOMPARE(client.exchange(specvectors::bytes(exchange.query), 9),
                     specvectors::bytes(exchange.reply));
        }
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
    }

    void sighupPowerCyclesTheBusAndLockedEepromWritesAreLost()
    {
        const QString link = m_dir.filePath(QStringLiteral("hup"));
        QProcess process;
        process.start(kServosim,
                      {QStringLiteral("feetech"), QStringLiteral("--link"), link,
                       QStringLiteral("--servo"), QStringLiteral("1:STS3215")});
        QTRY_VERIFY(process.canReadLine());
        testsupport::PortClient client;
        QVERIFY(client.open(link, 1000000));
        // Max temperature (address 13): 70 at the factory; write 60 while locked.
        QCOMPARE(client.exchange(feetech::write(1, 13, QByteArray(1, char(60))), 6),
                 feetech::status(1, 0));
        QCOMPARE(client.exchange(feetech::read(1, 13, 1), 7),
                 feetech::status(1, 0, QByteArray(1, char(60))));
        ::kill(pid_t(process.processId()), SIGHUP);
        QVERIFY(QTest::qWaitFor(
            [&] {
                return client.exchange(feetech::read(1, 13, 1), 7)
                    == feetech::status(1, 0, QByteArray(1, char(70)));
            },
            5000));
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
    }

    void robotSo101AnswersAScanAtIds1To6WithTheTemplatesSettings()
    {
        const QString link = m_dir.filePath(QStringLiteral("so101"));
        QProcess process;
        QVERIFY(startServosim(process,
                              {QStringLiteral("feetech"), QStringLiteral("--link"), link,
                               QStringLiteral("--robot"), QStringLiteral("so101")}));
        feetech::BusClient client;
        const int gripper = testsupport::connectScanAndRead(client, link, 10, 6);
        QVERIFY(gripper >= 0);
        QCOMPARE(client.servos()->idsInUse(), (QVector<int> {1, 2, 3, 4, 5, 6}));
        QCOMPARE(client.servos()->at(gripper).info.model.name, QStringLiteral("STS3215"));
        model::ParameterModel *settings = client.servos()->parameters(gripper);
        QCOMPARE(settings->deviceValue(QStringLiteral("max_torque")), std::optional<qint64>(500));
        QCOMPARE(settings->deviceValue(QStringLiteral("p_gain")), std::optional<qint64>(16));
        QCOMPARE(settings->deviceValue(QStringLiteral("d_gain")), std::optional<qint64>(32));
        QCOMPARE(settings->deviceValue(QStringLiteral("torque_enable")), std::optional<qint64>(0));
        client.disconnectFrom();
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
    }

    void plugAndUnplugOnStandardInputAreSeenByASerialClient()
    {
        const QString link = m_dir.filePath(QStringLiteral("plug"));
        QProcess process;
        QVERIFY(startServosim(process,
                              {QStringLiteral("feetech"), QStringLiteral("--link"), link,
                               QStringLiteral("--servo"), QStringLiteral("1:STS3215")}));
        testsupport::PortClient client;
        QVERIFY(client.open(link, 1000000));
        QCOMPARE(client.exchange(feetech::ping(1), 6), feetech::status(1, 0));
        QVERIFY(client.exchange(feetech::ping(2), 6, 300).isEmpty());

        QCOMPARE(command(process, "plug 2:STS3215"),
                 QStringLiteral("ok plugged #2 (ID 2): STS3215 at 1000000 bps"));
        QCOMPARE(client.exchange(feetech::ping(2), 6), feetech::status(2, 0));
        const QString list = command(process, "list");
        QVERIFY2(list.startsWith(QLatin1String("ok #1 id=1 "))
                     && list.contains(QLatin1String("#2 id=2 ")),
                 qPrintable(list));

        QCOMPARE(command(process, "unplug 2"), QStringLiteral("ok unplugged #2 (ID 2)"));
        QVERIFY(client.exchange(feetech::ping(2), 6, 300).isEmpty());
        QVERIFY(command(process, "wiggle").startsWith(QLatin1String("error unknown command")));

        // The end of standard input is not the end of the simulator.
        process.closeWriteChannel();
        QCOMPARE(client.exchange(feetech::ping(1), 6), feetech::status(1, 0));
        QCOMPARE(process.state(), QProcess::Running);
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
        QCOMPARE(process.exitCode(), 0);
    }

    void handOptionSweepsAJointTheClientSeesMove()
    {
        const QString link = m_dir.filePath(QStringLiteral("hand"));
        QProcess process;
        QVERIFY(startServosim(process,
                              {QStringLiteral("feetech"), QStringLiteral("--link"), link,
                               QStringLiteral("--servo"), QStringLiteral("1:STS3215"),
                               QStringLiteral("--hand"), QStringLiteral("1:1000:3000:1")}));
        testsupport::PortClient client;
        QVERIFY(client.open(link, 1000000));
        // Present position, address 56: it goes up past 2500 and comes back under 1500.
        const auto position = [&] {
            const QByteArray reply = client.exchange(feetech::read(1, 56, 2), 8);
            return reply.size() >= 8 ? int(littleEndianWord(reply, 5)) : -1;
        };
        QVERIFY(QTest::qWaitFor([&] { return position() > 2500; }, 5000));
        QVERIFY(QTest::qWaitFor([&] { return position() < 1500 && position() >= 1000; }, 5000));
        QCOMPARE(command(process, "release"), QStringLiteral("ok the hand let go of 1 sweep(s)"));
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
    }

    void twoServosShareAnIdOnlyWhenAllowed()
    {
        const QString link = m_dir.filePath(QStringLiteral("twins"));
        const QStringList twins {
            QStringLiteral("feetech"),  QStringLiteral("--link"),    link,
            QStringLiteral("--servo"),  QStringLiteral("1:STS3215"), QStringLiteral("--servo"),
            QStringLiteral("1:STS3215")};
        QProcess refused;
        refused.start(kServosim, twins);
        QVERIFY(refused.waitForFinished(5000));
        QCOMPARE(refused.exitCode(), 2);
        QVERIFY(refused.readAllStandardError().contains("--allow-shared-ids"));

        QProcess process;
        QVERIFY(startServosim(process, twins + QStringList {QStringLiteral("--allow-shared-ids")}));
        const QString list = command(process, "list");
        QVERIFY2(list.contains(QLatin1String("#1 id=1 "))
                     && list.contains(QLatin1String("#2 id=1 ")),
                 qPrintable(list));
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
    }

    void commandOptionsPlayBenchCasesBeforeReady()
    {
        const QString link = m_dir.filePath(QStringLiteral("cases"));
        QProcess process;
        QVERIFY(startServosim(process,
                              {QStringLiteral("feetech"), QStringLiteral("--link"), link,
                               QStringLiteral("--robot"), QStringLiteral("so101"),
                               QStringLiteral("--command"), QStringLiteral("break-chain 2"),
                               QStringLiteral("--command"), QStringLiteral("supply 12.6")}));
        testsupport::PortClient client;
        QVERIFY(client.open(link, 1000000));
        // ID 2 answers, with the voltage bit of its status set: 12.6 V is over its limit.
        QCOMPARE(client.exchange(feetech::ping(2), 6), feetech::status(2, 0x01));
        QVERIFY(client.exchange(feetech::ping(3), 6, 300).isEmpty());
        const QString list = command(process, "list");
        QCOMPARE(list.count(QLatin1String("power=off")), 4);
        QCOMPARE(list.count(QLatin1String("supply=12.6")), 6);
        process.terminate();
        QVERIFY(process.waitForFinished(5000));
    }

    void badArgumentsExitTwoWithAMessage_data()
    {
        QTest::addColumn<QStringList>("arguments");
        const QString link = m_dir.filePath(QStringLiteral("bad"));
        const QString l = QStringLiteral("--link");
        QTest::newRow("no protocol") << QStringList {};
        QTest::newRow("unknown protocol") << QStringList {QStringLiteral("dxl"), l, link};
        QTest::newRow("no link") << QStringList {QStringLiteral("ptk")};
        QTest::newRow("unknown option")
            << QStringList {QStringLiteral("ptk"), l, link, QStringLiteral("--fast")};
        QTest::newRow("bad fault") << QStringList {
            QStringLiteral("ptk"), l, link, QStringLiteral("--faults"), QStringLiteral("drop=2")};
        QTest::newRow("bad value") << QStringList {
            QStringLiteral("ptk"), l, link, QStringLiteral("--values"), QStringLiteral("gain=99")};
        QTest::newRow("no servo") << QStringList {QStringLiteral("feetech"), l, link};
        QTest::newRow("unknown model")
            << QStringList {QStringLiteral("feetech"), l, link, QStringLiteral("--servo"),
                            QStringLiteral("1:XYZ99")};
        QTest::newRow("id over 253")
            << QStringList {QStringLiteral("feetech"), l, link, QStringLiteral("--servo"),
                            QStringLiteral("254:STS3215")};
        QTest::newRow("duplicate id") << QStringList {QStringLiteral("feetech"),
                                                      l,
                                                      link,
                                                      QStringLiteral("--servo"),
                                                      QStringLiteral("1:STS3215"),
                                                      QStringLiteral("--servo"),
                                                      QStringLiteral("1:SCS15")};
        QTest::newRow("bad baud") << QStringList {QStringLiteral("feetech"), l, link,
                                                  QStringLiteral("--servo"),
                                                  QStringLiteral("1:STS3215@12345")};
        QTest::newRow("unknown robot") << QStringList {
            QStringLiteral("feetech"), l, link, QStringLiteral("--robot"), QStringLiteral("koch")};
        QTest::newRow("bad hand") << QStringList {QStringLiteral("feetech"),
                                                  l,
                                                  link,
                                                  QStringLiteral("--robot"),
                                                  QStringLiteral("so101"),
                                                  QStringLiteral("--hand"),
                                                  QStringLiteral("1:0:9999:1")};
        QTest::newRow("hand on a missing id") << QStringList {QStringLiteral("feetech"),
                                                              l,
                                                              link,
                                                              QStringLiteral("--robot"),
                                                              QStringLiteral("so101"),
                                                              QStringLiteral("--hand"),
                                                              QStringLiteral("9:0:100:1")};
        QTest::newRow("bad command") << QStringList {QStringLiteral("feetech"),
                                                     l,
                                                     link,
                                                     QStringLiteral("--robot"),
                                                     QStringLiteral("so101"),
                                                     QStringLiteral("--command"),
                                                     QStringLiteral("supply 99")};
    }
    void badArgumentsExitTwoWithAMessage()
    {
        QFETCH(QStringList, arguments);
        QProcess process;
        process.start(kServosim, arguments);
        QVERIFY(process.waitForFinished(5000));
        QCOMPARE(process.exitCode(), 2);
        QVERIFY(process.readAllStandardError().startsWith("servosim: "));
        QVERIFY(process.readAllStandardOutput().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestServosim)
#include "tst_servosim.moc"
