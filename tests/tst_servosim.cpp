// Tests the servosim executable: ready line, link lifetime, signals and argument errors.
#include "simclient.h"
#include "specvectors.h"

#include "feetech/feetechpacket.h"

#include <QFileInfo>
#include <QProcess>
#include <QtTest>

#include <csignal>

namespace {

const QString kServosim = QStringLiteral(SERVOBENCH_BINARY_DIR "/app/servosim");

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
