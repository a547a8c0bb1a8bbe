// servoctl feetech load --ids against a simulated bus (STS3215 ×2, SCS0009 at 1 Mbps): one
// profile or a robot template's settings to several servos, each diffed, written, verified and
// reported in a JSON array; a missing servo fails alone; an invalid file sends nothing; a
// profile's offset is not copied and a servo with torque on gets no offset or limit change.
#include "feetechbus.h"
#include "servoctlrun.h"

#include "robottemplate.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;

QJsonArray arrayOf(const QString &json)
{
    return QJsonDocument::fromJson(json.toUtf8()).array();
}

QStringList stringsOf(const QJsonValue &value)
{
    QStringList strings;
    for (const QJsonValue &each : value.toArray())
        strings.append(each.toString());
    return strings;
}

} // namespace

class TestServoctlBatch : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    // `arguments` after "servoctl --port LINK feetech".
    testsupport::ServoctlResult feetech(const QStringList &arguments) const
    {
        return testsupport::runServoctl(QStringList {QStringLiteral("--port"),
                                                     m_simulator->linkPath(),
                                                     QStringLiteral("feetech")}
                                        + arguments);
    }

    QString stsProfile() const
    {
        return writeTestFile(QStringLiteral("gains.json"),
                             R"({"format": "servobench-profile", "version": 1, "family": "sts",
                             "model": "STS3215",
                             "parameters": {"p_gain": 20, "max_temperature": 60}})");
    }

    // The byte at `key`'s address in servo `id`'s persistent EEPROM.
    int eepromByte(quint8 id, const QString &key)
    {
        const int address =
            feetech::RegisterTable::forFamily(feetech::Family::Sts).find(key)->address;
        int value = -1;
        withServo(id, k1M, [&](sim::VirtualFeetechServo &servo) {
            value = quint8(servo.eepromImage().at(address));
        });
        return value;
    }

    int writesTo(quint8 id) const
    {
        return int(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write, id)
                       .size());
    }

private slots:
    void init()
    {
        QString error;
        const auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS0009"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
    }

    void cleanup()
    {
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aProfileGoesToEveryServoAndAMissingOneFailsAlone()
    {
        const auto result =
            feetech({QStringLiteral("--json"), QStringLiteral("load"), QStringLiteral("--ids"),
                     QStringLiteral("1,2,4"), stsProfile()});
        QCOMPARE(result.exitCode, 1);
        const QJsonArray entries = arrayOf(result.out);
        QCOMPARE(entries.size(), 3);
        for (const int i : {0, 1}) {
            const QJsonObject entry = entries.at(i).toObject();
            QCOMPARE(entry.value(QStringLiteral("id")).toInt(), i + 1);
            QCOMPARE(entry.value(QStringLiteral("status")).toString(), QStringLiteral("ok"));
            QCOMPARE(stringsOf(entry.value(QStringLiteral("changed"))),
                     (QStringList {QStringLiteral("max_temperature"), QStringLiteral("p_gain")}));
            QVERIFY(entry.value(QStringLiteral("error")).isNull());
        }
        const QJsonObject missing = entries.at(2).toObject();
        QCOMPARE(missing.value(QStringLiteral("id")).toInt(), 4);
        QCOMPARE(missing.value(QStringLiteral("status")).toString(), QStringLiteral("failed"));
        QVERIFY(missing.value(QStringLiteral("error")).toString().contains(QStringLiteral("4")));
        for (const quint8 id : {1, 2}) {
            QCOMPARE(simulatorValue(id, u"p_gain"), 20);
            QCOMPARE(simulatorValue(id, u"max_temperature"), 60);
            // Locked EEPROM writes: the values persist.
            QCOMPARE(eepromByte(id, QStringLiteral("p_gain")), 20);
            QCOMPARE(eepromByte(id, QStringLiteral("max_temperature")), 60);
            QCOMPARE(simulatorValue(id, u"lock"), 1);
        }
    }

    void aProfileKeepsEachOffsetAndATorquedServoIsRefusedItsLimits()
    {
        const QString profile =
            writeTestFile(QStringLiteral("calibrated.json"),
                          R"({"format": "servobench-profile", "version": 1, "family": "sts",
                          "parameters": {"p_gain": 20, "position_offset": 300,
                                         "min_angle_limit": 100}})");
        setSimulatorValue(2, u"torque_enable", 1);
        const qint32 offset = simulatorValue(1, u"position_offset");
        const qint32 gain = simulatorValue(2, u"p_gain");
        const int writesBefore = writesTo(2);
        const auto result = feetech({QStringLiteral("--json"), QStringLiteral("load"),
                                     QStringLiteral("--ids"), QStringLiteral("1,2"), profile});
        QCOMPARE(result.exitCode, 1);
        const QJsonArray entries = arrayOf(result.out);
        QCOMPARE(entries.size(), 2);
        const QJsonObject written = entries.at(0).toObject();
        QCOMPARE(written.value(QStringLiteral("status")).toString(), QStringLiteral("ok"));
        QCOMPARE(stringsOf(written.value(QStringLiteral("left_out"))),
                 QStringList {QStringLiteral("position_offset")});
        QVERIFY(!stringsOf(written.value(QStringLiteral("changed")))
                     .contains(QStringLiteral("position_offset")));
        QCOMPARE(simulatorValue(1, u"position_offset"), offset);
        QCOMPARE(simulatorValue(1, u"min_angle_limit"), 100);
        const QJsonObject refused = entries.at(1).toObject();
        QCOMPARE(refused.value(QStringLiteral("status")).toString(), QStringLiteral("failed"));
        QVERIFY(refused.value(QStringLiteral("error"))
                    .toString()
                    .contains(QLatin1String("torque is on")));
        QCOMPARE(writesTo(2), writesBefore);
        QCOMPARE(simulatorValue(2, u"p_gain"), gain);

        // The text report says why the offset was not copied.
        const auto text = feetech(
            {QStringLiteral("load"), QStringLiteral("--ids"), QStringLiteral("1"), profile});
        QVERIFY2(text.out.contains(QLatin1String("Not copied from the profile: position_offset")),
                 qPrintable(text.out));
    }

    void loadingOneServoRefusesAnOffsetUnderTorqueAndRestoresItWithTorqueOff()
    {
        const QString profile =
            writeTestFile(QStringLiteral("own-calibration.json"),
                          R"({"format": "servobench-profile", "version": 1, "family": "sts",
                          "parameters": {"position_offset": 300}})");
        setSimulatorValue(1, u"torque_enable", 1);
        const qint32 offset = simulatorValue(1, u"position_offset");
        const int writesBefore = writesTo(1);
        const auto refused =
            feetech({QStringLiteral("load"), QStringLiteral("--id"), QStringLiteral("1"), profile});
        QCOMPARE(refused.exitCode, 1);
        QVERIFY2(refused.err.contains(QLatin1String("torque is on")), qPrintable(refused.err));
        QCOMPARE(writesTo(1), writesBefore);
        QCOMPARE(simulatorValue(1, u"position_offset"), offset);

        // One servo's own profile is its calibration: with torque off its offset is restored.
        setSimulatorValue(1, u"torque_enable", 0);
        const auto loaded =
            feetech({QStringLiteral("load"), QStringLiteral("--id"), QStringLiteral("1"), profile});
        QCOMPARE(loaded.exitCode, 0);
        QCOMPARE(simulatorValue(1, u"position_offset"), 300);
    }

    void servosThatAlreadyHoldTheValuesAreUnchangedAndNotWritten()
    {
        QCOMPARE(feetech({QStringLiteral("load"), QStringLiteral("--id"), QStringLiteral("1"),
                          stsProfile()})
                     .exitCode,
                 0);
        const int writesBefore = writesTo(1);
        const auto result = feetech({QStringLiteral("--json"), QStringLiteral("load"),
                                     QStringLiteral("--ids"), QStringLiteral("1-2"), stsProfile()});
        QCOMPARE(result.exitCode, 0);
        const QJsonArray entries = arrayOf(result.out);
        QCOMPARE(entries.at(0)[QStringLiteral("status")].toString(), QStringLiteral("unchanged"));
        QVERIFY(entries.at(0)[QStringLiteral("changed")].toArray().isEmpty());
        QCOMPARE(entries.at(1)[QStringLiteral("status")].toString(), QStringLiteral("ok"));
        QCOMPARE(writesTo(1), writesBefore);
    }

    void aTemplateGivesEachServoItsJointSettingsByIdAndRefusesAnotherModel()
    {
        feetech::RobotTemplate robot;
        robot.name = QStringLiteral("Test arm");
        robot.joints = {{QStringLiteral("base"),
                         1,
                         QStringLiteral("STS3215"),
                         false,
                         {{QStringLiteral("p_gain"), 25}},
                         {}},
                        {QStringLiteral("elbow"),
                         2,
                         QStringLiteral("STS3215"),
                         false,
                         {{QStringLiteral("p_gain"), 27}, {QStringLiteral("max_torque"), 500}},
                         {}},
                        {QStringLiteral("wrist"), 3, QStringLiteral("STS3215"), false, {}, {}}};
        const QString path =
            writeTestFile(QStringLiteral("arm.json"), feetech::robotTemplateToJson(robot));
        const auto result = feetech({QStringLiteral("--json"), QStringLiteral("load"),
                                     QStringLiteral("--ids"), QStringLiteral("1-3"), path});
        QCOMPARE(result.exitCode, 1);
        const QJsonArray entries = arrayOf(result.out);
        QCOMPARE(entries.size(), 3);
        QCOMPARE(entries.at(0)[QStringLiteral("status")].toString(), QStringLiteral("ok"));
        QCOMPARE(entries.at(1)[QStringLiteral("status")].toString(), QStringLiteral("ok"));
        QCOMPARE(stringsOf(entries.at(1)[QStringLiteral("changed")]),
                 (QStringList {QStringLiteral("max_torque"), QStringLiteral("p_gain")}));
        QCOMPARE(simulatorValue(1, u"p_gain"), 25);
        QCOMPARE(simulatorValue(2, u"p_gain"), 27);
        QCOMPARE(simulatorValue(2, u"max_torque"), 500);
        // Servo 3 is an SCS0009, the joint an STS3215: refused, nothing written to it.
        QCOMPARE(entries.at(2)[QStringLiteral("status")].toString(), QStringLiteral("failed"));
        QVERIFY(
            entries.at(2)[QStringLiteral("error")].toString().contains(QStringLiteral("STS3215")));
        QCOMPARE(writesTo(3), 0);
    }

    void aServoTheTemplateHasNoJointForFailsWithTheReason()
    {
        feetech::RobotTemplate robot;
        robot.name = QStringLiteral("One joint");
        robot.joints = {{QStringLiteral("base"),
                         1,
                         QStringLiteral("STS3215"),
                         false,
                         {{QStringLiteral("p_gain"), 25}},
                         {}}};
        const QString path =
            writeTestFile(QStringLiteral("one.json"), feetech::robotTemplateToJson(robot));
        const auto result =
            feetech({QStringLiteral("load"), QStringLiteral("--ids"), QStringLiteral("1,2"), path});
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.out.contains(QStringLiteral("no joint with ID 2")));
        QCOMPARE(writesTo(2), 0);
        QCOMPARE(simulatorValue(1, u"p_gain"), 25);
    }

    void anInvalidFileExitsTwoAndNothingIsSent_data()
    {
        QTest::addColumn<QByteArray>("contents");
        QTest::newRow("not json") << QByteArray("{ nope");
        QTest::newRow("value out of range")
            << QByteArray(R"({"format": "servobench-profile", "version": 1, "family": "sts",
                              "parameters": {"p_gain": 9999}})");
        QTest::newRow("template with a duplicate ID")
            << QByteArray(R"({"format": "servobench-robot", "version": 1, "name": "Bad",
                              "joints": [{"name": "a", "id": 1, "model": "STS3215"},
                                         {"name": "b", "id": 1, "model": "STS3215"}]})");
    }

    void anInvalidFileExitsTwoAndNothingIsSent()
    {
        QFETCH(QByteArray, contents);
        const QString path = writeTestFile(QStringLiteral("bad.json"), contents);
        const auto result =
            feetech({QStringLiteral("load"), QStringLiteral("--ids"), QStringLiteral("1-2"), path});
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.err.contains(QStringLiteral("bad.json")));
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }

    void badListsExitTwo_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::newRow("empty") << QStringList {QStringLiteral("--ids"), QString()};
        QTest::newRow("backwards") << QStringList {QStringLiteral("--ids"), QStringLiteral("3-1")};
        QTest::newRow("twice") << QStringList {QStringLiteral("--ids"), QStringLiteral("1,1")};
        QTest::newRow("both") << QStringList {QStringLiteral("--ids"), QStringLiteral("1"),
                                              QStringLiteral("--id"), QStringLiteral("1")};
    }

    void badListsExitTwo()
    {
        QFETCH(QStringList, arguments);
        const auto result =
            feetech(QStringList {QStringLiteral("load")} + arguments + QStringList {stsProfile()});
        QCOMPARE(result.exitCode, 2);
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }

    void withoutJsonTheResultIsATable()
    {
        const auto result = feetech(
            {QStringLiteral("load"), QStringLiteral("--ids"), QStringLiteral("1,4"), stsProfile()});
        QCOMPARE(result.exitCode, 1);
        const QStringList lines = result.out.split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4); // title, header, two servos
        QVERIFY(lines.at(2).startsWith(QStringLiteral("1 ")));
        QVERIFY(lines.at(2).contains(QStringLiteral("max_temperature, p_gain")));
        QVERIFY(lines.at(3).startsWith(QStringLiteral("4 ")));
        QVERIFY(lines.at(3).contains(QStringLiteral("failed")));
    }
};

QTEST_GUILESS_MAIN(TestServoctlBatch)
#include "tst_servoctlbatch.moc"
