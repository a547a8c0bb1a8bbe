// Tests of arm calibration: unwrapping across the seam, offsets, limits and refusals.
#include "armcalibration.h"
#include "registertable.h"

#include <QtTest>

using namespace feetech;

namespace {

// A joint recorded through `positions` (as the servo read them) with `currentOffset`.
JointRecording recorded(std::initializer_list<int> positions, qint32 currentOffset = 0,
                        bool fullTurn = false)
{
    JointRecording joint;
    joint.name = QStringLiteral("elbow_flex");
    joint.id = 3;
    joint.fullTurn = fullTurn;
    joint.currentOffset = currentOffset;
    for (const int position : positions)
        joint.range.addSample(position);
    return joint;
}

// Steps from `from` to `to` (unwrapped), at most 100 at a time, read as the servo would.
void sweep(JointRecording &joint, int from, int to)
{
    const int direction = to >= from ? 1 : -1;
    for (int p = from; p != to; p += direction * std::min(100, std::abs(to - p)))
        joint.range.addSample(wrapToEncoder(p));
    joint.range.addSample(wrapToEncoder(to));
}

} // namespace

class TestArmCalibration : public QObject
{
    Q_OBJECT

private slots:
    void motionAcrossTheSeamIsUnwrapped()
    {
        JointRangeRecorder range;
        for (const int p : {4000, 4090, 10, 150, 4050, 3900})
            range.addSample(p);
        QCOMPARE(range.minimum(), 3900);
        QCOMPARE(range.maximum(), 4096 + 150);
        QCOMPARE(range.present(), 3900);
        QCOMPARE(range.span(), 346);
    }

    void motionDownwardsAcrossTheSeamGoesBelowZero()
    {
        JointRangeRecorder range;
        for (const int p : {100, 20, 4080, 3990})
            range.addSample(p);
        QCOMPARE(range.minimum(), -106);
        QCOMPARE(range.maximum(), 100);
        QCOMPARE(range.first(), 100);
    }

    void aRangeIsCentredOnTheMiddleOfTheEncoder()
    {
        JointRecording joint = recorded({});
        sweep(joint, 1000, 3000);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        QCOMPARE(result.offset, -48);
        QCOMPARE(result.minimumLimit, 1048);
        QCOMPARE(result.maximumLimit, 3048);
        QCOMPARE((result.minimumLimit + result.maximumLimit) / 2, kEncoderMiddle);
    }

    void aRangeAcrossTheSeamBecomesContiguous()
    {
        JointRecording joint = recorded({});
        sweep(joint, 3500, 4096 + 700); // reads 3500 .. 4095, 0 .. 700
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        // The middle 4148 (reads 52) goes to 2048: offset 52 - 2048.
        QCOMPARE(result.offset, 52 - 2048);
        QCOMPARE(result.minimumLimit, 2048 - 648);
        QCOMPARE(result.maximumLimit, 2048 + 648);
    }

    void theOffsetTheServoHadWhileRecordingIsTakenIntoAccount()
    {
        // The servo read 1000 .. 3000 with offset 500: physically 1500 .. 3500.
        JointRecording joint = recorded({}, 500);
        sweep(joint, 1000, 3000);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY(result.ok());
        QCOMPARE(result.offset, 2500 - 2048);
        QCOMPARE(result.minimumLimit, 1048);
        QCOMPARE(result.maximumLimit, 3048);
        QCOMPARE(inCalibratedCoordinates(joint, result, 1000), 1048);
        QCOMPARE(inCalibratedCoordinates(joint, result, 3000), 3048);
    }

    void anOffsetBeyondTheRegisterIsTheNearestItHolds()
    {
        const CalibrationLimits sts;
        QCOMPARE(offsetPlacing(0, 2048, sts), -2047); // -2048 does not fit bit 11's magnitude
        QCOMPARE(offsetPlacing(4095, 2048, sts), 2047);
        QCOMPARE(offsetPlacing(4096 + 4095, 2048, sts), 2047);
        QCOMPARE(offsetPlacing(1, 2048, sts), -2047);
        QCOMPARE(offsetPlacing(2048, 2047, sts), 1);
        CalibrationLimits hls;
        hls.minimumOffset = -4095;
        hls.maximumOffset = 4095;
        QCOMPARE(offsetPlacing(0, 2048, hls), -2048);
    }

    void aRangeWhoseMiddleNeedsOffsetMinus2048EndsOneStepOff()
    {
        JointRecording joint = recorded({});
        sweep(joint, -1000, 1000); // middle 0: the exact offset would be -2048
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY(result.ok());
        QCOMPARE(result.offset, -2047);
        QCOMPARE(result.minimumLimit, 1047);
        QCOMPARE(result.maximumLimit, 3047);
    }

    void aRangeJustInsideTheMarginIsAccepted()
    {
        JointRecording joint = recorded({});
        sweep(joint, 500, 500 + kEncoderSteps - kRangeSafetyMargin);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        QCOMPARE(result.minimumLimit, kRangeSafetyMargin / 2);
        QCOMPARE(result.maximumLimit, kEncoderSteps - kRangeSafetyMargin / 2);
    }

    void aRangeWiderThanTheEncoderLessTheMarginIsRefused()
    {
        JointRecording joint = recorded({});
        sweep(joint, 500, 500 + kEncoderSteps - kRangeSafetyMargin + 1);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY(!result.ok());
        QVERIFY2(result.refusal.contains(QLatin1String("wider")), qPrintable(result.refusal));
    }

    void aJointThatNeverMovedIsRefused()
    {
        const JointCalibration result = calibrateJoint(
            recorded({2000, 2005, 2000 + kMinimumMotionSteps - 1}), CalibrationOrder::RangeFirst);
        QVERIFY(!result.ok());
        QVERIFY2(result.refusal.contains(QLatin1String("never moved")), qPrintable(result.refusal));
    }

    void aServoThatStoppedAnsweringIsRefused()
    {
        JointRecording joint = recorded({});
        sweep(joint, 1000, 3000);
        joint.range.markLost();
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY(!result.ok());
        QVERIFY2(result.refusal.contains(QLatin1String("stopped answering")),
                 qPrintable(result.refusal));
        QVERIFY(!calibrateJoint(recorded({}), CalibrationOrder::RangeFirst).ok());
    }

    void aFullTurnJointGetsTheWholeEncoderAndTheMiddleOfItsMotion()
    {
        JointRecording joint = recorded({}, 0, true);
        sweep(joint, 3000, 4096 + 1000);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY(result.ok());
        QCOMPARE(result.minimumLimit, 0);
        QCOMPARE(result.maximumLimit, 4095);
        QCOMPARE(result.offset, 2000); // the middle, 4048, reads 2048
    }

    void aFullTurnJointTurnedAllRoundIsCentredWhereItWasLeft()
    {
        JointRecording joint = recorded({}, 0, true);
        sweep(joint, 0, 4096 + 300);
        sweep(joint, 4096 + 300, 4096 + 100);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::RangeFirst);
        QVERIFY(result.ok());
        QCOMPARE(result.offset, 100 - 2048);
        QCOMPARE(result.maximumLimit, 4095);
    }

    void leRobotsOrderPutsTheMiddlePoseAtHalfTurn2047()
    {
        JointRecording joint = recorded({}, 100);
        joint.middlePose = 1900; // physically 2000
        sweep(joint, 1900, 900);
        sweep(joint, 900, 2900);
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::MiddlePoseFirst);
        QVERIFY2(result.ok(), qPrintable(result.refusal));
        QCOMPARE(result.offset, 2000 - 2047);
        QCOMPARE(result.minimumLimit, 2047 - 1000);
        QCOMPARE(result.maximumLimit, 2047 + 1000);
    }

    void leRobotsOrderRefusesARangeThatStillCrossesTheSeam()
    {
        JointRecording joint = recorded({});
        joint.middlePose = 1000;
        sweep(joint, 1000, 3900); // from the middle pose 2900 steps one way
        const JointCalibration result = calibrateJoint(joint, CalibrationOrder::MiddlePoseFirst);
        QVERIFY(!result.ok());
        QVERIFY2(result.refusal.contains(QLatin1String("seam")), qPrintable(result.refusal));
        // ServoBench's order centres the same range.
        QVERIFY(calibrateJoint(joint, CalibrationOrder::RangeFirst).ok());
    }

    void leRobotsOrderWithoutAMiddlePoseIsRefused()
    {
        JointRecording joint = recorded({});
        sweep(joint, 1000, 2000);
        QVERIFY(!calibrateJoint(joint, CalibrationOrder::MiddlePoseFirst).ok());
    }

    void stsLimitsComeFromItsRegisterTable()
    {
        const auto limits = calibrationLimits(RegisterTable::forFamily(Family::Sts));
        QVERIFY(limits);
        QCOMPARE(limits->minimumOffset, -2047);
        QCOMPARE(limits->maximumOffset, 2047);
        QCOMPARE(limits->highestMaximumLimit, 4095);
        QVERIFY(!calibrationLimits(RegisterTable::forFamily(Family::Scs)));
    }

    void mismatchesNameTheRegisterWrittenAndRead()
    {
        const auto items = calibrationWrites(-5, 100, 4000);
        QCOMPARE(items.size(), 3);
        QCOMPARE(items.first().key, QStringLiteral("position_offset"));
        QHash<QString, qint32> read {{QStringLiteral("position_offset"), -5},
                                     {QStringLiteral("min_angle_limit"), 100},
                                     {QStringLiteral("max_angle_limit"), 3999}};
        QCOMPARE(calibrationMismatches(items, read),
                 QStringList {QStringLiteral("max_angle_limit: wrote 4000, the servo holds 3999")});
        read.insert(QStringLiteral("max_angle_limit"), 4000);
        QVERIFY(calibrationMismatches(items, read).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestArmCalibration)
#include "tst_armcalibration.moc"
