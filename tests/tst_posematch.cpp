// Tests how a pose meets the servos of a bus, and the pose their targets make.
#include "posematch.h"

#include <QtTest>

using feetech::JointTarget;
using feetech::Pose;
using feetech::PoseMatch;
using feetech::PositionRange;

namespace {

constexpr qint32 k1M = 1000000;

QVector<JointTarget> threeJoints()
{
    const PositionRange range {0, 4095, true};
    return {
        {{1, k1M}, std::nullopt, range}, {{2, k1M}, 100, range}, {{1, 115200}, 50, std::nullopt}};
}

} // namespace

class TestPoseMatch : public QObject
{
    Q_OBJECT

private slots:
    void aPoseFillsTheServosItNamesByIdAndBaudRate()
    {
        Pose pose;
        pose.name = QStringLiteral("Folded");
        pose.servos = {{2, k1M, 300}, {1, 115200, -20}, {1, k1M, 2048}};
        const PoseMatch match = feetech::matchPose(pose, threeJoints(), QStringLiteral("file"));
        QCOMPARE(match.name, QStringLiteral("Folded"));
        QCOMPARE(match.filled, 3);
        QCOMPARE(match.targets,
                 (QVector<std::optional<qint32>> {qint32(2048), qint32(300), qint32(-20)}));
        QVERIFY(match.isClean());
    }

    void entriesAndServosThatDoNotMeetAreNamed()
    {
        Pose pose;
        pose.servos = {{2, k1M, 5000}, {7, k1M, 10}, {1, 57600, 10}};
        const PoseMatch match = feetech::matchPose(pose, threeJoints(), QStringLiteral("file"));
        QCOMPARE(match.name, QStringLiteral("file"));
        QCOMPARE(match.filled, 1);
        QCOMPARE(match.targets.size(), 3);
        QVERIFY(!match.targets.at(0));
        QCOMPARE(match.targets.at(1), std::optional<qint32>(5000));
        QCOMPARE(match.notOnBus.size(), 2);
        QCOMPARE(match.notOnBus.at(0).id, quint8(7));
        QCOMPARE(match.notOnBus.at(1).baud, 57600);
        QCOMPARE(match.rowsWithoutEntry, (QVector<int> {0, 2}));
        QCOMPARE(match.rowsOutOfRange, (QVector<int> {1}));
        QVERIFY(!match.isClean());
    }

    void aServoWithoutRangeIsNeverOutOfRange()
    {
        Pose pose;
        pose.servos = {{1, 115200, 99999}};
        const PoseMatch match = feetech::matchPose(pose, threeJoints(), {});
        QCOMPARE(match.filled, 1);
        QVERIFY(match.rowsOutOfRange.isEmpty());
    }

    void thePoseOfTheTargetsLeavesOutServosWithoutOne()
    {
        const Pose pose = feetech::poseFromTargets(QStringLiteral("Rest"), threeJoints());
        QCOMPARE(pose.name, QStringLiteral("Rest"));
        QCOMPARE(pose.servos, (QVector<feetech::PoseEntry> {{2, k1M, 100}, {1, 115200, 50}}));
    }
};

QTEST_GUILESS_MAIN(TestPoseMatch)
#include "tst_posematch.moc"
