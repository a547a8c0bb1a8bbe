// servoctl feetech calibrate and calibration save/load against a simulated arm over a pty, its
// joints turned by a scripted hand: offsets and limits in EEPROM, refusals, LeRobot files.
#include "feetechbus.h"
#include "scriptedhand.h"
#include "servoctlrun.h"

#include "feetechvalue.h"
#include "lerobotcalibration.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <unistd.h>

using testsupport::runServoctl;
using testsupport::ScriptedHand;

namespace {

constexpr int kOffsetAddress = 31;
constexpr int kMinimumLimitAddress = 9;

QJsonObject jointNamed(const QJsonArray &joints, const QString &name)
{
    for (const QJsonValue &joint : joints) {
        if (joint[QStringLiteral("name")].toString() == name)
            return joint.toObject();
    }
    return {};
}

struct Expected
{
    const char *name;
    int offset;
    int minimum;
    int maximum;
};

} // namespace

class TestServoctlCalibration : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    // A simulated SO-101 follower: six STS3215 at IDs 1-6, torque off.
    void startArm(int servos = 6)
    {
        QVector<sim::FeetechServoSpec> specs;
        for (int id = 1; id <= servos; ++id)
            specs.append({quint8(id), QStringLiteral("STS3215"), 1000000});
        QString error;
        QVERIFY2(startSimulator(busOptions(specs), &error), qPrintable(error));
    }

    testsupport::ServoctlResult servoctl(const QStringList &arguments) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath()}
                           + arguments);
    }

    QString path(const QString &name) const { return m_dir.filePath(name); }

    // Whether the recording has begun: the first SYNC READ of the positions has come in.
    bool recording() const
    {
        return !testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncRead)
                    .isEmpty();
    }

    QByteArray eeprom(quint8 id)
    {
        QByteArray image;
        m_simulator->call([&](sim::Simulator &simulator) {
            if (sim::VirtualFeetechServo *servo = simulator.feetechBus()->findServo(id))
                image = servo->eepromImage();
        });
        return image;
    }

private slots:
    void cleanup()
    {
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void sixJointsAreCentredOnTheEncoderAndKeptInEeprom()
    {
        startArm();
        // The elbow already has an offset: what it reads while recording is physical - 300.
        setSimulatorValue(3, u"position_offset", 300);
        ScriptedHand hand(*m_simulator);
        hand.place(1, 2000);
        hand.script(1, {500, 3000, 1800});
        hand.place(2, 3600); // across the seam: 3500 .. 4095, 0 .. 700
        hand.script(2, {3500, 4096 + 700, 4000});
        hand.place(3, 2000);
        hand.script(3, {1200, 2800, 2100});
        hand.place(4, 2048);
        hand.script(4, {1000, 3000, 2000});
        hand.place(5, 100); // the wrist roll turns without end stops
        hand.script(5, {1100, 600});
        hand.place(6, 2100);
        hand.script(6, {1900, 2600, 2000});
        hand.start([this] { return recording(); });
        const QString out = path(QStringLiteral("follower.json"));
        const auto result = servoctl(
            {QStringLiteral("--json"), QStringLiteral("feetech"), QStringLiteral("calibrate"),
             QStringLiteral("--ids"), QStringLiteral("1-6"), QStringLiteral("--names"),
             QStringLiteral("shoulder_pan,shoulder_lift,elbow_flex,wrist_flex,wrist_roll,gripper"),
             QStringLiteral("--full-turn"), QStringLiteral("5"), QStringLiteral("--duration"),
             QStringLiteral("4"), QStringLiteral("--out"), out});
        QVERIFY2(hand.done(), "the hand had not finished when the recording ended");
        QVERIFY2(result.exitCode == 0, qPrintable(result.err + result.out));

        const Expected expected[] = {
            {"shoulder_pan", 1750 - 2048, 2048 - 1250, 2048 + 1250},
            {"shoulder_lift", 4148 - 4096 - 2048, 2048 - 648, 2048 + 648},
            {"elbow_flex", 2000 - 2048, 2048 - 800, 2048 + 800},
            {"wrist_flex", 2000 - 2048, 2048 - 1000, 2048 + 1000},
            {"wrist_roll", 600 - 2048, 0, 4095},
            {"gripper", 2250 - 2048, 2048 - 350, 2048 + 350},
        };
        const QJsonObject report = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(report[QStringLiteral("file")].toString(), out);
        const QJsonArray joints = report[QStringLiteral("joints")].toArray();
        QCOMPARE(joints.size(), 6);
        for (int i = 0; i < 6; ++i) {
            const quint8 id = quint8(i + 1);
            const Expected &joint = expected[i];
            const QJsonObject shown = jointNamed(joints, QLatin1String(joint.name));
            QVERIFY2(shown[QStringLiteral("verified")].toBool(), joint.name);
            QCOMPARE(shown[QStringLiteral("offset")].toInt(), joint.offset);
            QCOMPARE(simulatorValue(id, u"position_offset"), joint.offset);
            QCOMPARE(simulatorValue(id, u"min_angle_limit"), joint.minimum);
            QCOMPARE(simulatorValue(id, u"max_angle_limit"), joint.maximum);
        }
        // Sign-magnitude with the sign in bit 11, low byte first: -1996 is 0x0FCC.
        QCOMPARE(feetech::toSignMagnitude(-1996, 11), std::optional<quint16>(0x0FCC));
        const QByteArray image = eeprom(2);
        QCOMPARE(quint8(image.at(kOffsetAddress)), quint8(0xCC));
        QCOMPARE(quint8(image.at(kOffsetAddress + 1)), quint8(0x0F));
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
        for (int i = 0; i < 6; ++i) {
            QCOMPARE(simulatorValue(quint8(i + 1), u"position_offset"), expected[i].offset);
            QCOMPARE(simulatorValue(quint8(i + 1), u"max_angle_limit"), expected[i].maximum);
        }
        // The joint that crossed the seam now reads one contiguous range about 2048.
        hand.place(2, 3500);
        hand.place(2, 4096 + 700);
        QTRY_COMPARE(simulatorValue(2, u"present_position"), 2048 + 648);

        util::FileError error;
        const auto saved = feetech::loadLeRobotCalibration(out, &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->size(), 6);
        QCOMPARE(saved->at(1).name, QStringLiteral("shoulder_lift"));
        QCOMPARE(saved->at(1).homingOffset, -1996);
        QCOMPARE(saved->at(4).rangeMax, 4095);
    }

    void refusedJointsAreNamedAndNothingIsWrittenForThem()
    {
        startArm(4);
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.script(1, {600, 1600, 1000});
        hand.place(2, 2000); // never moved
        hand.place(3, 100); // wider than a turn less the margin
        hand.script(3, {4180, 2000});
        hand.place(4, 2000); // stops answering: its ID changes under the recording
        hand.script(4, {1500, 2500},
                    [](sim::VirtualFeetechServo &servo) { servo.setValue(u"id", 99); });
        hand.start([this] { return recording(); });
        const auto result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibrate"),
                                      QStringLiteral("--ids"), QStringLiteral("1-4"),
                                      QStringLiteral("--duration"), QStringLiteral("4"),
                                      QStringLiteral("--out"), path(QStringLiteral("arm.json"))});
        QVERIFY(hand.done());
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.out.contains(QLatin1String("id_2 (servo 2): refused, nothing written: "
                                                   "the joint never moved")),
                 qPrintable(result.out));
        QVERIFY2(result.out.contains(QLatin1String("id_3 (servo 3): refused")),
                 qPrintable(result.out));
        QVERIFY2(result.out.contains(QLatin1String("wider")), qPrintable(result.out));
        QVERIFY2(result.out.contains(QLatin1String("servo 4 stopped answering")),
                 qPrintable(result.out));
        QVERIFY2(result.out.contains(QLatin1String("id_1 (servo 1): offset -948, limits 1548 to "
                                                   "2548, written and verified")),
                 qPrintable(result.out));
        for (const quint8 id : {2, 3, 4}) {
            QCOMPARE(testsupport::writesReceived(logPath(), id, kOffsetAddress), 0);
            QCOMPARE(testsupport::writesReceived(logPath(), id, kMinimumLimitAddress), 0);
        }
        QCOMPARE(simulatorValue(99, u"position_offset"), 0);
        QCOMPARE(testsupport::writesReceived(logPath(), 1, kOffsetAddress), 1);
        util::FileError error;
        const auto saved =
            feetech::loadLeRobotCalibration(path(QStringLiteral("arm.json")), &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->size(), 1);
        QCOMPARE(saved->first().name, QStringLiteral("id_1"));
    }

    void aDryRunSavesTheFileAndWritesNothing()
    {
        startArm(1);
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.script(1, {600, 1600, 1000});
        hand.start([this] { return recording(); });
        const QString out = path(QStringLiteral("dry.json"));
        const auto result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibrate"),
                                      QStringLiteral("--ids"), QStringLiteral("1"),
                                      QStringLiteral("--dry-run"), QStringLiteral("--duration"),
                                      QStringLiteral("3"), QStringLiteral("--out"), out});
        QVERIFY(hand.done());
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        QVERIFY(result.out.contains(QLatin1String("not written: --dry-run")));
        QCOMPARE(testsupport::writesReceived(logPath(), 1, kOffsetAddress), 0);
        QCOMPARE(simulatorValue(1, u"position_offset"), 0);
        util::FileError error;
        QVERIFY2(feetech::loadLeRobotCalibration(out, &error), qPrintable(error.describe()));
    }

    void aReplacedMotorIsCalibratedAloneAndTheFilesOtherJointsAreKept()
    {
        startArm(3);
        const QString file = writeTestFile(
            QStringLiteral("arm.json"),
            QByteArray(R"({"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": 11,
                             "range_min": 900, "range_max": 3100},
                           "shoulder_lift": {"id": 2, "drive_mode": 1, "homing_offset": -7,
                             "range_min": 800, "range_max": 3300},
                           "elbow_flex": {"id": 3, "drive_mode": 0, "homing_offset": 5,
                             "range_min": 1000, "range_max": 3000}})"));
        ScriptedHand hand(*m_simulator);
        hand.place(2, 2000);
        hand.script(2, {1200, 2800, 2000});
        hand.start([this] { return recording(); });
        const auto result =
            servoctl({QStringLiteral("feetech"), QStringLiteral("calibrate"),
                      QStringLiteral("--ids"), QStringLiteral("2"), QStringLiteral("--duration"),
                      QStringLiteral("4"), QStringLiteral("--update"), file});
        QVERIFY2(hand.done(), qPrintable(result.err + result.out));
        QVERIFY2(result.exitCode == 0, qPrintable(result.err + result.out));
        // Only the new motor's registers were written.
        QCOMPARE(testsupport::writesReceived(logPath(), 1, kOffsetAddress), 0);
        QCOMPARE(testsupport::writesReceived(logPath(), 3, kOffsetAddress), 0);
        QVERIFY(testsupport::writesReceived(logPath(), 2, kOffsetAddress) > 0);
        util::FileError error;
        const auto motors = feetech::loadLeRobotCalibration(file, &error);
        QVERIFY2(motors, qPrintable(error.describe()));
        QCOMPARE(motors->size(), 3);
        QCOMPARE(motors->at(0).homingOffset, 11);
        QCOMPARE(motors->at(0).rangeMin, 900);
        QCOMPARE(motors->at(2).rangeMax, 3000);
        const feetech::LeRobotMotor &replaced = motors->at(1);
        QCOMPARE(replaced.name, QStringLiteral("shoulder_lift"));
        QCOMPARE(replaced.driveMode, 1); // LeRobot's setting, kept
        QCOMPARE(replaced.homingOffset, simulatorValue(2, u"position_offset"));
        QCOMPARE(replaced.rangeMin, simulatorValue(2, u"min_angle_limit"));
        QVERIFY(replaced.rangeMin != 800);
        // A servo the file does not name is refused before anything is sent.
        const auto refused =
            servoctl({QStringLiteral("feetech"), QStringLiteral("calibrate"),
                      QStringLiteral("--ids"), QStringLiteral("9"), QStringLiteral("--duration"),
                      QStringLiteral("1"), QStringLiteral("--update"), file});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("no joint of")), qPrintable(refused.err));
    }

    void usageErrorsSendNothing_data()
    {
        QTest::addColumn<QString>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("names count") << "calibrate --ids 1-3 --names a,b --out F"
                                     << "--names gives 2 name(s) for 3 servo(s)";
        QTest::newRow("no out") << "calibrate --ids 1-3"
                                << "needs --out FILE";
        QTest::newRow("bad list") << "calibrate --ids 1-x --out F"
                                  << "is not an ID";
        QTest::newRow("full turn outside") << "calibrate --ids 1-3 --full-turn 5 --out F"
                                           << "--full-turn: servo 5 is not in";
        QTest::newRow("bad name") << "calibrate --ids 1 --names 9lives --out F"
                                  << "is not a joint name";
        QTest::newRow("save without file") << "calibration save --ids 1"
                                           << "needs one FILE";
        QTest::newRow("unknown sub") << "calibration erase F"
                                     << "use save or load";
    }

    void usageErrorsSendNothing()
    {
        QFETCH(QString, arguments);
        QFETCH(QString, message);
        startArm(1);
        arguments.replace(QLatin1String(" F"), u' ' + path(QStringLiteral("f.json")));
        const auto result =
            servoctl(QStringList {QStringLiteral("feetech")} + arguments.split(u' '));
        QCOMPARE(result.exitCode, 2);
        QVERIFY2(result.err.contains(message), qPrintable(result.err));
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }

    void withoutATerminalTheRecordingNeedsADuration()
    {
        if (isatty(STDIN_FILENO))
            QSKIP("standard input is a terminal here: Enter can end the recording");
        startArm(1);
        const auto result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibrate"),
                                      QStringLiteral("--ids"), QStringLiteral("1"),
                                      QStringLiteral("--out"), path(QStringLiteral("f.json"))});
        QCOMPARE(result.exitCode, 2);
        QVERIFY2(result.err.contains(QLatin1String("needs --duration S")), qPrintable(result.err));
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }

    void aCalibrationIsSavedAndLoadedBackWithItsDifferences()
    {
        startArm(2);
        setSimulatorValue(1, u"position_offset", -1200);
        setSimulatorValue(1, u"min_angle_limit", 800);
        setSimulatorValue(1, u"max_angle_limit", 3300);
        const QString file = path(QStringLiteral("saved.json"));
        auto result = servoctl({QStringLiteral("--json"), QStringLiteral("feetech"),
                                QStringLiteral("calibration"), QStringLiteral("save"),
                                QStringLiteral("--ids"), QStringLiteral("1,2"),
                                QStringLiteral("--names"), QStringLiteral("pan,lift"), file});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QJsonObject saved = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(
            saved[QStringLiteral("joints")][QStringLiteral("pan")][QStringLiteral("homing_offset")]
                .toInt(),
            -1200);
        // Onto the other servo's values, then the file back.
        const QVector<feetech::LeRobotMotor> swapped {
            {QStringLiteral("pan"), 1, 0, 0, 0, 4095},
            {QStringLiteral("lift"), 2, 0, -1200, 800, 3300}};
        util::FileError error;
        QVERIFY(feetech::saveLeRobotCalibration(swapped, file, &error));
        result = servoctl({QStringLiteral("--json"), QStringLiteral("feetech"),
                           QStringLiteral("calibration"), QStringLiteral("load"), file});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QJsonArray joints = QJsonDocument::fromJson(result.out.toUtf8())
                                      .object()[QStringLiteral("joints")]
                                      .toArray();
        const QJsonObject lift = jointNamed(joints, QStringLiteral("lift"));
        QVERIFY(lift[QStringLiteral("verified")].toBool());
        QCOMPARE(lift[QStringLiteral("changes")].toArray().size(), 3);
        QCOMPARE(lift[QStringLiteral("changes")][0][QStringLiteral("to")].toInt(), -1200);
        QCOMPARE(simulatorValue(2, u"position_offset"), -1200);
        QCOMPARE(simulatorValue(2, u"max_angle_limit"), 3300);
        QCOMPARE(simulatorValue(1, u"position_offset"), 0);
        QCOMPARE(simulatorValue(1, u"min_angle_limit"), 0);
        // Loading it again changes nothing.
        result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibration"),
                           QStringLiteral("load"), file});
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(result.out.contains(QLatin1String("lift (servo 2): already holds")),
                 qPrintable(result.out));
    }

    void whatSaveWritesLoadReadsWithLeRobotsLimitAndDriveMode()
    {
        // LeRobot gives a servo the limit 4096 and keeps drive_mode in its file only.
        startArm(2);
        setSimulatorValue(1, u"max_angle_limit", 4096);
        const QString file = path(QStringLiteral("lerobot.json"));
        util::FileError error;
        QVERIFY(feetech::saveLeRobotCalibration(
            {{QStringLiteral("pan"), 1, 1, 0, 0, 4096}, {QStringLiteral("lift"), 2, 0, 0, 0, 4095}},
            file, &error));
        auto result =
            servoctl({QStringLiteral("feetech"), QStringLiteral("calibration"),
                      QStringLiteral("save"), QStringLiteral("--ids"), QStringLiteral("1,2"),
                      QStringLiteral("--names"), QStringLiteral("pan,lift"), file});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const auto saved = feetech::loadLeRobotCalibration(file, &error);
        QVERIFY2(saved, qPrintable(error.describe()));
        QCOMPARE(saved->at(0).name, QStringLiteral("pan"));
        QCOMPARE(saved->at(0).rangeMax, 4096);
        QCOMPARE(saved->at(0).driveMode, 1); // kept from the file, not written as 0
        QCOMPARE(saved->at(1).driveMode, 0);

        const int writesBefore =
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size();
        result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibration"),
                           QStringLiteral("load"), file});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err + result.out));
        QVERIFY2(result.out.contains(QLatin1String("pan (servo 1): already holds")),
                 qPrintable(result.out));
        QVERIFY2(result.out.contains(QLatin1String("drive_mode 1 is LeRobot's software setting")),
                 qPrintable(result.out));
        QCOMPARE(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size(),
            writesBefore);
        QCOMPARE(simulatorValue(1, u"max_angle_limit"), 4096);
    }

    void aLimitNoFileCanHoldIsSaidAndNothingIsSaved()
    {
        startArm(1);
        setSimulatorValue(1, u"max_angle_limit", 5000);
        const QString file = path(QStringLiteral("past.json"));
        const auto result =
            servoctl({QStringLiteral("feetech"), QStringLiteral("calibration"),
                      QStringLiteral("save"), QStringLiteral("--ids"), QStringLiteral("1"), file});
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QLatin1String("\"range_max\" is 5000")),
                 qPrintable(result.err));
        QVERIFY2(result.err.contains(QLatin1String("it was not saved")), qPrintable(result.err));
        QVERIFY(!QFile::exists(file));
    }

    void aLoadIsRefusedForAJointWhoseTorqueIsOn()
    {
        startArm(1);
        setSimulatorValue(1, u"torque_enable", 1);
        const QString file = path(QStringLiteral("torque.json"));
        util::FileError error;
        QVERIFY(feetech::saveLeRobotCalibration({{QStringLiteral("pan"), 1, 0, 100, 10, 4000}},
                                                file, &error));
        const auto result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibration"),
                                      QStringLiteral("load"), file});
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.out.contains(QLatin1String("torque is on")), qPrintable(result.out));
        QCOMPARE(testsupport::writesReceived(logPath(), 1, kOffsetAddress), 0);
    }

    void aMalformedFileIsRefusedBeforeAnythingIsSent()
    {
        startArm(1);
        const QString file = path(QStringLiteral("bad.json"));
        QFile bad(file);
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(R"({"pan": {"id": 1, "drive_mode": 0, "homing_offset": 9000,
                    "range_min": 0, "range_max": 4095}})");
        bad.close();
        const auto result = servoctl({QStringLiteral("feetech"), QStringLiteral("calibration"),
                                      QStringLiteral("load"), file});
        QCOMPARE(result.exitCode, 2);
        QVERIFY2(result.err.contains(QLatin1String("motor \"pan\": \"homing_offset\" is 9000")),
                 qPrintable(result.err));
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestServoctlCalibration)
#include "tst_servoctlcalibration.moc"
