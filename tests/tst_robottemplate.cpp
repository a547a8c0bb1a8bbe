// Tests robot templates: the built-in arms, the checks that name the field at fault, saving.
#include "robottemplate.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

using feetech::RobotTemplate;

using Code = util::FileError::Code;
Q_DECLARE_METATYPE(util::FileError::Code)

namespace {

const QString kSource = QStringLiteral("arm.json");

QJsonObject joint(const QString &name, int id, const QJsonObject &settings = {})
{
    QJsonObject object {{QStringLiteral("name"), name},
                        {QStringLiteral("id"), id},
                        {QStringLiteral("model"), QStringLiteral("STS3215")}};
    if (!settings.isEmpty())
        object.insert(QStringLiteral("settings"), settings);
    return object;
}

QJsonObject armObject(const QJsonArray &joints)
{
    return {{QStringLiteral("format"), QStringLiteral("servobench-robot")},
            {QStringLiteral("version"), 1},
            {QStringLiteral("name"), QStringLiteral("Test arm")},
            {QStringLiteral("settings"), QJsonObject {{QStringLiteral("return_delay"), 0}}},
            {QStringLiteral("joints"), joints}};
}

QByteArray json(const QJsonObject &object)
{
    return QJsonDocument(object).toJson();
}

} // namespace

class TestRobotTemplate : public QObject
{
    Q_OBJECT

private slots:
    void theFourLeRobotArmsAreBuiltIn()
    {
        const auto &templates = feetech::builtInRobotTemplates();
        QStringList names;
        for (const RobotTemplate &robot : templates)
            names.append(robot.name);
        QCOMPARE(names,
                 (QStringList {
                     QStringLiteral("SO-100 follower arm"), QStringLiteral("SO-100 leader arm"),
                     QStringLiteral("SO-101 follower arm"), QStringLiteral("SO-101 leader arm")}));
        const QStringList joints {QStringLiteral("shoulder_pan"), QStringLiteral("shoulder_lift"),
                                  QStringLiteral("elbow_flex"),   QStringLiteral("wrist_flex"),
                                  QStringLiteral("wrist_roll"),   QStringLiteral("gripper")};
        for (const RobotTemplate &robot : templates) {
            QCOMPARE(robot.baud, 1000000);
            QCOMPARE(robot.joints.size(), 6);
            for (int i = 0; i < 6; ++i) {
                QCOMPARE(robot.joints.at(i).name, joints.at(i));
                QCOMPARE(robot.joints.at(i).id, i + 1);
                QCOMPARE(robot.joints.at(i).model, QStringLiteral("STS3215"));
                QCOMPARE(robot.joints.at(i).fullTurn, joints.at(i) == u"wrist_roll");
                QCOMPARE(robot.joints.at(i).settings.value(QStringLiteral("return_delay"), -1), 0);
                QCOMPARE(robot.joints.at(i).settings.value(QStringLiteral("acceleration"), -1),
                         254);
            }
        }
    }

    void followersGetLeRobotsGainsAndAGentlerGripper()
    {
        const RobotTemplate &follower = feetech::builtInRobotTemplates().at(2);
        const feetech::RobotJoint *elbow = follower.joint(u"elbow_flex");
        QVERIFY(elbow);
        QCOMPARE(elbow->settings.value(QStringLiteral("p_gain")), 16);
        QCOMPARE(elbow->settings.value(QStringLiteral("i_gain")), 0);
        QCOMPARE(elbow->settings.value(QStringLiteral("d_gain")), 32);
        QVERIFY(!elbow->settings.contains(QStringLiteral("max_torque")));
        const feetech::RobotJoint *gripper = follower.joint(u"gripper");
        QCOMPARE(gripper->settings.value(QStringLiteral("max_torque")), 500);
        QCOMPARE(gripper->settings.value(QStringLiteral("protection_current")), 250);
        QCOMPARE(gripper->settings.value(QStringLiteral("overload_torque")), 25);
        // A leader arm is moved by hand: no gains of its own.
        const RobotTemplate &leader = feetech::builtInRobotTemplates().at(3);
        QVERIFY(!leader.joint(u"elbow_flex")->settings.contains(QStringLiteral("p_gain")));
    }

    void everyBuiltInArmClearsPhaseBit4OnEveryJointAsLeRobotDoes()
    {
        for (const RobotTemplate &robot : feetech::builtInRobotTemplates()) {
            for (const feetech::RobotJoint &joint : robot.joints)
                QCOMPARE(joint.clearedBits.value(QStringLiteral("phase")), 0x10u);
        }
        const RobotTemplate &follower = feetech::builtInRobotTemplates().at(2);
        QCOMPARE(feetech::motorTarget(follower, follower.joints.first()).clearedBits,
                 follower.joints.first().clearedBits);
        QCOMPARE(feetech::jointChecks(follower).first().clearedBits,
                 follower.joints.first().clearedBits);
        const auto expected = feetech::settingsExpectations(follower);
        QCOMPARE(expected.clearedBitsById.value(6).value(QStringLiteral("phase")), 0x10u);
        QCOMPARE(expected.byId.value(6).value(QStringLiteral("max_torque")), 500);
        QVERIFY(expected.keys().contains(QStringLiteral("phase")));
    }

    void aJointsOwnBitsToClearGoOnTopOfTheCommonOnes()
    {
        QJsonObject arm =
            armObject({joint(QStringLiteral("base"), 1), joint(QStringLiteral("arm"), 2)});
        arm.insert(QStringLiteral("clear_bits"),
                   QJsonObject {{QStringLiteral("phase"), QJsonArray {4}}});
        QJsonArray joints = arm.value(QStringLiteral("joints")).toArray();
        QJsonObject second = joints.at(1).toObject();
        second.insert(QStringLiteral("clear_bits"),
                      QJsonObject {{QStringLiteral("phase"), QJsonArray {7}},
                                   {QStringLiteral("unload_conditions"), QJsonArray {0, 1}}});
        joints[1] = second;
        arm.insert(QStringLiteral("joints"), joints);
        util::FileError error;
        const auto robot = feetech::robotTemplateFromJson(json(arm), kSource, &error);
        QVERIFY2(robot, qPrintable(error.describe()));
        QCOMPARE(robot->joints.at(0).clearedBits.value(QStringLiteral("phase")), 0x10u);
        QCOMPARE(robot->joints.at(1).clearedBits.value(QStringLiteral("phase")), 0x90u);
        QCOMPARE(robot->joints.at(1).clearedBits.value(QStringLiteral("unload_conditions")), 0x03u);
        // Saved and read again, each joint keeps its own.
        const auto again =
            feetech::robotTemplateFromJson(feetech::robotTemplateToJson(*robot), kSource, &error);
        QVERIFY2(again, qPrintable(error.describe()));
        QCOMPARE(again->joints.at(1).clearedBits, robot->joints.at(1).clearedBits);
    }

    void aJointsOwnSettingsGoOnTopOfTheCommonOnes()
    {
        util::FileError error;
        const auto robot = feetech::robotTemplateFromJson(
            json(
                armObject({joint(QStringLiteral("base"), 1, {{QStringLiteral("return_delay"), 10}}),
                           joint(QStringLiteral("arm"), 2)})),
            kSource, &error);
        QVERIFY2(robot, qPrintable(error.describe()));
        QCOMPARE(robot->joints.at(0).settings.value(QStringLiteral("return_delay")), 10);
        QCOMPARE(robot->joints.at(1).settings.value(QStringLiteral("return_delay")), 0);
    }

    // What a set-up says of a joint is in the user's language, not the file's key.
    void aJointsTargetIsNamedAsTheUsersLanguageNamesIt()
    {
        class ChineseJoint : public QTranslator
        {
        public:
            QString translate(const char *context, const char *source, const char *,
                              int) const override
            {
                return qstrcmp(context, "Joint") == 0 && qstrcmp(source, "shoulder_pan") == 0
                    ? QStringLiteral("肩部旋转")
                    : QString();
            }
            bool isEmpty() const override { return false; }
        } translator;
        QVERIFY(QCoreApplication::installTranslator(&translator));
        const auto restore =
            qScopeGuard([&translator] { QCoreApplication::removeTranslator(&translator); });
        const feetech::RobotTemplate *arm =
            feetech::defaultRobotTemplateIn(feetech::builtInRobotTemplates());
        QVERIFY(arm);
        const feetech::MotorTarget target = feetech::motorTarget(*arm, arm->joints.first());
        QCOMPARE(arm->joints.first().name, QStringLiteral("shoulder_pan"));
        QCOMPARE(target.joint, QStringLiteral("肩部旋转"));
    }

    void aTemplateSavedAndLoadedIsTheSame()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("mine.json"));
        RobotTemplate robot = feetech::builtInRobotTemplates().at(2);
        robot.name = QStringLiteral("My arm");
        robot.joints[5].id = 9;
        util::FileError error;
        QVERIFY2(feetech::saveRobotTemplate(robot, path, &error), qPrintable(error.describe()));
        const auto loaded = feetech::loadRobotTemplate(path, &error);
        QVERIFY2(loaded, qPrintable(error.describe()));
        QCOMPARE(loaded->name, robot.name);
        QCOMPARE(loaded->joints.size(), 6);
        for (int i = 0; i < 6; ++i) {
            QCOMPARE(loaded->joints.at(i).id, robot.joints.at(i).id);
            QCOMPARE(loaded->joints.at(i).fullTurn, robot.joints.at(i).fullTurn);
            QCOMPARE(loaded->joints.at(i).settings, robot.joints.at(i).settings);
        }
    }

    void savedTemplatesAreListedAfterTheBuiltInOnesAndBadFilesAreReported()
    {
        QStandardPaths::setTestModeEnabled(true);
        QDir folder(feetech::userRobotTemplateFolder());
        QVERIFY(folder.removeRecursively() || !folder.exists());
        QVERIFY(folder.mkpath(QStringLiteral(".")));
        RobotTemplate robot = feetech::builtInRobotTemplates().first();
        robot.name = QStringLiteral("Workshop arm");
        util::FileError error;
        QVERIFY2(
            feetech::saveRobotTemplate(robot, folder.filePath(QStringLiteral("a.json")), &error),
            qPrintable(error.describe()));
        QFile broken(folder.filePath(QStringLiteral("b.json")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{ not json");
        broken.close();

        QStringList problems;
        const QVector<RobotTemplate> all = feetech::availableRobotTemplates(&problems);
        QCOMPARE(all.size(), feetech::builtInRobotTemplates().size() + 1);
        QCOMPARE(all.last().name, robot.name);
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.first().contains(QStringLiteral("b.json")), qPrintable(problems.first()));
        folder.removeRecursively();
    }

    void aTemplateThatCannotBeSavedSaysWhereAndWhy()
    {
        util::FileError error;
        QVERIFY(!feetech::saveRobotTemplate(feetech::builtInRobotTemplates().first(),
                                            QStringLiteral("/proc/no-such-dir/arm.json"), &error));
        QCOMPARE(error.code(), Code::CannotWrite);
        QVERIFY2(error.describe().contains(QStringLiteral("arm.json")),
                 qPrintable(error.describe()));
        QVERIFY(!feetech::loadRobotTemplate(QStringLiteral("/no/such/arm.json"), &error));
        QCOMPARE(error.code(), Code::CannotRead);
        QVERIFY2(error.describe().contains(QStringLiteral("arm.json")),
                 qPrintable(error.describe()));
    }

    void aBadTemplateIsRefusedNamingTheJointAndField_data()
    {
        QTest::addColumn<QByteArray>("document");
        QTest::addColumn<QString>("mention");
        QTest::addColumn<Code>("code");
        const QJsonArray two {joint(QStringLiteral("base"), 1), joint(QStringLiteral("arm"), 2)};
        QTest::newRow("not JSON") << QByteArray("{\"format\": ") << QStringLiteral("JSON")
                                  << Code::NotJson;
        QJsonObject wrong = armObject(two);
        wrong.insert(QStringLiteral("format"), QStringLiteral("servobench-pose"));
        QTest::newRow("another file kind")
            << json(wrong) << QStringLiteral("servobench-robot") << Code::WrongFormat;
        QJsonObject unnamed = armObject(two);
        unnamed.insert(QStringLiteral("name"), QStringLiteral("  "));
        QTest::newRow("no name") << json(unnamed) << QStringLiteral("\"name\"")
                                 << Code::MissingField;
        QJsonObject baud = armObject(two);
        baud.insert(QStringLiteral("baud"), 123456);
        QTest::newRow("no Feetech rate")
            << json(baud) << QStringLiteral("\"baud\"") << Code::BadValue;
        QTest::newRow("no joints")
            << json(armObject({})) << QStringLiteral("joints") << Code::MissingField;
        QTest::newRow("same ID twice")
            << json(armObject({joint(QStringLiteral("base"), 1), joint(QStringLiteral("arm"), 1)}))
            << QStringLiteral("joint 2 (arm): ID 1 is already base's") << Code::Duplicate;
        QTest::newRow("same name twice")
            << json(armObject({joint(QStringLiteral("base"), 1), joint(QStringLiteral("base"), 2)}))
            << QStringLiteral("\"base\" is used twice") << Code::Duplicate;
        QJsonObject unknownModel = joint(QStringLiteral("arm"), 2);
        unknownModel.insert(QStringLiteral("model"), QStringLiteral("XL330"));
        QTest::newRow("unknown model")
            << json(armObject({joint(QStringLiteral("base"), 1), unknownModel}))
            << QStringLiteral("joint 2 (arm): \"model\": \"XL330\"") << Code::BadValue;
        QTest::newRow("ID out of range")
            << json(armObject({joint(QStringLiteral("base"), 254)}))
            << QStringLiteral("joint 1 (base): \"id\"") << Code::BadValue;
        QTest::newRow("bad joint name") << json(armObject({joint(QStringLiteral("2nd joint"), 1)}))
                                        << QStringLiteral("joint 1") << Code::BadValue;
        QTest::newRow("setting out of range")
            << json(
                   armObject({joint(QStringLiteral("base"), 1, {{QStringLiteral("p_gain"), 300}})}))
            << QStringLiteral(
                   "joint 1 (base): settings: \"p_gain\" = 300 is out of range (0 to 254)")
            << Code::BadValue;
        QTest::newRow("register it has not")
            << json(armObject({joint(QStringLiteral("base"), 1, {{QStringLiteral("gain"), 3}})}))
            << QStringLiteral("\"gain\" is no writable register") << Code::UnknownKey;
        QTest::newRow("read-only register")
            << json(armObject(
                   {joint(QStringLiteral("base"), 1, {{QStringLiteral("present_position"), 3}})}))
            << QStringLiteral("\"present_position\" is no writable register") << Code::UnknownKey;
        QTest::newRow("the ID by the back door")
            << json(armObject({joint(QStringLiteral("base"), 1, {{QStringLiteral("id"), 3}})}))
            << QStringLiteral("\"id\" is set by its own flow") << Code::BadValue;
        QTest::newRow("the lock by the back door")
            << json(armObject({joint(QStringLiteral("base"), 1, {{QStringLiteral("lock"), 0}})}))
            << QStringLiteral("\"lock\" is set by its own flow") << Code::BadValue;
        QTest::newRow("a setting that is no number")
            << json(armObject({joint(QStringLiteral("base"), 1,
                                     {{QStringLiteral("p_gain"), QStringLiteral("16")}})}))
            << QStringLiteral("\"p_gain\" must be a whole number") << Code::WrongType;
        QJsonObject bitTooHigh = armObject(two);
        bitTooHigh.insert(QStringLiteral("clear_bits"),
                          QJsonObject {{QStringLiteral("phase"), QJsonArray {8}}});
        QTest::newRow("a bit the register has not")
            << json(bitTooHigh) << QStringLiteral("clear_bits: \"phase\" has bits 0 to 7")
            << Code::BadValue;
        QJsonObject bitsNoList = armObject(two);
        bitsNoList.insert(QStringLiteral("clear_bits"), QJsonObject {{QStringLiteral("phase"), 4}});
        QTest::newRow("bits that are no list")
            << json(bitsNoList) << QStringLiteral("\"phase\" must be a list of bit numbers")
            << Code::WrongType;
        QJsonObject bitsOfLock = armObject(two);
        bitsOfLock.insert(QStringLiteral("clear_bits"),
                          QJsonObject {{QStringLiteral("lock"), QJsonArray {0}}});
        QTest::newRow("the lock's bits by the back door")
            << json(bitsOfLock) << QStringLiteral("\"lock\" is set by its own flow")
            << Code::BadValue;
        QJsonObject bitsOfReadOnly = armObject(two);
        bitsOfReadOnly.insert(QStringLiteral("clear_bits"),
                              QJsonObject {{QStringLiteral("status"), QJsonArray {0}}});
        QTest::newRow("bits of a read-only register")
            << json(bitsOfReadOnly) << QStringLiteral("\"status\" is no writable register")
            << Code::UnknownKey;
        QJsonObject extra = joint(QStringLiteral("base"), 1);
        extra.insert(QStringLiteral("colour"), QStringLiteral("red"));
        QTest::newRow("unknown entry")
            << json(armObject({extra})) << QStringLiteral("\"colour\"") << Code::UnknownKey;
    }

    void aBadTemplateIsRefusedNamingTheJointAndField()
    {
        QFETCH(QByteArray, document);
        QFETCH(QString, mention);
        QFETCH(Code, code);
        util::FileError error;
        QVERIFY(!feetech::robotTemplateFromJson(document, kSource, &error));
        QCOMPARE(error.code(), code);
        QVERIFY2(error.describe().startsWith(kSource + QStringLiteral(": ")),
                 qPrintable(error.describe()));
        QVERIFY2(error.describe().contains(mention), qPrintable(error.describe()));
    }
};

QTEST_GUILESS_MAIN(TestRobotTemplate)
#include "tst_robottemplate.moc"
