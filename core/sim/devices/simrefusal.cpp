// The simulated devices' refusals, and their sentences.
#include "simrefusal.h"

#include "feetechpacket.h"
#include "hand.h"
#include "virtualfeetechbustr.h"
#include "virtualfeetechservo.h"

#include <QCoreApplication>
#include <QStringList>

namespace {

// The context the hand's sentences have always been translated in.
struct HandRefusalTr
{
    Q_DECLARE_TR_FUNCTIONS(Hand)
};

// The context the demo's sentences have always been translated in.
struct DemoTr
{
    Q_DECLARE_TR_FUNCTIONS(DemoServos)
};

QString baudList()
{
    QStringList rates;
    for (int code = 0; sim::VirtualFeetechServo::baudForCode(code) != 0; ++code)
        rates.append(QString::number(sim::VirtualFeetechServo::baudForCode(code)));
    return rates.join(QLatin1String(", "));
}

} // namespace

namespace sim {

SimRefusal SimRefusal::ofServo(Code code, int place, int id, qint64 value, qint64 other)
{
    SimRefusal refusal(code, place, value);
    refusal.m_id = id;
    refusal.m_other = other;
    return refusal;
}

SimRefusal SimRefusal::stateFile(Code code, const QString &file, int servo, qint64 value,
                                 qint64 other, const QString &name, const QString &busModel)
{
    SimRefusal refusal(code, servo, value, name);
    refusal.m_other = other;
    refusal.m_busModel = busModel;
    refusal.m_file = file;
    return refusal;
}

QString SimRefusal::describe() const
{
    switch (m_code) {
    case Code::None:
        return {};
    case Code::NoServos:
        return VirtualFeetechBusTr::tr("a Feetech bus needs at least one servo");
    case Code::UnknownModel:
        return VirtualFeetechBusTr::tr("servo %1: unknown model \"%2\"").arg(m_servo).arg(m_name);
    case Code::NoRegisterTable:
        return VirtualFeetechBusTr::tr("servo %1: model %2 has no register table to simulate")
            .arg(m_servo)
            .arg(m_name);
    case Code::IdOutOfRange:
        return VirtualFeetechBusTr::tr("servo ID %1 is out of range: IDs are 0 to %2")
            .arg(m_servo)
            .arg(feetech::kMaxServoId);
    case Code::NotAFeetechRate:
        return VirtualFeetechBusTr::tr("servo %1: %2 bps is not a Feetech baud rate (%3)")
            .arg(m_servo)
            .arg(m_value)
            .arg(baudList());
    case Code::IdTaken:
        return VirtualFeetechBusTr::tr("two servos have ID %1 at %2 bps").arg(m_servo).arg(m_value);
    case Code::NoSuchPlace:
        return VirtualFeetechBusTr::tr("there is no servo #%1 on the bus (it has %2)")
            .arg(m_servo)
            .arg(m_value);
    case Code::NoSuchId:
        return VirtualFeetechBusTr::tr("no servo has ID %1").arg(m_servo);
    case Code::SharedId:
        return VirtualFeetechBusTr::tr("servos %1 share ID %2: name one by its place, as #N")
            .arg(m_name)
            .arg(m_servo);
    case Code::CannotWriteState:
        return VirtualFeetechBusTr::tr("cannot write the state file %1: %2").arg(m_file, m_name);
    case Code::CannotReadState:
    case Code::StateNotJson:
    case Code::StateNotThisFormat:
    case Code::StateServoCount:
    case Code::StateModelDiffers:
    case Code::StateImageSize:
    case Code::StateImageModel:
    case Code::StateImageIdOrBaud:
        return VirtualFeetechBusTr::tr("state file %1: %2").arg(m_file, stateReason());
    case Code::PositionOutOfRange:
        return HandRefusalTr::tr("position %1 is out of range: %2 turns from 0 to %3")
            .arg(m_value)
            .arg(Hand::describe(m_servo - 1, m_id))
            .arg(m_other);
    case Code::TorqueOn:
        return HandRefusalTr::tr(
                   "%1 has its torque on: it holds its position and the hand cannot turn it")
            .arg(Hand::describe(m_servo - 1, m_id));
    case Code::SweepTooLong:
        return HandRefusalTr::tr("a sweep takes more than 0 and at most %1 seconds")
            .arg(Hand::kMaxSweepSeconds);
    case Code::TooManyCycles:
        return HandRefusalTr::tr("a sweep runs 0 (until released) to %1 times")
            .arg(Hand::kMaxSweepCycles);
    case Code::NoSeam:
        return HandRefusalTr::tr("%1 is an SCS servo: it stops at 0 and %2, there is no "
                                 "seam to sweep across")
            .arg(Hand::describe(m_servo - 1, m_id))
            .arg(m_other);
    case Code::BadPtkValues:
        return QStringLiteral("--values: ") + m_name;
    case Code::NoDemoFolder:
        return DemoTr::tr("Cannot create a folder for the simulated servos: %1").arg(m_name);
    case Code::NoDemoRobot:
    case Code::DemoNotStarted:
        return m_name;
    }
    return {};
}

QString SimRefusal::stateReason() const
{
    switch (m_code) {
    case Code::CannotReadState:
        return m_name;
    case Code::StateNotJson:
        return VirtualFeetechBusTr::tr("not valid JSON (%1)").arg(m_name);
    case Code::StateNotThisFormat:
        return VirtualFeetechBusTr::tr("not a format %1 simulator state").arg(m_value);
    case Code::StateServoCount:
        return VirtualFeetechBusTr::tr("it holds %1 servos, the bus has %2")
            .arg(m_value)
            .arg(m_other);
    case Code::StateModelDiffers:
        return VirtualFeetechBusTr::tr("servo %1 is a %2 in the file but a %3 on the bus")
            .arg(m_servo)
            .arg(m_name, m_busModel);
    case Code::StateImageSize:
        return VirtualFeetechBusTr::tr("servo %1: the EEPROM image is not %2 hex bytes")
            .arg(m_servo)
            .arg(m_value);
    case Code::StateImageModel:
        return VirtualFeetechBusTr::tr("servo %1: the EEPROM image is of model %2/%3, not %4")
            .arg(m_servo)
            .arg(m_value)
            .arg(m_other)
            .arg(m_busModel);
    case Code::StateImageIdOrBaud:
        return VirtualFeetechBusTr::tr(
                   "servo %1: the EEPROM image holds an invalid ID or baud code")
            .arg(m_servo);
    default:
        return {};
    }
}

bool refused(const SimRefusal &refusal, SimRefusal *out)
{
    if (!refusal)
        return false;
    if (out)
        *out = refusal;
    return true;
}

} // namespace sim
