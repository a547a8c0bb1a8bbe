// Tests how servos are named by joint: only when every servo found is a joint of a robot
// template (its ID and model), never for one servo alone or an ID found twice.
#include "jointnames.h"
#include "modeltable.h"

#include <QtTest>

using feetech::JointNames;
using feetech::ServoInfo;

namespace {

constexpr qint32 k1M = 1000000;

ServoInfo servo(quint8 id, quint8 major = 9, quint8 minor = 3, qint32 baud = k1M)
{
    ServoInfo info;
    info.id = id;
    info.baud = baud;
    info.modelMajor = major;
    info.modelMinor = minor;
    info.model = feetech::ModelTable::builtIn().identify(major, minor);
    return info;
}

QVector<ServoInfo> arm(int joints)
{
    QVector<ServoInfo> servos;
    for (int id = 1; id <= joints; ++id)
        servos.append(servo(quint8(id)));
    return servos;
}

} // namespace

class TestJointNames : public QObject
{
    Q_OBJECT

private slots:
    void anSo101ArmsServosAreNamedByJoint()
    {
        const JointNames names(feetech::builtInRobotTemplates(), arm(6));
        QVERIFY(!names.isEmpty());
        QVERIFY2(names.robot().startsWith(QLatin1String("SO-10")), qPrintable(names.robot()));
        QCOMPARE(names.joint({1, k1M}), QStringLiteral("shoulder_pan"));
        QCOMPARE(names.joint({6, k1M}), QStringLiteral("gripper"));
        QCOMPARE(names.label({3, k1M}), QStringLiteral("elbow_flex (ID 3)"));
    }

    void partOfTheArmIsNamedToo()
    {
        // A broken chain: the joints that answer keep their names.
        const JointNames names(feetech::builtInRobotTemplates(), arm(3));
        QCOMPARE(names.label({2, k1M}), QStringLiteral("shoulder_lift (ID 2)"));
    }

    void aServoOfAnotherModelOrIdNamesNothing()
    {
        QVector<ServoInfo> servos = arm(5);
        servos.append(servo(6, 5, 15)); // an SCS15 where the gripper's STS3215 should be
        QVERIFY(JointNames(feetech::builtInRobotTemplates(), servos).isEmpty());
        servos = arm(6);
        servos.append(servo(9));
        const JointNames names(feetech::builtInRobotTemplates(), servos);
        QVERIFY(names.isEmpty());
        QCOMPARE(names.label({9, k1M}), QStringLiteral("ID 9"));
        QCOMPARE(names.label({1, k1M}), QStringLiteral("ID 1"));
    }

    void oneServoOrAnIdTwiceNamesNothing()
    {
        QVERIFY(JointNames(feetech::builtInRobotTemplates(), arm(1)).isEmpty());
        QVector<ServoInfo> servos = arm(2);
        servos.append(servo(2, 9, 3, 500000)); // ID 2 at a second rate
        QVERIFY(JointNames(feetech::builtInRobotTemplates(), servos).isEmpty());
        servos = arm(2);
        servos[1].sharedId = true;
        QVERIFY(JointNames(feetech::builtInRobotTemplates(), servos).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestJointNames)
#include "tst_jointnames.moc"
