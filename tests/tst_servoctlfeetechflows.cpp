// servoctl feetech against a simulated mixed bus over a pty: factory reset, middle calibration,
// reboot, unknown models, ping, trace, monitor and a missing port.
#include "servoctlfeetechbus.h"

using namespace servoctlfeetech;
using testsupport::runServoctl;

class TestServoctlFeetechFlows : public QObject, private ServoctlFeetechBus
{
    Q_OBJECT

private slots:
    void init() { start(); }
    void cleanup() { stop(); }

    void factoryResetSavesABackupFirst()
    {
        QCOMPARE(run(QStringLiteral("set --id 1 max_temperature=65")).exitCode, 0);
        const QString backup = m_dir.filePath(QStringLiteral("backup1.json"));
        const auto result = run(QStringLiteral("--json factory-reset --id 1 --backup ") + backup);
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(objectOf(result.out).value(QStringLiteral("backup")).toString(), backup);
        // The backup holds the values from before the reset; the servo has factory values.
        const auto saved = profile::load(
            backup, QStringLiteral("sts"),
            feetech::profileDefinitions(feetech::RegisterTable::forFamily(feetech::Family::Sts)));
        QVERIFY(saved);
        QCOMPARE(*saved->value(QStringLiteral("max_temperature")), qint64(65));
        QCOMPARE(servoValue(1, QStringLiteral("max_temperature")), 70);
        QCOMPARE(instructionsReceived().count(kRecovery), 1);
    }

    void factoryResetNamesItsBackupInTheCurrentFolder()
    {
        const QString folder = m_dir.filePath(QStringLiteral("cwd"));
        QVERIFY(QDir().mkpath(folder));
        const QString previous = QDir::currentPath();
        QVERIFY(QDir::setCurrent(folder));
        const auto result = run(QStringLiteral("factory-reset --id 2"));
        QVERIFY(QDir::setCurrent(previous));
        QCOMPARE(result.exitCode, 0);
        const QStringList backups =
            QDir(folder).entryList({QStringLiteral("servo-2-backup-*.json")}, QDir::Files);
        QCOMPARE(backups.size(), 1);
        QVERIFY(QRegularExpression(QStringLiteral("^servo-2-backup-\\d{8}-\\d{6}\\.json$"))
                    .match(backups.first())
                    .hasMatch());
        QVERIFY(result.out.contains(backups.first()));
    }

    void factoryResetWithoutABackupSendsNothing()
    {
        // A folder where the file should be: the backup cannot be written.
        const auto result = run(QStringLiteral("factory-reset --id 1 --backup ") + m_dir.path());
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QStringLiteral("backup")));
        QCOMPARE(instructionsReceived().count(kRecovery), 0);
        QCOMPARE(writesReceived(), 0);
    }

    void calibrateMiddleWhereTheServoSupportsIt()
    {
        m_simulator.call(
            [](sim::Simulator &s) { s.feetechBus()->findServo(1)->setPhysicalPosition(2548); });
        auto result = run(QStringLiteral("--json calibrate-middle --id 1"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY(objectOf(result.out).contains(QStringLiteral("position_offset")));
        QVERIFY(qAbs(servoValue(1, QStringLiteral("present_position")) - 2048) <= 2);
        result = run(QStringLiteral("calibrate-middle --id 3")); // SCS: no offset register
        QCOMPARE(result.exitCode, 1);
    }

    void rebootWaitsForTheServo()
    {
        const auto result = run(QStringLiteral("reboot --id 1"));
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(instructionsReceived().count(quint8(0x08)), 1);
    }

    void anUnknownModelIsReadRawAndNeverWritten()
    {
        setServoValue(1, QStringLiteral("model_major"), 77);
        auto result = run(QStringLiteral("--json read --id 1"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject read = objectOf(result.out);
        QVERIFY(read.value(QStringLiteral("servo"))[QStringLiteral("family")].isNull());
        QCOMPARE(read.value(QStringLiteral("registers")).toArray().size(),
                 feetech::RegisterTable::kRawViewSize);
        QCOMPARE(registerNamed(read, QStringLiteral("byte_003")).value(QStringLiteral("value")),
                 QJsonValue(77));
        result = run(QStringLiteral("set --id 1 max_temperature=60"));
        QCOMPARE(result.exitCode, 1);
        QCOMPARE(writesReceived(), 0);
    }

    void pingOfAMissingIdExitsOne()
    {
        const auto result = run(QStringLiteral("ping --id 7"));
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QStringLiteral("7")));
        QVERIFY(result.out.isEmpty());
    }

    void pingJsonReportsTheServoAndItsLatency()
    {
        const auto result = run(QStringLiteral("--json --baud 115200 ping --id 5"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject ping = objectOf(result.out);
        QCOMPARE(ping.value(QStringLiteral("servo"))[QStringLiteral("family")].toString(),
                 QStringLiteral("sms"));
        // The latency is the time beyond what the wire needs: a device that answers the moment
        // the request is complete (while an echo may still be expected) has none.
        QVERIFY(ping.contains(QStringLiteral("latency_us")));
        QVERIFY(ping.value(QStringLiteral("latency_us")).toInteger()
                >= (testsupport::instantTestDevice() ? 0 : 1));
    }

    void traceShowsEveryFrameOnStderr()
    {
        const auto result = run(QStringLiteral("--trace ping --id 1"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(result.err.contains(QStringLiteral("-> FF FF 01 02 01 FB")),
                 qPrintable(result.err));
        QVERIFY(result.err.contains(QStringLiteral("<- FF FF 01 02 00 FC")));
    }

    void monitorCsvParsesBackWithSamplesOfEveryServo()
    {
        setServoValue(2, QStringLiteral("torque_enable"), 1);
        setServoValue(2, QStringLiteral("goal_position"), 2500);
        const auto result =
            run(QStringLiteral("monitor --ids 1-3 --rate 100 --duration 0.6 --csv"));
        QCOMPARE(result.exitCode, 0);
        QString error;
        const auto samples = feetech::parseTelemetryCsv(result.out, &error);
        QVERIFY2(samples, qPrintable(error));
        QHash<int, QVector<feetech::CsvSample>> byServo;
        for (const feetech::CsvSample &sample : *samples)
            byServo[sample.id].append(sample);
        QCOMPARE(byServo.keys().size(), 3);
        for (const int id : {1, 2, 3}) {
            QVERIFY(byServo.value(id).size() >= 2); // a stream, however slow the machine
            QVERIFY(byServo.value(id).first().values.at(int(feetech::Quantity::Voltage)));
        }
        // Servo 2 was on its way to 2500.
        const auto &moving = byServo.value(2);
        QVERIFY(*moving.last().values.at(int(feetech::Quantity::Position))
                > *moving.first().values.at(int(feetech::Quantity::Position)));
        QVERIFY(moving.last().timeSeconds > moving.first().timeSeconds);
        // SYNC READ for the STS pair, one READ of the feedback block for the SCS.
        const QVector<quint8> instructions = instructionsReceived();
        QVERIFY(instructions.count(0x82) >= 2);
        QVERIFY(result.err.contains(QLatin1String("samples")));
    }

    void monitorJsonLinesCarryTheDecodedFields()
    {
        const auto result = run(QStringLiteral("monitor --ids 1,3 --duration 0.3"));
        QCOMPARE(result.exitCode, 0);
        const auto json =
            runServoctl(QStringList {QStringLiteral("--json")}
                        + feetech(QStringLiteral("monitor --ids 1,3 --duration 0.3").split(u' ')));
        QCOMPARE(json.exitCode, 0);
        const QStringList lines = json.out.split(u'\n', Qt::SkipEmptyParts);
        QVERIFY(lines.size() >= 2); // a sample of each servo at least, however slow the machine
        QSet<int> ids;
        for (const QString &line : lines) {
            const QJsonObject row = objectOf(line);
            ids.insert(row.value(QStringLiteral("id")).toInt());
            QVERIFY(row.contains(QStringLiteral("time_s")));
            QVERIFY(row.value(QStringLiteral("position")).isDouble());
            QCOMPARE(row.value(QStringLiteral("status_bits")).toString(), QStringLiteral("none"));
            // The SCS reports no current in mA: null, never a made-up number.
            if (row.value(QStringLiteral("id")).toInt() == 3)
                QVERIFY(row.value(QStringLiteral("current")).isNull());
        }
        QCOMPARE(ids, (QSet<int> {1, 3}));
    }

    void monitorOfAMissingServoExitsOneBeforeStreaming()
    {
        const auto result = run(QStringLiteral("monitor --ids 1,9 --duration 0.3 --csv"));
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QLatin1String("9")));
        QVERIFY(!instructionsReceived().contains(0x82));
    }

    void aMissingPortExitsOne()
    {
        const auto result =
            runServoctl({QStringLiteral("--port"), m_dir.filePath(QStringLiteral("absent")),
                         QStringLiteral("feetech"), QStringLiteral("ping"), QStringLiteral("--id"),
                         QStringLiteral("1")});
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QStringLiteral("does not exist")));
    }
};

QTEST_MAIN(TestServoctlFeetechFlows)
#include "tst_servoctlfeetechflows.moc"
