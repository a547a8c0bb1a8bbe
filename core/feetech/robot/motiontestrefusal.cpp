// The refusals of a motion test, and their sentences.
#include "motiontestrefusal.h"

#include <QCoreApplication>

namespace {

struct MotionTestRefusalTr
{
    Q_DECLARE_TR_FUNCTIONS(MotionTestRefusal)
};

} // namespace

namespace feetech {

MotionTestRefusal MotionTestRefusal::beingIdentified(quint8 servoId)
{
    MotionTestRefusal refusal(Code::BeingIdentified);
    refusal.m_servoId = servoId;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::notInPositionMode(quint8 servoId)
{
    MotionTestRefusal refusal(Code::NotInPositionMode);
    refusal.m_servoId = servoId;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::outsideRange(qint32 from, qint32 to,
                                                  const PositionRange &range)
{
    MotionTestRefusal refusal(Code::OutsideRange);
    refusal.m_from = from;
    refusal.m_to = to;
    refusal.m_range = range;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::tooClose(double reachTolerance)
{
    MotionTestRefusal refusal(Code::TooClose);
    refusal.m_limit = reachTolerance;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::settingOutOfRange(const QString &label, qint64 minimum,
                                                       qint64 maximum)
{
    MotionTestRefusal refusal(Code::SettingOutOfRange);
    refusal.m_label = label;
    refusal.m_minimum = minimum;
    refusal.m_maximum = maximum;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::badRecordLength(double maximumSeconds)
{
    MotionTestRefusal refusal(Code::BadRecordLength);
    refusal.m_limit = maximumSeconds;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::badLegCount(int maximumLegs)
{
    MotionTestRefusal refusal(Code::BadLegCount);
    refusal.m_maximum = maximumLegs;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::servoGone(quint8 servoId)
{
    MotionTestRefusal refusal(Code::ServoGone);
    refusal.m_servoId = servoId;
    return refusal;
}

MotionTestRefusal MotionTestRefusal::clientRefused(const Refusal &refusal)
{
    MotionTestRefusal refused(Code::ClientRefused);
    refused.m_clientRefusal = refusal;
    return refused;
}

QString MotionTestRefusal::describe() const
{
    switch (m_code) {
    case Code::None:
        return {};
    case Code::AlreadyRunning:
        return MotionTestRefusalTr::tr("A test is already running.");
    case Code::NotConnected:
        return MotionTestRefusalTr::tr("The bus is not connected.");
    case Code::NoServo:
        return MotionTestRefusalTr::tr("No servo is selected.");
    case Code::BeingIdentified:
        return MotionTestRefusalTr::tr("Servo ID %1 is being identified; wait until it is back.")
            .arg(m_servoId);
    case Code::UnknownModel:
        return MotionTestRefusalTr::tr(
            "This servo's model is unknown: ServoBench does not move it.");
    case Code::NotMovable:
        return MotionTestRefusalTr::tr("This servo has no goal position register.");
    case Code::NotInPositionMode:
        return MotionTestRefusalTr::tr(
                   "Servo ID %1 is not in position mode: set its operating mode to "
                   "position first.")
            .arg(m_servoId);
    case Code::OutsideRange: {
        const QString limits = m_range.fromAngleLimits
            ? MotionTestRefusalTr::tr("the servo's angle limits")
            : MotionTestRefusalTr::tr("the goal position range");
        return MotionTestRefusalTr::tr("From (%1) and to (%2) must lie within %3, %4 to %5 steps.")
            .arg(m_from)
            .arg(m_to)
            .arg(limits)
            .arg(m_range.minimum)
            .arg(m_range.maximum);
    }
    case Code::TooClose:
        return MotionTestRefusalTr::tr("From and to must be more than %1 steps apart.")
            .arg(m_limit);
    case Code::SettingOutOfRange:
        return MotionTestRefusalTr::tr("%1 must lie between %2 and %3.")
            .arg(m_label)
            .arg(m_minimum)
            .arg(m_maximum);
    case Code::BadRecordLength:
        return MotionTestRefusalTr::tr(
                   "The recording must last more than 0 and at most %1 seconds.")
            .arg(m_limit);
    case Code::BadLegCount:
        return MotionTestRefusalTr::tr("A sweep has 1 to %1 legs.").arg(m_maximum);
    case Code::ServoGone:
        return MotionTestRefusalTr::tr("%1 is no longer on the bus.")
            .arg(MotionTestRefusalTr::tr("Servo ID %1").arg(m_servoId));
    case Code::ClientRefused:
        return m_clientRefusal.describe();
    }
    return {};
}

} // namespace feetech
