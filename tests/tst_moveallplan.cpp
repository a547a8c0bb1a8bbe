// Tests Move all's plan: what it sends, what it skips, and the first servo that refuses it.
#include "moveallplan.h"

#include <QtTest>

using feetech::MoveAllJoint;
using feetech::MoveAllPlan;
using feetech::PositionRange;

namespace {

constexpr qint32 k1M = 1000000;

MoveAllJoint joint(qint32 baud, std::optional<qint32> target)
{
    MoveAllJoint joint;
    joint.baud = baud;
    joint.known = true;
    joint.target = target;
    joint.range = PositionRange {0, 4095, true};
    joint.mode = 0;
    return joint;
}

} // namespace

Q_DECLARE_METATYPE(feetech::MoveAllJoint)

class TestMoveAllPlan : public QObject
{
    Q_OBJECT

private slots:
    void everyTargetIsSentInOneSyncWritePerBaudRate()
    {
        const MoveAllPlan plan =
            feetech::planMoveAll({joint(k1M, 10), joint(115200, 20), joint(k1M, 30)});
        QVERIFY(!plan.isRefused());
        QCOMPARE(plan.rows, (QVector<int> {0, 1, 2}));
        QCOMPARE(plan.syncWrites, 2);
        QVERIFY(plan.skipped.isEmpty());
        QVERIFY(plan.torqueOff.isEmpty());
    }

    void servosOfUnknownModelAreSkippedAndTorqueOffIsNoted()
    {
        MoveAllJoint unknown = joint(k1M, std::nullopt);
        unknown.known = false;
        unknown.range.reset();
        MoveAllJoint limp = joint(k1M, 100);
        limp.torqueOff = true;
        const MoveAllPlan plan = feetech::planMoveAll({unknown, limp});
        QVERIFY(!plan.isRefused());
        QCOMPARE(plan.rows, (QVector<int> {1}));
        QCOMPARE(plan.skipped, (QVector<int> {0}));
        QCOMPARE(plan.torqueOff, (QVector<int> {1}));
        QCOMPARE(plan.syncWrites, 1);
    }

    void theFirstServoThatRefusesStopsEverything_data()
    {
        QTest::addColumn<MoveAllJoint>("refusing");
        QTest::addColumn<int>("refusal");
        QTest::newRow("no target")
            << joint(k1M, std::nullopt) << int(MoveAllPlan::Refusal::NoTarget);
        QTest::newRow("out of range") << joint(k1M, 5000) << int(MoveAllPlan::Refusal::OutOfRange);
        MoveAllJoint wheel = joint(k1M, 100);
        wheel.mode = 1;
        QTest::newRow("wheel mode") << wheel << int(MoveAllPlan::Refusal::NotPositionMode);
    }

    void theFirstServoThatRefusesStopsEverything()
    {
        QFETCH(MoveAllJoint, refusing);
        QFETCH(int, refusal);
        const MoveAllPlan plan = feetech::planMoveAll({joint(k1M, 10), refusing, joint(k1M, -1)});
        QCOMPARE(int(plan.refusal), refusal);
        QCOMPARE(plan.refusedRow, 1);
        QVERIFY(plan.rows.isEmpty());
    }

    void nothingMovableIsRefused()
    {
        MoveAllJoint unknown;
        const MoveAllPlan plan = feetech::planMoveAll({unknown});
        QCOMPARE(plan.refusal, MoveAllPlan::Refusal::NothingMovable);
        QCOMPARE(plan.skipped, (QVector<int> {0}));
    }
};

QTEST_GUILESS_MAIN(TestMoveAllPlan)
#include "tst_moveallplan.moc"
