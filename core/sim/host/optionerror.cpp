// servosim's refusals of option values, and their sentences.
#include "optionerror.h"

#include "feetechpacket.h"
#include "hand.h"
#include "servosimtr.h"

#include <QCoreApplication>

namespace {

// The contexts the sentences have always been translated in.
struct FaultsTr
{
    Q_DECLARE_TR_FUNCTIONS(Faults)
};

} // namespace

namespace sim {

QString OptionError::describe() const
{
    switch (m_code) {
    case Code::None:
        return {};
    case Code::FaultNotNameValue:
        return FaultsTr::tr("--faults: \"%1\" is not NAME=VALUE").arg(m_text);
    case Code::FaultNotANumber:
        return FaultsTr::tr("--faults: \"%1\" is not a number").arg(m_text);
    case Code::FaultDelayOutOfRange:
        return FaultsTr::tr("--faults: delay is in milliseconds, 0 to 60000");
    case Code::FaultNotAProbability:
        return FaultsTr::tr("--faults: %1 is a probability from 0 to 1").arg(m_text);
    case Code::UnknownFault:
        return FaultsTr::tr("--faults: unknown fault \"%1\" (drop, corrupt, truncate, noise, "
                            "delay, lost)")
            .arg(m_text);
    case Code::NotAServoSpec:
        return ServosimTr::tr("%1 \"%2\" is not ID:MODEL[@BAUD]").arg(m_source, m_text);
    case Code::ServoIdOverMax:
        return ServosimTr::tr("%1 \"%2\": ID %3 is over %4")
            .arg(m_source, m_text)
            .arg(m_value)
            .arg(feetech::kMaxServoId);
    case Code::ServoWithoutModel:
        return ServosimTr::tr("%1 \"%2\" names no model").arg(m_source, m_text);
    case Code::ServoBadBaud:
        return ServosimTr::tr("%1 \"%2\": bad baud rate").arg(m_source, m_text);
    case Code::SweepFields:
    case Code::SweepBadId:
    case Code::SweepBadPositions:
    case Code::SweepBadSeconds:
    case Code::SweepBadCycles:
        return QStringLiteral("%1: %2").arg(m_source, sweepReason());
    case Code::UnknownRobot:
        return ServosimTr::tr("unknown robot \"%1\": use %2")
            .arg(m_text, simulatedRobotNames().join(u", "));
    case Code::BadRobotTemplate:
        return m_text;
    }
    return {};
}

QStringList OptionError::simulatedRobotNames()
{
    return {QStringLiteral("so101"), QStringLiteral("so100"), QStringLiteral("so101-leader"),
            QStringLiteral("so100-leader")};
}

QString OptionError::sweepReason() const
{
    switch (m_code) {
    case Code::SweepFields:
        return ServosimTr::tr("expected ID FROM TO SECONDS [CYCLES] [up|down]");
    case Code::SweepBadId:
        return ServosimTr::tr("the ID must be 0 to %1, not \"%2\"")
            .arg(feetech::kMaxServoId)
            .arg(m_text);
    case Code::SweepBadPositions:
        return ServosimTr::tr("FROM and TO must be positions from 0 to 4095");
    case Code::SweepBadSeconds:
        return ServosimTr::tr("SECONDS must be a number above 0 and at most %1, not \"%2\"")
            .arg(Hand::kMaxSweepSeconds)
            .arg(m_text);
    case Code::SweepBadCycles:
        return ServosimTr::tr(
                   "CYCLES must be a whole number from 0 (until released) to %1, not \"%2\"")
            .arg(Hand::kMaxSweepCycles)
            .arg(m_text);
    default:
        return {};
    }
}

bool refused(const OptionError &error, OptionError *out)
{
    if (!error)
        return false;
    if (out)
        *out = error;
    return true;
}

} // namespace sim
