// A leader's joints onto a follower's in LeRobot's normalised units: ranges, drive_mode, the
// gripper's 0…100, clamping, and joints matched by name.
#include "teleopmapping.h"

#include <QtTest>

using feetech::LeRobotMotor;
using feetech::TeleopMapping;

namespace {

LeRobotMotor motor(const QString &name, int id, qint32 low, qint32 high, int driveMode = 0)
{
    return {name, id, driveMode, 0, low, high};
}

} // namespace

class TestTeleopMapping : public QObject
{
    Q_OBJECT

private slots:
    void bodyJointsSpanMinus100To100AndTheGripper0To100()
    {
        const LeRobotMotor joint = motor(QStringLiteral("elbow_flex"), 3, 1000, 3000);
        QCOMPARE(TeleopMapping::normalise(joint, false, 1000), -100.0);
        QCOMPARE(TeleopMapping::normalise(joint, false, 2000), 0.0);
        QCOMPARE(TeleopMapping::normalise(joint, false, 3000), 100.0);
        QCOMPARE(TeleopMapping::normalise(joint, false, 5000), 100.0); // clamped to the range
        const LeRobotMotor gripper = motor(QStringLiteral("gripper"), 6, 2000, 3000);
        QCOMPARE(TeleopMapping::normalise(gripper, true, 2500), 50.0);
        QCOMPARE(TeleopMapping::position(gripper, true, 25.0), 2250);
        QCOMPARE(TeleopMapping::position(gripper, true, 150.0), 3000);
    }

    void driveModeInvertsTheDirection()
    {
        const LeRobotMotor inverted = motor(QStringLiteral("wrist_roll"), 5, 0, 4095, 1);
        QCOMPARE(TeleopMapping::normalise(inverted, false, 0), 100.0);
        QCOMPARE(TeleopMapping::position(inverted, false, 100.0), 0);
        QCOMPARE(TeleopMapping::position(inverted, false, -100.0), 4095);
        const LeRobotMotor gripper = motor(QStringLiteral("gripper"), 6, 0, 1000, 1);
        QCOMPARE(TeleopMapping::normalise(gripper, true, 0), 100.0);
    }

    void armsOfDifferentRangesMapOntoEachOther()
    {
        QStringList missing;
        const auto mapping =
            TeleopMapping::match({motor(QStringLiteral("shoulder_pan"), 1, 1000, 3000),
                                  motor(QStringLiteral("gripper"), 6, 2000, 2400)},
                                 {motor(QStringLiteral("gripper"), 16, 0, 1000),
                                  motor(QStringLiteral("shoulder_pan"), 11, 500, 1500, 1)},
                                 &missing, TeleopMapping::NormMode::RangeM100_100);
        QVERIFY(mapping);
        QCOMPARE(mapping->joints().size(), 2);
        QCOMPARE(mapping->joints().at(0).leader.id, 11); // in the follower's order, by name
        // The leader's pan at its 75 % is −50 (inverted), the follower's 25 %.
        QCOMPARE(mapping->followerGoal(0, 1250), 1500);
        QCOMPARE(mapping->followerGoal(1, 500), 2200);
        QCOMPARE(mapping->followerGoal(1, 9999), 2400);
    }

    // LeRobot's SO arms' default (use_degrees): the same angle from each range's middle, not
    // the same share of each range; the gripper still maps share onto share.
    void inDegreesAJointKeepsItsAngleFromTheMiddleOfEachRange()
    {
        const auto mapping =
            TeleopMapping::match({motor(QStringLiteral("shoulder_pan"), 1, 1000, 3000),
                                  motor(QStringLiteral("gripper"), 6, 2000, 2400)},
                                 {motor(QStringLiteral("shoulder_pan"), 11, 500, 1500, 1),
                                  motor(QStringLiteral("gripper"), 16, 0, 1000)},
                                 nullptr);
        QVERIFY(mapping);
        QCOMPARE(mapping->normMode(), TeleopMapping::kDefaultNormMode);
        QCOMPARE(TeleopMapping::kDefaultNormMode, TeleopMapping::NormMode::Degrees);
        // 400 steps past the leader's middle (1000): 400 past the follower's (2000), where range
        // onto range would send it 800 past; drive_mode plays no part in LeRobot's degrees.
        QVERIFY(qAbs(mapping->followerGoal(0, 1400) - 2400) <= 1);
        QVERIFY(qAbs(mapping->followerGoal(0, 700) - 1700) <= 1);
        QCOMPARE(mapping->followerGoal(0, 1000), 2000);
        // Not clamped to the leader's range (LeRobot does not); within the follower's.
        QCOMPARE(mapping->followerGoal(0, 3000), 3000);
        QCOMPARE(mapping->followerGoal(1, 500), 2200);
        for (const auto mode :
             {TeleopMapping::NormMode::Degrees, TeleopMapping::NormMode::RangeM100_100})
            QCOMPARE(TeleopMapping::normModeFromKey(TeleopMapping::normModeKey(mode)), mode);
        QCOMPARE(TeleopMapping::normModeKey(TeleopMapping::NormMode::Degrees),
                 QStringLiteral("degrees"));
        QVERIFY(!TeleopMapping::normModeFromKey(u"radians"));
    }

    void aJointOnlyOneFileNamesIsMissing()
    {
        QStringList missing;
        QVERIFY(!TeleopMapping::match({motor(QStringLiteral("shoulder_pan"), 1, 0, 4095)},
                                      {motor(QStringLiteral("gripper"), 6, 0, 4095)}, &missing));
        QCOMPARE(missing.size(), 2);
        QVERIFY(missing.first().contains(QStringLiteral("shoulder_pan")));
        QVERIFY(missing.last().contains(QStringLiteral("gripper")));
    }
};

QTEST_GUILESS_MAIN(TestTeleopMapping)
#include "tst_teleopmapping.moc"
