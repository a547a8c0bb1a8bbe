// servoctl feetech against a simulated mixed bus over a pty: scan, read, get, set, IDs, rates
// and profiles; output, JSON, exit codes, and that refused commands write nothing.
#include "hostilefiles.h"
#include "samplefiles.h"
#include "servoctlfeetechbus.h"

using namespace servoctlfeetech;
using testsupport::runServoctl;

class TestServoctlFeetech : public QObject, private ServoctlFeetechBus
{
    Q_OBJECT

private slots:
    void init() { start(); }
    void cleanup() { stop(); }

    void scanJsonListsTheServosAtTheBaudWithTheirIdentity()
    {
        const auto result = run(QStringLiteral("--json scan --ids 0-10"));
        QCOMPARE(result.exitCode, 0);
        const QJsonArray servos = QJsonDocument::fromJson(result.out.toUtf8()).array();
        QCOMPARE(servos.size(), 3);
        for (int i = 0; i < 3; ++i) // by ID, however late one answered
            QCOMPARE(servos.at(i)[QStringLiteral("id")].toInt(), i + 1);
        const QJsonObject sts = byId(servos, 1);
        QCOMPARE(sts.value(QStringLiteral("baud")).toInt(), k1M);
        QCOMPARE(sts.value(QStringLiteral("model")).toString(), QStringLiteral("STS3215"));
        QCOMPARE(sts.value(QStringLiteral("model_number")).toInt(), 777);
        QCOMPARE(sts.value(QStringLiteral("family")).toString(), QStringLiteral("sts"));
        QCOMPARE(sts.value(QStringLiteral("firmware")).toString(), QStringLiteral("3.10"));
        QVERIFY(!byId(servos, 2).isEmpty());
        const QJsonObject scs = byId(servos, 3);
        QCOMPARE(scs.value(QStringLiteral("model")).toString(), QStringLiteral("SCS15"));
        QCOMPARE(scs.value(QStringLiteral("model_number")).toInt(), 0x050F);
        QCOMPARE(scs.value(QStringLiteral("family")).toString(), QStringLiteral("scs"));
        QVERIFY(byId(servos, 5).isEmpty()); // at 115200, not scanned
    }

    void scanTextCoversEveryIdByDefault()
    {
        const auto result = run(QStringLiteral("scan"));
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QStringList lines = result.out.trimmed().split(u'\n');
        QCOMPARE(lines.size(), 1 + 3); // header and one row per servo
        // Rows come as servos are found: one asked again after a late answer comes later.
        QCOMPARE(lines.mid(1).filter(QStringLiteral("STS3215")).size(), 2);
        QCOMPARE(lines.mid(1).filter(QStringLiteral("SCS15")).size(), 1);
        // Every unicast ID was asked at 1 Mbps, the last one too (again, if bytes that named
        // no one came just after its wait: the scan then looks once more).
        QVERIFY(!framesReceived().filter(QStringLiteral("FF FF FD 02 01")).isEmpty());
    }

    void scanOfAllBaudRatesFindsTheSmsAt115200()
    {
        const auto result = run(QStringLiteral("--json --baud all scan --ids 0-10"));
        QCOMPARE(result.exitCode, 0);
        const QJsonArray servos = QJsonDocument::fromJson(result.out.toUtf8()).array();
        QCOMPARE(servos.size(), 4);
        const QJsonObject sms = byId(servos, 5);
        QCOMPARE(sms.value(QStringLiteral("baud")).toInt(), k115k);
        QCOMPARE(sms.value(QStringLiteral("family")).toString(), QStringLiteral("sms"));
    }

    void aScanFindsServosWhoseAnswersCarryTheVoltageBitAndShowsIt()
    {
        // A 12.6 V supply on 7.4 V servos: each STS answers a PING with the PING's very bytes.
        setSupplyVoltage(12.6);
        const auto json = run(QStringLiteral("--json --trace scan --ids 0-10"));
        const QJsonArray servos = QJsonDocument::fromJson(json.out.toUtf8()).array();
        QVERIFY2(servos.size() == 3, qPrintable(json.err));
        for (const int id : {1, 2}) {
            const QJsonObject sts = byId(servos, id);
            QCOMPARE(sts.value(QStringLiteral("error_bits")).toInt() & 0x01, 0x01);
            QVERIFY(
                sts.value(QStringLiteral("errors")).toArray().contains(QStringLiteral("voltage")));
            QCOMPARE(sts.value(QStringLiteral("shared_id")).toBool(), false);
        }
        QCOMPARE(json.exitCode, 0);
        const auto text = run(QStringLiteral("scan --ids 0-10"));
        QVERIFY2(
            text.out.contains(QStringLiteral("servo 1 answers with error bits 0x01 (voltage)")),
            qPrintable(text.out));
    }

    void aScanSaysWhenTwoServosAnswerAtOneIdAndNothingIsWrittenThere()
    {
        restart({{1, QStringLiteral("STS3215"), k1M},
                 {4, QStringLiteral("STS3215"), k1M},
                 {4, QStringLiteral("STS3215"), k1M}},
                true);
        const auto json = run(QStringLiteral("--json --trace scan --ids 0-10"));
        QCOMPARE(json.exitCode, 1);
        const QJsonArray servos = QJsonDocument::fromJson(json.out.toUtf8()).array();
        QVERIFY2(servos.size() == 2, qPrintable(json.err));
        QCOMPARE(byId(servos, 4).value(QStringLiteral("shared_id")).toBool(), true);
        QCOMPARE(byId(servos, 1).value(QStringLiteral("shared_id")).toBool(), false);
        QVERIFY2(json.err.contains(QStringLiteral("ID 4")), qPrintable(json.err));
        const auto text = run(QStringLiteral("scan --ids 0-10"));
        QVERIFY2(text.out.contains(QStringLiteral("Two or more servos answer at ID 4")),
                 qPrintable(text.out));
        const int writesBefore = writesReceived();
        const auto set = run(QStringLiteral("set --id 4 max_temperature=70"));
        QCOMPARE(set.exitCode, 1);
        QVERIFY2(set.err.contains(QStringLiteral("nothing is written")), qPrintable(set.err));
        QCOMPARE(writesReceived(), writesBefore);
        // Both would take a new ID: refused too, as every command that sends to the servo.
        const auto setId = run(QStringLiteral("set-id --id 4 9"));
        QCOMPARE(setId.exitCode, 1);
        QVERIFY2(setId.err.contains(QStringLiteral("nothing is written")), qPrintable(setId.err));
        QCOMPARE(writesReceived(), writesBefore);
        QVERIFY(run(QStringLiteral("set --id 1 max_temperature=70")).exitCode == 0);
    }

    void aScanThatFindsNothingExitsOne()
    {
        const auto result = run(QStringLiteral("--json scan --ids 20-30"));
        QCOMPARE(result.exitCode, 1);
        QCOMPARE(QJsonDocument::fromJson(result.out.toUtf8()).array().size(), 0);
        QVERIFY(!result.err.isEmpty());
    }

    void readJsonDecodesSignedAndBigEndianValues()
    {
        setServoValue(1, QStringLiteral("position_offset"), -100);
        setServoValue(3, QStringLiteral("max_angle_limit"), 1000);
        auto result = run(QStringLiteral("--json read --id 1"));
        QCOMPARE(result.exitCode, 0);
        QJsonObject read = objectOf(result.out);
        QCOMPARE(read.value(QStringLiteral("servo"))[QStringLiteral("id")].toInt(), 1);
        QCOMPARE(read.value(QStringLiteral("servo"))[QStringLiteral("family")].toString(),
                 QStringLiteral("sts"));
        QCOMPARE(read.value(QStringLiteral("registers")).toArray().size(),
                 feetech::RegisterTable::forFamily(feetech::Family::Sts).registers().size());
        const QJsonObject offset = registerNamed(read, QStringLiteral("position_offset"));
        QCOMPARE(offset.value(QStringLiteral("address")).toInt(), 31);
        QCOMPARE(offset.value(QStringLiteral("size")).toInt(), 2);
        QCOMPARE(offset.value(QStringLiteral("value")).toInt(), -100);
        QCOMPARE(offset.value(QStringLiteral("raw")).toInt(), 0x800 | 100); // sign bit 11

        result = run(QStringLiteral("--json read --id 3"));
        QCOMPARE(result.exitCode, 0);
        read = objectOf(result.out);
        const QJsonObject limit = registerNamed(read, QStringLiteral("max_angle_limit"));
        QCOMPARE(limit.value(QStringLiteral("value")).toInt(), 1000);
        QCOMPARE(limit.value(QStringLiteral("raw")).toInt(), 1000);
    }

    void readTextIsATableWithUnits()
    {
        setServoValue(1, QStringLiteral("position_offset"), -100);
        const auto result = run(QStringLiteral("read --id 1"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY(result.out.startsWith(QStringLiteral("servo 1 at 1000000 bps: STS3215")));
        QVERIFY2(result.out.contains(QRegularExpression(
                     QStringLiteral("\n  31  position_offset {15}  -100  -100 step\n"))),
                 qPrintable(result.out));
        QVERIFY(result.out.contains(QRegularExpression(QStringLiteral("\n  13  max_temperature"))));
    }

    void getPrintsTheNamedRegisters()
    {
        setServoValue(1, QStringLiteral("position_offset"), -100);
        const auto result =
            run(QStringLiteral("--json get --id 1 max_temperature position_offset"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject values = objectOf(result.out);
        QCOMPARE(values.size(), 2);
        QCOMPARE(values.value(QStringLiteral("max_temperature")).toInt(),
                 servoValue(1, QStringLiteral("max_temperature")));
        QCOMPARE(values.value(QStringLiteral("position_offset")).toInt(), -100);
    }

    void setWritesVerifiesAndTheServoHoldsIt()
    {
        auto result = run(QStringLiteral("set --id 1 max_temperature=65 position_offset=-20"));
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(servoValue(1, QStringLiteral("max_temperature")), 65);
        QCOMPARE(servoValue(1, QStringLiteral("position_offset")), -20);
        // Big-endian SCS, and the JSON report.
        result = run(QStringLiteral("--json set --id 3 max_angle_limit=900"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject report = objectOf(result.out);
        QCOMPARE(report.value(QStringLiteral("verified")), QJsonValue(true));
        QCOMPARE(report.value(QStringLiteral("values"))[QStringLiteral("max_angle_limit")].toInt(),
                 900);
        QCOMPARE(servoValue(3, QStringLiteral("max_angle_limit")), 900);
        // Survives a power cycle: the EEPROM was unlocked and locked around the write.
        m_simulator.call([](sim::Simulator &s) { s.powerCycle(); });
        QCOMPARE(servoValue(1, QStringLiteral("max_temperature")), 65);
    }

    void badKeysAndValuesExitTwoWithoutWriting_data()
    {
        QTest::addColumn<QString>("line");
        QTest::newRow("unknown key") << QStringLiteral("set --id 1 max_temprature=65");
        QTest::newRow("out of range") << QStringLiteral("set --id 1 max_temperature=101");
        QTest::newRow("signed out of range") << QStringLiteral("set --id 1 position_offset=-3000");
        QTest::newRow("one bad among good")
            << QStringLiteral("set --id 1 max_temperature=60 p_gain=255");
        QTest::newRow("key of another family") << QStringLiteral("set --id 3 position_offset=1");
        QTest::newRow("not a number") << QStringLiteral("set --id 1 max_temperature=hot");
        QTest::newRow("read-only") << QStringLiteral("set --id 1 present_position=5");
        QTest::newRow("id") << QStringLiteral("set --id 1 id=7");
        QTest::newRow("baud rate") << QStringLiteral("set --id 1 baud_rate=115200");
        QTest::newRow("no assignment") << QStringLiteral("set --id 1");
        QTest::newRow("not an assignment") << QStringLiteral("set --id 1 max_temperature");
        QTest::newRow("missing id") << QStringLiteral("set max_temperature=60");
        QTest::newRow("unknown get key") << QStringLiteral("get --id 1 colour");
        QTest::newRow("unknown command") << QStringLiteral("flash --id 1");
        QTest::newRow("monitor without ids") << QStringLiteral("monitor --id 1");
        QTest::newRow("monitor rate too high") << QStringLiteral("monitor --ids 1 --rate 5000");
        QTest::newRow("monitor rate not a number") << QStringLiteral("monitor --ids 1 --rate fast");
        QTest::newRow("monitor id twice") << QStringLiteral("monitor --ids 1,2,1");
        QTest::newRow("monitor zero duration") << QStringLiteral("monitor --ids 1 --duration 0");
        QTest::newRow("monitor csv and json") << QStringLiteral("monitor --ids 1 --csv --json");
        QTest::newRow("rate elsewhere") << QStringLiteral("read --id 1 --rate 5");
        QTest::newRow("option not taken") << QStringLiteral("read --id 1 --ids 1-3");
        QTest::newRow("not a baud rate") << QStringLiteral("ping --id 1 --baud 9600");
        QTest::newRow("new id out of range") << QStringLiteral("set-id --id 1 254");
        QTest::newRow("new baud not feetech") << QStringLiteral("set-baud --id 1 9600");
        QTest::newRow("scan of two ranges") << QStringLiteral("scan --ids 1-3,7-9");
        QTest::newRow("missing profile") << QStringLiteral("load --id 1 /nonexistent/p.json");
        QTest::newRow("backup folder missing")
            << QStringLiteral("factory-reset --id 1 --backup /nonexistent/b.json");
        // Every way a file can be bad, for each command that reads one.
        const QString robot = m_dir.filePath(QStringLiteral("robot.json"));
        const QString calibration = m_dir.filePath(QStringLiteral("calibration.json"));
        util::FileError error;
        QVERIFY(
            feetech::saveRobotTemplate(feetech::builtInRobotTemplates().first(), robot, &error));
        QVERIFY(
            feetech::saveLeRobotCalibration(testsupport::sampleCalibration(), calibration, &error));
        const struct
        {
            QString command;
            QString good;
        } readers[] = {{QStringLiteral("load --id 1"), robot},
                       {QStringLiteral("load --ids 1,2"), robot},
                       {QStringLiteral("calibration load"), calibration}};
        for (const auto &reader : readers) {
            QFile file(reader.good);
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QString folder = m_dir.filePath(QString(reader.command).replace(u' ', u'_'));
            for (const auto &bad : testsupport::writeHostileFiles(
                     folder, QFileInfo(reader.good).fileName(), file.readAll())) {
                QTest::newRow(qPrintable(reader.command + QStringLiteral(", ") + bad.kind))
                    << reader.command + u' ' + bad.path;
            }
        }
    }

    void aServoLeftUnlockedIsNamedInANoteWithTheWayToLockIt()
    {
        auto result = run(QStringLiteral("get --id 1 max_temperature"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(result.err.isEmpty(), qPrintable(result.err)); // locked, as servos power on
        setServoValue(1, QStringLiteral("lock"), 0); // a write cut short before its relock
        result = run(QStringLiteral("get --id 1 max_temperature"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(result.err.contains(QStringLiteral("note: servo 1's EEPROM is unlocked")),
                 qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("servoctl feetech lock --id 1")),
                 qPrintable(result.err));
        QCOMPARE(result.err.count(u'\n'), 1);
        QVERIFY(!result.out.isEmpty()); // and the command still did its work
        QCOMPARE(writesReceived(), 0); // nothing is locked behind the user's back
    }

    void everyCommandWithMalformedArgumentsExitsTwoAndWritesNothing()
    {
        // Each command, each way its arguments can be wrong: exit 2 and one line saying why.
        const QStringList commands = {
            QStringLiteral("scan"),          QStringLiteral("ping"),
            QStringLiteral("read"),          QStringLiteral("get"),
            QStringLiteral("set"),           QStringLiteral("save"),
            QStringLiteral("load"),          QStringLiteral("set-id"),
            QStringLiteral("set-baud"),      QStringLiteral("calibrate-middle"),
            QStringLiteral("factory-reset"), QStringLiteral("reboot"),
            QStringLiteral("recover"),       QStringLiteral("setup-motor"),
            QStringLiteral("monitor"),       QStringLiteral("identify"),
            QStringLiteral("health"),        QStringLiteral("calibrate"),
            QStringLiteral("calibration")};
        const QStringList malformed = {QStringLiteral("--bogus 1"),
                                       QStringLiteral("--id abc"),
                                       QStringLiteral("--id 999"),
                                       QStringLiteral("--id -1"),
                                       QStringLiteral("--id 1.5"),
                                       QStringLiteral("--ids 1,,2"),
                                       QStringLiteral("--ids 3-1"),
                                       QStringLiteral("--ids 1-999999999999"),
                                       QStringLiteral("--id 1 --id 2 x y z"),
                                       QStringLiteral("--id"),
                                       QStringLiteral("--rate nan"),
                                       QStringLiteral("--duration -5"),
                                       QStringLiteral("--baud 12abc"),
                                       QStringLiteral("--id 1 --baud 0")};
        QStringList wrong;
        for (const QString &command : commands) {
            for (const QString &arguments : malformed) {
                const QString line = command + u' ' + arguments;
                const auto result = run(line);
                if (result.exitCode != 2 || result.err.count(u'\n') != 1
                    || !result.err.startsWith(u"servoctl: ")) {
                    wrong.append(QStringLiteral("%1: exit %2, %3")
                                     .arg(line)
                                     .arg(result.exitCode)
                                     .arg(result.err.trimmed()));
                }
            }
        }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u'\n')));
        QCOMPARE(writesReceived(), 0);
        for (const quint8 instruction : instructionsReceived())
            QVERIFY(instruction == 0x01 || instruction == 0x02);
    }

    void badKeysAndValuesExitTwoWithoutWriting()
    {
        QFETCH(QString, line);
        const auto result = run(line);
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.out.isEmpty());
        QCOMPARE(result.err.count(u'\n'), 1);
        QCOMPARE(writesReceived(), 0);
        // At most the identification (PING and READ of 0-8) went out.
        for (const quint8 instruction : instructionsReceived())
            QVERIFY2(instruction == 0x01 || instruction == 0x02, qPrintable(line));
    }

    void setIdToAnOccupiedIdIsRefused()
    {
        const auto result = run(QStringLiteral("set-id --id 1 2"));
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QStringLiteral("2")));
        QCOMPARE(writesReceived(), 0);
        QCOMPARE(servoValue(1, QStringLiteral("id")), 1);
    }

    void setIdToAFreeIdMovesTheServo()
    {
        const auto result = run(QStringLiteral("--json set-id --id 2 9"));
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(objectOf(result.out).value(QStringLiteral("servo"))[QStringLiteral("id")].toInt(),
                 9);
        QCOMPARE(run(QStringLiteral("ping --id 9")).exitCode, 0);
        QCOMPARE(run(QStringLiteral("ping --id 2")).exitCode, 1);
    }

    void setBaudIsFollowedToTheNewRate()
    {
        const auto result = run(QStringLiteral("--json set-baud --id 2 500000"));
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(
            objectOf(result.out).value(QStringLiteral("servo"))[QStringLiteral("baud")].toInt(),
            500000);
        QCOMPARE(run(QStringLiteral("ping --id 2 --baud 500000")).exitCode, 0);
        QCOMPARE(run(QStringLiteral("ping --id 2")).exitCode, 1);
    }

    void aSavedProfileLoadsBackOntoTheServo()
    {
        const QString path = m_dir.filePath(QStringLiteral("servo1.json"));
        QCOMPARE(run(QStringLiteral("save --id 1 ") + path).exitCode, 0);
        util::FileError error;
        const auto saved = profile::load(
            path, QStringLiteral("sts"),
            feetech::profileDefinitions(feetech::RegisterTable::forFamily(feetech::Family::Sts)),
            &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->model, QStringLiteral("STS3215"));
        QCOMPARE(*saved->value(QStringLiteral("max_temperature")),
                 qint64(servoValue(1, QStringLiteral("max_temperature"))));
        QVERIFY(!saved->value(QStringLiteral("id")));
        QVERIFY(!saved->value(QStringLiteral("baud_rate")));

        const qint32 temperature = servoValue(1, QStringLiteral("max_temperature"));
        const qint32 gain = servoValue(1, QStringLiteral("p_gain"));
        QCOMPARE(run(QStringLiteral("set --id 1 max_temperature=61 p_gain=9 position_offset=-7"))
                     .exitCode,
                 0);
        const int writesBefore = writesReceived();
        const auto loaded = run(QStringLiteral("--json load --id 1 ") + path);
        QCOMPARE(loaded.exitCode, 0);
        QCOMPARE(objectOf(loaded.out).value(QStringLiteral("changed")).toInt(), 3);
        QCOMPARE(servoValue(1, QStringLiteral("max_temperature")), temperature);
        QCOMPARE(servoValue(1, QStringLiteral("p_gain")), gain);
        QCOMPARE(servoValue(1, QStringLiteral("position_offset")), 0);
        // Unlock, three values, lock: only what differed was written.
        QCOMPARE(writesReceived() - writesBefore, 5);

        // Loading it again changes nothing and writes nothing.
        const int writesAfter = writesReceived();
        QCOMPARE(run(QStringLiteral("load --id 1 ") + path).exitCode, 0);
        QCOMPARE(writesReceived(), writesAfter);
    }

    void aProfileOfAnotherFamilyIsRefusedWithoutWriting()
    {
        const QString path = m_dir.filePath(QStringLiteral("scs.json"));
        QCOMPARE(run(QStringLiteral("save --id 3 ") + path).exitCode, 0);
        const auto result = run(QStringLiteral("load --id 1 ") + path);
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.err.contains(QStringLiteral("scs")));
        QCOMPARE(writesReceived(), 0);
    }

    void anInvalidProfileIsRefusedBeforeAnythingIsSent()
    {
        const QString path = m_dir.filePath(QStringLiteral("bad.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format":"servobench-profile","version":1,"family":"sts",
                      "parameters":{"max_temperature":20,"p_gain":9999}})");
        file.close();
        const auto result = run(QStringLiteral("load --id 1 ") + path);
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.err.contains(QStringLiteral("p_gain")));
        QCOMPARE(framesReceived().size(), 0);
    }
};

QTEST_MAIN(TestServoctlFeetech)
#include "tst_servoctlfeetech.moc"
