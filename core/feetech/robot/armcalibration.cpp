// Arm calibration: unwrapping the recorded motion and choosing each joint's offset and limits.
#include "armcalibration.h"

#include "lerobotcalibration.h"
#include "registertable.h"

#include <QCoreApplication>

#include <algorithm>
#include <functional>
#include <optional>

namespace {

struct ArmCalibrationTr
{
    Q_DECLARE_TR_FUNCTIONS(ArmCalibration)
};

} // namespace

namespace feetech {

namespace {

// Why nothing may be written from this recording, whichever the order; empty when it may.
QString recordingRefusal(const JointRecording &joint)
{
    const JointRangeRecorder &range = joint.range;
    if (!range.hasSamples())
        return ArmCalibrationTr::tr("no position was read from servo %1").arg(joint.id);
    if (range.isLost())
        return ArmCalibrationTr::tr("servo %1 stopped answering during the recording: record again")
            .arg(joint.id);
    if (range.span() < kMinimumMotionSteps)
        return ArmCalibrationTr::tr(
                   "the joint never moved (%1 steps; move it through its whole range)")
            .arg(range.span());
    if (!joint.fullTurn && range.span() > kEncoderSteps - kRangeSafetyMargin)
        return ArmCalibrationTr::tr(
                   "the range of %1 steps is wider than the encoder allows (%2 steps: a turn "
                   "less a safety margin of %3); is this a full-turn joint?")
            .arg(range.span())
            .arg(kEncoderSteps - kRangeSafetyMargin)
            .arg(kRangeSafetyMargin);
    if (joint.middlePose && (*joint.middlePose < 0 || *joint.middlePose >= kEncoderSteps))
        return ArmCalibrationTr::tr("the middle pose %1 is not a position of the encoder")
            .arg(*joint.middlePose);
    return {};
}

// The limits for the range [minimum, maximum] in new coordinates, or the refusal.
void setLimits(JointCalibration &result, int minimum, int maximum, const CalibrationLimits &limits)
{
    if (minimum < 0 || maximum >= kEncoderSteps) {
        result.refusal =
            ArmCalibrationTr::tr("from the middle pose, the range (%1 to %2) would cross the "
                                 "encoder's 0/4095 seam: take a middle pose nearer the middle of "
                                 "the joint's travel, or use ServoBench's order")
                .arg(minimum)
                .arg(maximum);
        return;
    }
    if (minimum > limits.highestMinimumLimit || maximum > limits.highestMaximumLimit) {
        result.refusal =
            ArmCalibrationTr::tr("the limits %1 to %2 are outside what the servo holds (at most "
                                 "%3 and %4)")
                .arg(minimum)
                .arg(maximum)
                .arg(limits.highestMinimumLimit)
                .arg(limits.highestMaximumLimit);
        return;
    }
    result.minimumLimit = minimum;
    result.maximumLimit = maximum;
}

} // namespace

int wrapToEncoder(int steps)
{
    return ((steps % kEncoderSteps) + kEncoderSteps) % kEncoderSteps;
}

int wrapSigned(int steps)
{
    const int wrapped = wrapToEncoder(steps);
    return wrapped >= kEncoderSteps / 2 ? wrapped - kEncoderSteps : wrapped;
}

void JointRangeRecorder::addSample(int present)
{
    if (m_samples == 0) {
        m_first = m_minimum = m_maximum = m_present = present;
    } else {
        // The nearest equivalent: a step of more than half a turn between two samples is the
        // seam, not the joint (a hand cannot turn a joint half a turn between two readings).
        m_present += wrapSigned(present - m_present);
        m_minimum = std::min(m_minimum, m_present);
        m_maximum = std::max(m_maximum, m_present);
    }
    ++m_samples;
}

std::optional<CalibrationLimits> calibrationLimits(const RegisterTable &table)
{
    const Register *offset = table.find(kOffsetKey);
    const Register *minimum = table.find(kMinimumLimitKey);
    const Register *maximum = table.find(kMaximumLimitKey);
    if (!offset || !minimum || !maximum || !offset->writable()
        || maximum->maximum != kEncoderSteps - 1)
        return std::nullopt;
    CalibrationLimits limits;
    limits.minimumOffset = offset->minimum;
    limits.maximumOffset = offset->maximum;
    limits.highestMinimumLimit = minimum->maximum;
    limits.highestMaximumLimit = maximum->maximum;
    return limits;
}

qint32 offsetPlacing(int physical, int target, const CalibrationLimits &limits)
{
    return std::clamp(qint32(wrapSigned(physical - target)), limits.minimumOffset,
                      limits.maximumOffset);
}

JointCalibration calibrateJoint(const JointRecording &joint, CalibrationOrder order)
{
    JointCalibration result;
    result.name = joint.name;
    result.id = joint.id;
    result.fullTurn = joint.fullTurn;
    result.refusal = recordingRefusal(joint);
    if (!result.ok())
        return result;
    const JointRangeRecorder &range = joint.range;
    // Recorded present positions are the servo's physical ones less the offset it had then.
    const int physicalMinimum = range.minimum() + joint.currentOffset;
    const int physicalMiddle = physicalMinimum + range.span() / 2;

    if (order == CalibrationOrder::MiddlePoseFirst) {
        if (!joint.middlePose) {
            result.refusal = ArmCalibrationTr::tr("no middle pose was taken for this joint");
            return result;
        }
        const int middlePose = *joint.middlePose + joint.currentOffset;
        result.offset = offsetPlacing(middlePose, kLeRobotHalfTurn, joint.limits);
        if (joint.fullTurn) {
            setLimits(result, 0, joint.limits.highestMaximumLimit, joint.limits);
            return result;
        }
        // The recording started where the middle pose left the joint (within half a turn):
        // its first sample is placed next to the middle pose, the rest follow from it.
        const int firstNew = wrapToEncoder(middlePose - result.offset)
            + wrapSigned(range.first() + joint.currentOffset - middlePose);
        setLimits(result, firstNew + range.minimum() - range.first(),
                  firstNew + range.maximum() - range.first(), joint.limits);
        return result;
    }

    if (joint.fullTurn) {
        const int centre =
            range.span() < kEncoderSteps ? physicalMiddle : range.present() + joint.currentOffset;
        result.offset = offsetPlacing(centre, kEncoderMiddle, joint.limits);
        setLimits(result, 0, joint.limits.highestMaximumLimit, joint.limits);
        return result;
    }
    result.offset = offsetPlacing(physicalMiddle, kEncoderMiddle, joint.limits);
    const int minimum = wrapToEncoder(physicalMiddle - result.offset) - range.span() / 2;
    setLimits(result, minimum, minimum + range.span(), joint.limits);
    return result;
}

int inCalibratedCoordinates(const JointRecording &joint, const JointCalibration &result,
                            int recorded)
{
    // The turn is the one that puts the middle of the recorded range between 0 and 4095.
    const int middle = joint.range.minimum() + joint.range.span() / 2;
    const int middleNew = middle + joint.currentOffset - result.offset;
    return recorded + joint.currentOffset - result.offset - (middleNew - wrapToEncoder(middleNew));
}

QVector<model::WriteItem> calibrationWrites(qint32 offset, qint32 minimumLimit, qint32 maximumLimit)
{
    // The offset first: the limits are positions in the coordinates it makes. LeRobot's limit
    // of 4096 is the register's largest value, 4095: no position reaches either.
    return {
        {QString::fromUtf16(kOffsetKey), offset},
        {QString::fromUtf16(kMinimumLimitKey), minimumLimit},
        {QString::fromUtf16(kMaximumLimitKey), std::min(maximumLimit, kLeRobotMaximumPosition)}};
}

namespace {

// Each item the servo does not hold as `say` puts it: the item, and what the servo holds (none
// when it was not read).
QStringList
unheld(const QVector<model::WriteItem> &items, const QHash<QString, qint32> &holds,
       const std::function<QString(const model::WriteItem &, std::optional<qint32>)> &say)
{
    QStringList said;
    for (const model::WriteItem &item : items) {
        const auto found = holds.constFind(item.key);
        if (found != holds.constEnd() && *found == item.value)
            continue;
        said.append(
            say(item, found != holds.constEnd() ? std::optional<qint32>(*found) : std::nullopt));
    }
    return said;
}

} // namespace

QStringList calibrationMismatches(const QVector<model::WriteItem> &items,
                                  const QHash<QString, qint32> &readBack)
{
    return unheld(items, readBack, [](const model::WriteItem &item, std::optional<qint32> held) {
        return ArmCalibrationTr::tr("%1: wrote %2, the servo holds %3")
            .arg(item.key)
            .arg(item.value)
            .arg(held ? QString::number(*held) : ArmCalibrationTr::tr("nothing"));
    });
}

QStringList calibrationDifferences(const RegisterTable &table,
                                   const QVector<model::WriteItem> &fileSays,
                                   const QHash<QString, qint32> &servoHolds)
{
    return unheld(
        fileSays, servoHolds, [&table](const model::WriteItem &item, std::optional<qint32> held) {
            const Register *reg = table.find(item.key);
            return ArmCalibrationTr::tr("%1: the file says %2, the servo holds %3")
                .arg(reg ? tableText(reg->label) : item.key)
                .arg(item.value)
                .arg(held ? QString::number(*held) : ArmCalibrationTr::tr("nothing readable"));
        });
}

} // namespace feetech
