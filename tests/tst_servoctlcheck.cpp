// servoctl feetech check against a simulated SO-101 arm over a pty: each problem the simulator is
// put into is found, --fix writes and verifies it, limits are refused with torque on, exit codes.
#include "feetechbus.h"
#include "servoctlrun.h"
#include "simoptions.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using testsupport::runServoctl;

namespace {

constexpr qint32 k1M = 1000000;

QJsonArray arrayOf(const QString &json)
{
    return QJsonDocument::fromJson(json.toUtf8()).array();
}

// The rows of servo `id` about register `key`.
QVector<QJsonObject> rowsOf(const QJsonArray &rows, int id, const QString &key)
{
    QVector<QJsonObject> found;
    for (const QJsonValue &row : rows) {
        if (row[QStringLiteral("id")].toInt() == id && row[QStringLiteral("key")].toString() == key)
            found.append(row.toObject());
    }
    return found;
}

} // namespace

class TestServoctlCheck : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    // The SO-101 follower as servosim --robot so101 plays it: set up with its template.
    void startArm(QVector<sim::FeetechServoSpec> extra = {})
    {
        sim::OptionError why;
        const auto robot = sim::simulatedRobot(QStringLiteral("so101"), &why);
        QVERIFY(robot);
        sim::SimulatorOptions options = busOptions(sim::robotServos(*robot) + extra);
        options.robot = robot;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
    }

    testsupport::ServoctlResult check(const QString &line) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath(),
                                        QStringLiteral("feetech"), QStringLiteral("check")}
                           + line.split(u' ', Qt::SkipEmptyParts));
    }

    int writesReceived() const
    {
        return int(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size());
    }

private slots:
    void cleanup()
    {
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void anArmSetUpFromItsTemplateHasNothingToFindAndWritesNothing()
    {
        startArm();
        const auto result = check(QStringLiteral("--ids 1-6 --robot so101-follower --json"));
        QVERIFY2(result.exitCode == 0, qPrintable(result.err + result.out));
        QVERIFY(arrayOf(result.out).isEmpty());
        const auto text = check(QStringLiteral("--ids 1-6 --robot so101-follower"));
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains(QStringLiteral("No problem found in the settings of 6 servo")),
                 qPrintable(text.out));
        QCOMPARE(writesReceived(), 0);
    }

    void eachProblemTheServosAreInIsARowWithItsExpectedValue()
    {
        startArm();
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) {
            s.setValue(u"phase", s.value(u"phase") | 0x10);
        }));
        setSimulatorValue(2, u"torque_limit", 0);
        setSimulatorValue(3, u"mode", 1);
        setSimulatorValue(4, u"min_angle_limit", 0);
        setSimulatorValue(4, u"max_angle_limit", 0);
        setSimulatorValue(5, u"return_delay", 250);
        setSimulatorValue(5, u"lock", 0);
        setSimulatorValue(6, u"max_torque", 0);
        setSimulatorValue(1, u"p_gain", 32);
        const auto result = check(QStringLiteral("--ids 1-6 --robot so101-follower --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonArray rows = arrayOf(result.out);
        const struct
        {
            int id;
            const char *key;
            const char *code;
            int expected;
        } cases[] = {{1, "phase", "multi-turn", simulatorValue(1, u"phase") & ~0x10},
                     {2, "torque_limit", "torque-limit-zero", 1000},
                     {3, "mode", "mode", 0},
                     {4, "max_angle_limit", "angle-limits-zero", 4095},
                     {5, "return_delay", "return-delay", 0},
                     {5, "lock", "unlocked", 1},
                     {6, "max_torque", "max-torque-zero", 500}, // the gripper's, as the template
                     {1, "p_gain", "template", 16}};
        for (const auto &expected : cases) {
            const auto found = rowsOf(rows, expected.id, QLatin1String(expected.key));
            QVERIFY2(found.size() == 1, expected.key);
            QCOMPARE(found.first()[QStringLiteral("code")].toString(),
                     QLatin1String(expected.code));
            QCOMPARE(found.first()[QStringLiteral("expected")].toInt(-1), expected.expected);
            QVERIFY(!found.first()[QStringLiteral("why")].toString().isEmpty());
            QVERIFY(found.first().contains(QStringLiteral("value")));
        }
        QCOMPARE(rows.size(), int(std::size(cases)));
        QCOMPARE(writesReceived(), 0);
    }

    void theTemplatesBitsToClearAreFoundAndFixedKeepingTheOtherBits()
    {
        startArm();
        // Phase bit 4 is also a rule of its own; the template names another bit too.
        const QString path =
            writeTestFile(QStringLiteral("arm.json"),
                          R"({"format": "servobench-robot", "version": 1, "name": "Test arm",
                "clear_bits": {"phase": [4, 7]},
                "joints": [{"name": "base", "id": 1, "model": "STS3215"}]})");
        QVERIFY(!path.isEmpty());
        const qint32 phase = simulatorValue(1, u"phase");
        QCOMPARE(phase & 0x90, 0); // set up as LeRobot does
        setSimulatorValue(1, u"phase", phase | 0x80);
        const QJsonArray rows =
            arrayOf(check(QStringLiteral("--ids 1 --json --robot ") + path).out);
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows.at(0)[QStringLiteral("code")].toString(), QStringLiteral("template"));
        QCOMPARE(rows.at(0)[QStringLiteral("expected")].toInt(), phase);
        const auto fixed = check(QStringLiteral("--ids 1 --fix --robot ") + path);
        QVERIFY2(fixed.exitCode == 0, qPrintable(fixed.out));
        QCOMPARE(simulatorValue(1, u"phase"), phase);
    }

    void factoryServosLoadedWithTheTemplateNeedNoSecondPass()
    {
        QString error;
        QVERIFY2(
            startSimulator(
                busOptions(testsupport::servosAt(
                    k1M, {u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215"})),
                &error),
            qPrintable(error));
        for (quint8 id = 1; id <= 6; ++id) {
            QVERIFY(withServo(id, k1M, [](sim::VirtualFeetechServo &s) {
                s.setValue(u"phase", s.value(u"phase") | 0x10); // as some servos leave the factory
                s.setValue(u"return_delay", 250);
            }));
        }
        QCOMPARE(check(QStringLiteral("--ids 1-6 --robot so101-follower")).exitCode, 1);
        const QString robot =
            QStringLiteral(SERVOBENCH_SOURCE_DIR "/resources/robots/so101-follower.json");
        const auto loaded = runServoctl({QStringLiteral("--port"), m_simulator->linkPath(),
                                         QStringLiteral("feetech"), QStringLiteral("load"),
                                         QStringLiteral("--ids"), QStringLiteral("1-6"), robot});
        QVERIFY2(loaded.exitCode == 0, qPrintable(loaded.err + loaded.out));
        for (quint8 id = 1; id <= 6; ++id)
            QCOMPARE(simulatorValue(id, u"phase") & 0x10, 0);
        const auto after = check(QStringLiteral("--ids 1-6 --robot so101-follower"));
        QVERIFY2(after.exitCode == 0, qPrintable(after.out));
    }

    void withoutARobotTemplateItsDifferencesAreNotFindings()
    {
        startArm();
        setSimulatorValue(1, u"p_gain", 32);
        QCOMPARE(check(QStringLiteral("--ids 1-6")).exitCode, 0);
    }

    void minAboveMaxIsFoundOnBothLimits()
    {
        startArm();
        setSimulatorValue(2, u"min_angle_limit", 3000);
        setSimulatorValue(2, u"max_angle_limit", 1000);
        const QJsonArray rows = arrayOf(check(QStringLiteral("--ids 2 --json")).out);
        QCOMPARE(rows.size(), 2);
        QCOMPARE(rows.at(0)[QStringLiteral("code")].toString(),
                 QStringLiteral("angle-limits-order"));
        QCOMPARE(rows.at(0)[QStringLiteral("expected")].toInt(), 0);
        QCOMPARE(rows.at(1)[QStringLiteral("expected")].toInt(), 4095);
    }

    void aSupplyAboveTheMaximumVoltageIsFoundButNotFixable()
    {
        startArm();
        QVERIFY(withServo(3, k1M, [](sim::VirtualFeetechServo &s) { s.setSupplyVoltage(12.0); }));
        const auto result = check(QStringLiteral("--ids 3 --fix --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonArray rows = arrayOf(result.out);
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows.at(0)[QStringLiteral("code")].toString(), QStringLiteral("voltage-limit"));
        QVERIFY(rows.at(0)[QStringLiteral("expected")].isNull());
        QVERIFY(!rows.at(0)[QStringLiteral("fixed")].toBool());
        QCOMPARE(writesReceived(), 0);
    }

    void servosOfOneModelWithDifferentFirmwareAreFound()
    {
        startArm();
        setSimulatorValue(2, u"firmware_minor", simulatorValue(1, u"firmware_minor") + 1);
        const QJsonArray rows = arrayOf(check(QStringLiteral("--ids 1-6 --json")).out);
        QStringList codes;
        for (const QJsonValue &row : rows)
            codes.append(row[QStringLiteral("code")].toString());
        QCOMPARE(codes.count(QStringLiteral("firmware-mismatch")), 6);
    }

    void fixWritesEveryExpectedValueVerifiesItAndExitsZero()
    {
        startArm();
        const qint32 phase = simulatorValue(1, u"phase");
        setSimulatorValue(1, u"phase", phase | 0x10);
        setSimulatorValue(2, u"torque_limit", 0);
        setSimulatorValue(3, u"mode", 1);
        setSimulatorValue(4, u"min_angle_limit", 0);
        setSimulatorValue(4, u"max_angle_limit", 0);
        setSimulatorValue(5, u"return_delay", 250);
        setSimulatorValue(5, u"lock", 0);
        setSimulatorValue(6, u"max_torque", 0);
        setSimulatorValue(1, u"p_gain", 32);
        const auto fixed = check(QStringLiteral("--ids 1-6 --robot so101-follower --fix --json"));
        QVERIFY2(fixed.exitCode == 0, qPrintable(fixed.err + fixed.out));
        const QJsonArray rows = arrayOf(fixed.out);
        QCOMPARE(rows.size(), 8);
        for (const QJsonValue &row : rows) {
            QVERIFY2(row[QStringLiteral("fixed")].toBool(),
                     qPrintable(row[QStringLiteral("result")].toString()));
        }
        QCOMPARE(simulatorValue(1, u"phase"), phase);
        QCOMPARE(simulatorValue(2, u"torque_limit"), 1000);
        QCOMPARE(simulatorValue(3, u"mode"), 0);
        QCOMPARE(simulatorValue(4, u"max_angle_limit"), 4095);
        QCOMPARE(simulatorValue(5, u"return_delay"), 0);
        QCOMPARE(simulatorValue(5, u"lock"), 1);
        QCOMPARE(simulatorValue(6, u"max_torque"), 500);
        QCOMPARE(simulatorValue(1, u"p_gain"), 16);
        // Every EEPROM it opened is closed again.
        for (quint8 id = 1; id <= 6; ++id)
            QCOMPARE(simulatorValue(id, u"lock"), 1);
        const auto after = check(QStringLiteral("--ids 1-6 --robot so101-follower"));
        QVERIFY2(after.exitCode == 0, qPrintable(after.out));
    }

    void withTorqueOnLimitsAndModeAreRefusedWithTheReasonAndLeftAsTheyWere()
    {
        startArm();
        setSimulatorValue(3, u"mode", 1);
        setSimulatorValue(3, u"return_delay", 250);
        setSimulatorValue(4, u"min_angle_limit", 3000);
        setSimulatorValue(4, u"max_angle_limit", 1000);
        for (const quint8 id : {3, 4}) {
            QVERIFY(withServo(id, k1M, [](sim::VirtualFeetechServo &s) {
                s.setValue(u"goal_position", s.value(u"present_position"));
                s.setValue(u"torque_enable", 1);
            }));
        }
        const auto result = check(QStringLiteral("--ids 3,4 --fix --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonArray rows = arrayOf(result.out);
        for (const char *key : {"mode", "min_angle_limit", "max_angle_limit"}) {
            const auto row = rowsOf(rows, QLatin1String(key) == QLatin1String("mode") ? 3 : 4,
                                    QLatin1String(key));
            QCOMPARE(row.size(), 1);
            QVERIFY(!row.first()[QStringLiteral("fixed")].toBool());
            QVERIFY2(row.first()[QStringLiteral("result")].toString().contains(
                         QStringLiteral("torque is on")),
                     qPrintable(row.first()[QStringLiteral("result")].toString()));
        }
        // What torque does not matter for is fixed all the same.
        QVERIFY(rowsOf(rows, 3, QStringLiteral("return_delay"))
                    .first()[QStringLiteral("fixed")]
                    .toBool());
        QCOMPARE(simulatorValue(3, u"return_delay"), 0);
        QCOMPARE(simulatorValue(3, u"mode"), 1);
        QCOMPARE(simulatorValue(4, u"min_angle_limit"), 3000);
        QCOMPARE(simulatorValue(4, u"max_angle_limit"), 1000);
        QCOMPARE(simulatorValue(3, u"lock"), 1);
    }

    void theTextIsATableWithAHeaderAndOneLinePerFinding()
    {
        startArm();
        setSimulatorValue(3, u"mode", 1);
        const auto result = check(QStringLiteral("--ids 1-6"));
        QCOMPARE(result.exitCode, 1);
        const QStringList lines = result.out.split(u'\n', Qt::SkipEmptyParts);
        QVERIFY2(lines.size() == 3, qPrintable(result.out));
        QVERIFY(lines.at(0).contains(QStringLiteral("EXPECTED")));
        QVERIFY(lines.at(1).startsWith(QStringLiteral("3 ")));
        QVERIFY(lines.at(1).contains(QStringLiteral("mode")));
    }

    void aServoThatDoesNotAnswerIsAFindingAndTheOthersAreChecked()
    {
        startArm();
        const auto result = check(QStringLiteral("--ids 1,9 --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonArray rows = arrayOf(result.out);
        QCOMPARE(rows.size(), 1);
        QCOMPARE(rows.at(0)[QStringLiteral("id")].toInt(), 9);
        QCOMPARE(rows.at(0)[QStringLiteral("code")].toString(), QStringLiteral("unreadable"));
    }

    void badUsageExitsTwoAndSendsNothing()
    {
        startArm();
        QCOMPARE(check(QString()).exitCode, 2);
        const auto unknown = check(QStringLiteral("--ids 1 --robot no-such-arm"));
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY(unknown.err.contains(QStringLiteral("no-such-arm")));
        QCOMPARE(check(QStringLiteral("--ids 1 --move-test")).exitCode, 2);
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestServoctlCheck)
#include "tst_servoctlcheck.moc"
