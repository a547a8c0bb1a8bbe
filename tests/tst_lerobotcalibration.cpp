// Tests of LeRobot calibration files: the format, its checks, saving and LeRobot's folder.
#include "lerobotcalibration.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace feetech;

using Code = util::FileError::Code;
Q_DECLARE_METATYPE(util::FileError::Code)

namespace {

const QByteArray kTwoMotors = R"({
    "shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": -1200, "range_min": 800,
                     "range_max": 3300},
    "wrist_roll": {"id": 5, "drive_mode": 0, "homing_offset": 15, "range_min": 0,
                   "range_max": 4095}
})";

} // namespace

class TestLeRobotCalibration : public QObject
{
    Q_OBJECT

private slots:
    void aFileIsReadInIdOrder()
    {
        util::FileError error;
        const auto motors =
            leRobotCalibrationFromJson(kTwoMotors, QStringLiteral("a.json"), &error);
        QVERIFY2(motors, qPrintable(error.describe()));
        QCOMPARE(motors->size(), 2);
        QCOMPARE(motors->at(0).name, QStringLiteral("shoulder_pan"));
        QCOMPARE(motors->at(0).homingOffset, -1200);
        QCOMPARE(motors->at(0).rangeMin, 800);
        QCOMPARE(motors->at(1).id, 5);
        QCOMPARE(motors->at(1).rangeMax, 4095);
    }

    void whatIsWrittenReadsBackTheSameInTheArmsOrder()
    {
        const QVector<LeRobotMotor> motors {{QStringLiteral("gripper"), 6, 0, 2047, 2000, 3500},
                                            {QStringLiteral("shoulder_pan"), 1, 0, -2047, 10, 20}};
        const QByteArray json = leRobotCalibrationToJson(motors);
        QVERIFY(json.indexOf("gripper") < json.indexOf("shoulder_pan"));
        QVERIFY(json.contains("        \"homing_offset\": -2047,\n"));
        util::FileError error;
        const auto read = leRobotCalibrationFromJson(json, QStringLiteral("b.json"), &error);
        QVERIFY2(read, qPrintable(error.describe()));
        QCOMPARE(read->at(0).name, QStringLiteral("shoulder_pan"));
        QCOMPARE(read->at(1).homingOffset, 2047);
        QCOMPARE(read->at(1).rangeMin, 2000);
    }

    void aMalformedFileIsRefusedNamingTheJointAndField_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expected");
        QTest::addColumn<Code>("code");
        QTest::newRow("not JSON") << QByteArray("{") << QStringLiteral("not valid JSON")
                                  << Code::NotJson;
        QTest::newRow("array") << QByteArray("[]") << QStringLiteral("not a JSON object")
                               << Code::NotAnObject;
        QTest::newRow("empty") << QByteArray("{}") << QStringLiteral("names no motor")
                               << Code::MissingField;
        QTest::newRow("bad name") << QByteArray(
            R"({"grip per": {"id": 6, "drive_mode": 0, "homing_offset": 0,
                 "range_min": 0, "range_max": 10}})")
                                  << QStringLiteral("motor \"grip per\": not a motor name")
                                  << Code::BadValue;
        QTest::newRow("motor not object")
            << QByteArray(R"({"gripper": 5})") << QStringLiteral("motor \"gripper\": not an")
            << Code::WrongType;
        QTest::newRow("missing field")
            << QByteArray(R"({"gripper": {"id": 6, "drive_mode": 0, "homing_offset": 0,
                 "range_min": 0}})")
            << QStringLiteral("motor \"gripper\": \"range_max\" is missing") << Code::MissingField;
        QTest::newRow("not whole")
            << QByteArray(R"({"gripper": {"id": 6, "drive_mode": 0, "homing_offset": 1.5,
                 "range_min": 0, "range_max": 10}})")
            << QStringLiteral("\"homing_offset\" must be a whole number") << Code::WrongType;
        QTest::newRow("string") << QByteArray(
            R"({"gripper": {"id": "6", "drive_mode": 0, "homing_offset": 1,
                 "range_min": 0, "range_max": 10}})")
                                << QStringLiteral("\"id\" must be a whole number")
                                << Code::WrongType;
        QTest::newRow("offset out of range")
            << QByteArray(R"({"gripper": {"id": 6, "drive_mode": 0, "homing_offset": 2048,
                 "range_min": 0, "range_max": 10}})")
            << QStringLiteral("\"homing_offset\" is 2048, outside -2047 to 2047") << Code::BadValue;
        QTest::newRow("range reversed")
            << QByteArray(R"({"gripper": {"id": 6, "drive_mode": 0, "homing_offset": 0,
                 "range_min": 10, "range_max": 10}})")
            << QStringLiteral("\"range_min\" (10) must be below \"range_max\" (10)")
            << Code::BadValue;
        QTest::newRow("unknown field")
            << QByteArray(R"({"gripper": {"id": 6, "drive_mode": 0, "homing_offset": 0,
                 "range_min": 0, "range_max": 10, "speed": 3}})")
            << QStringLiteral("unknown field \"speed\"") << Code::UnknownKey;
        QTest::newRow("repeated ID")
            << QByteArray(R"({"a": {"id": 6, "drive_mode": 0, "homing_offset": 0,
                 "range_min": 0, "range_max": 10},
                 "b": {"id": 6, "drive_mode": 0, "homing_offset": 0,
                 "range_min": 0, "range_max": 10}})")
            << QStringLiteral("ID 6 is used by another motor too") << Code::Duplicate;
    }

    void aMalformedFileIsRefusedNamingTheJointAndField()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, expected);
        QFETCH(Code, code);
        util::FileError error;
        QVERIFY(!leRobotCalibrationFromJson(json, QStringLiteral("arm.json"), &error));
        QCOMPARE(error.code(), code);
        QVERIFY2(error.describe().startsWith(QLatin1String("arm.json: ")),
                 qPrintable(error.describe()));
        QVERIFY2(error.describe().contains(expected), qPrintable(error.describe()));
    }

    void savedFilesLoadBackAndAMissingOneIsNamed()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("arm.json"));
        util::FileError error;
        const QVector<LeRobotMotor> motors {{QStringLiteral("elbow_flex"), 3, 0, 12, 900, 3100}};
        QVERIFY2(saveLeRobotCalibration(motors, path, &error), qPrintable(error.describe()));
        const auto loaded = loadLeRobotCalibration(path, &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        QCOMPARE(loaded->first().rangeMax, 3100);
        QVERIFY(!loadLeRobotCalibration(dir.filePath(QStringLiteral("none.json")), &error));
        QCOMPARE(error.code(), Code::CannotRead);
        QVERIFY2(error.describe().contains(QLatin1String("none.json")),
                 qPrintable(error.describe()));
    }

    void leRobotsLimitOf4096IsReadAndOnePastItRefused()
    {
        util::FileError error;
        QVERIFY2(leRobotCalibrationFromJson(
                     R"({"wrist_roll": {"id": 5, "drive_mode": 0, "homing_offset": 0,
                         "range_min": 0, "range_max": 4096}})",
                     QStringLiteral("arm.json"), &error),
                 qPrintable(error.describe()));
        QVERIFY(!leRobotCalibrationFromJson(
            R"({"wrist_roll": {"id": 5, "drive_mode": 0, "homing_offset": 0,
                "range_min": 0, "range_max": 4097}})",
            QStringLiteral("arm.json"), &error));
        QCOMPARE(error.code(), Code::BadValue);
        QCOMPARE(error.field(), QStringLiteral("range_max"));
        QCOMPARE(error.value(), QStringLiteral("4097"));
        QVERIFY2(error.describe().contains(QLatin1String("outside 0 to 4096")),
                 qPrintable(error.describe()));
    }

    void whatCannotBeLoadedIsNotSaved()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("arm.json"));
        util::FileError error;
        QVERIFY(!saveLeRobotCalibration({{QStringLiteral("elbow_flex"), 3, 0, 12, 900, 5000}}, path,
                                        &error));
        QCOMPARE(error.code(), Code::BadValue);
        QCOMPARE(error.action(), util::FileError::Action::CheckingSave);
        QVERIFY2(error.describe().contains(QLatin1String("\"range_max\" is 5000")),
                 qPrintable(error.describe()));
        QVERIFY(!QFile::exists(path));
    }

    void aFileSavedOverAnotherKeepsItsDriveModes()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("arm.json"));
        util::FileError error;
        QVERIFY(saveLeRobotCalibration({{QStringLiteral("elbow_flex"), 3, 1, 12, 900, 3100},
                                        {QStringLiteral("gripper"), 6, 0, 0, 2000, 3400}},
                                       path, &error));
        QVector<LeRobotMotor> again {{QStringLiteral("elbow_flex"), 3, 0, 40, 800, 3000},
                                     {QStringLiteral("wrist_roll"), 5, 0, 0, 0, 4095}};
        keepDriveModes(again, path);
        QCOMPARE(again.at(0).driveMode, 1);
        QCOMPARE(again.at(1).driveMode, 0); // a joint the file did not have
        keepDriveModes(again, dir.filePath(QStringLiteral("none.json")));
        QCOMPARE(again.at(0).driveMode, 1);
    }

    void aReplacedJointIsUpdatedAndTheFilesOthersKept()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("arm.json"));
        QVector<LeRobotMotor> file {{QStringLiteral("shoulder_pan"), 1, 0, -1200, 800, 3300},
                                    {QStringLiteral("elbow_flex"), 3, 1, 40, 900, 3100},
                                    {QStringLiteral("wrist_roll"), 5, 0, 15, 0, 4095}};
        util::FileError error;
        QVERIFY(saveLeRobotCalibration(file, path, &error));
        const QByteArray before = [&] {
            QFile saved(path);
            return saved.open(QIODevice::ReadOnly) ? saved.readAll() : QByteArray();
        }();

        // The new servo's name and drive_mode are the file's, whatever the calibration says.
        QVERIFY2(updateLeRobotCalibrationFile({{QStringLiteral("id_3"), 3, 0, -300, 1000, 2900}},
                                              path, &error),
                 qPrintable(error.describe()));
        const auto updated = loadLeRobotCalibration(path, &error);
        QVERIFY(updated);
        QCOMPARE(updated->size(), 3);
        QCOMPARE(updated->at(0).homingOffset, -1200);
        QCOMPARE(updated->at(0).rangeMax, 3300);
        const LeRobotMotor *elbow = leRobotMotorWithId(*updated, 3);
        QVERIFY(elbow);
        QCOMPARE(elbow->name, QStringLiteral("elbow_flex"));
        QCOMPARE(elbow->driveMode, 1);
        QCOMPARE(elbow->homingOffset, -300);
        QCOMPARE(elbow->rangeMin, 1000);
        QCOMPARE(elbow->rangeMax, 2900);
        QCOMPARE(updated->at(2).homingOffset, 15);
        QVERIFY(before != leRobotCalibrationToJson(*updated));

        // A joint the file lacks: refused, the file left as it was.
        const QByteArray now = leRobotCalibrationToJson(*updated);
        QVERIFY(!updateLeRobotCalibrationFile({{QStringLiteral("gripper"), 6, 0, 0, 100, 200}},
                                              path, &error));
        QCOMPARE(error.code(), Code::MissingField);
        QVERIFY2(error.describe().contains(QLatin1String("no joint has ID 6")),
                 qPrintable(error.describe()));
        QCOMPARE(leRobotCalibrationToJson(*loadLeRobotCalibration(path, &error)), now);
        QVERIFY(!leRobotMotorWithId(*updated, 6));
    }

    void theFolderFollowsLeRobotsEnvironment()
    {
        const QByteArray saved[] = {qgetenv("HF_LEROBOT_CALIBRATION"), qgetenv("HF_LEROBOT_HOME"),
                                    qgetenv("HF_HOME")};
        qunsetenv("HF_LEROBOT_CALIBRATION");
        qunsetenv("HF_LEROBOT_HOME");
        qputenv("HF_HOME", "/tmp/hf");
        QCOMPARE(leRobotCalibrationFolder(), QStringLiteral("/tmp/hf/lerobot/calibration"));
        qputenv("HF_LEROBOT_HOME", "/tmp/lr");
        QCOMPARE(leRobotCalibrationFolder(), QStringLiteral("/tmp/lr/calibration"));
        qputenv("HF_LEROBOT_CALIBRATION", "/tmp/cal/");
        QCOMPARE(leRobotCalibrationFolder(), QStringLiteral("/tmp/cal"));
        qunsetenv("HF_LEROBOT_CALIBRATION");
        qunsetenv("HF_LEROBOT_HOME");
        qunsetenv("HF_HOME");
        QVERIFY(
            leRobotCalibrationFolder().endsWith(QLatin1String("huggingface/lerobot/calibration")));
        const char *names[] = {"HF_LEROBOT_CALIBRATION", "HF_LEROBOT_HOME", "HF_HOME"};
        for (int i = 0; i < 3; ++i) {
            if (!saved[i].isEmpty())
                qputenv(names[i], saved[i]);
        }
    }

    void soArmsHaveTheirLeRobotFolders()
    {
        QCOMPARE(leRobotArmFolders(QStringLiteral("SO-101 follower arm")).first(),
                 QStringLiteral("robots/so101_follower"));
        QCOMPARE(leRobotArmFolders(QStringLiteral("SO-100 leader arm")).first(),
                 QStringLiteral("teleoperators/so100_leader"));
        QVERIFY(leRobotArmFolders(QStringLiteral("My hexapod")).isEmpty());
    }

    void anArmsFolderIsTheOneLeRobotHasElseTheUsualOne()
    {
        QTemporaryDir root;
        QVERIFY(root.isValid());
        const QByteArray saved = qgetenv("HF_LEROBOT_CALIBRATION");
        qputenv("HF_LEROBOT_CALIBRATION", QFile::encodeName(root.path()));
        const QString follower = QStringLiteral("SO-101 follower arm");
        QCOMPARE(leRobotArmFolder(follower),
                 root.filePath(QStringLiteral("robots/so101_follower")));
        // LeRobot 0.4 keeps both SO arms in so_follower: a folder it made is the one.
        QVERIFY(QDir(root.path()).mkpath(QStringLiteral("robots/so_follower")));
        QCOMPARE(leRobotArmFolder(follower), root.filePath(QStringLiteral("robots/so_follower")));
        QCOMPARE(leRobotArmFolder(QStringLiteral("SO-100 leader arm")),
                 root.filePath(QStringLiteral("teleoperators/so100_leader")));
        QVERIFY(leRobotArmFolder(QStringLiteral("My hexapod")).isEmpty());
        if (saved.isNull())
            qunsetenv("HF_LEROBOT_CALIBRATION");
        else
            qputenv("HF_LEROBOT_CALIBRATION", saved);
    }
};

QTEST_GUILESS_MAIN(TestLeRobotCalibration)
#include "tst_lerobotcalibration.moc"
