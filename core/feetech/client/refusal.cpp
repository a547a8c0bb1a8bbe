// The refusals of the bus client and its services, and their sentences.
#include "refusal.h"

#include "sharedidcheck.h"

#include <QCoreApplication>

namespace {

// The context the client's sentences have always been translated in.
struct FeetechBusClientTr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

Refusal Refusal::sharedId(quint8 servoId)
{
    return Refusal(Code::SharedId, servoId, 0, {});
}

Refusal Refusal::unknownModel(quint8 servoId)
{
    return Refusal(Code::UnknownModel, servoId, 0, {});
}

Refusal Refusal::servoHeld(const QString &holderReason)
{
    return Refusal(Code::ServoHeld, std::nullopt, 0, holderReason);
}

Refusal Refusal::idInUse(int id)
{
    return Refusal(Code::IdInUse, std::nullopt, id, {});
}

Refusal Refusal::badValue(const QString &reason)
{
    return Refusal(Code::BadValue, std::nullopt, 0, reason);
}

Refusal Refusal::badValue(quint8 servoId, const QString &reason)
{
    return Refusal(Code::BadValue, servoId, 0, reason);
}

Refusal Refusal::notAFeetechRate(qint32 baud)
{
    return Refusal(Code::NotAFeetechRate, std::nullopt, baud, {});
}

Refusal Refusal::notConfirmed(quint8 servoId)
{
    return Refusal(Code::NotConfirmed, servoId, 0, {});
}

Refusal Refusal::undecodableFeedback(quint8 servoId)
{
    return Refusal(Code::UndecodableFeedback, servoId, 0, {});
}

Refusal Refusal::jointNotFound(quint8 servoId)
{
    return Refusal(Code::JointNotFound, servoId, 0, {});
}

QString Refusal::describe() const
{
    const int id = m_servoId.value_or(0);
    switch (m_code) {
    case Code::None:
        return {};
    case Code::NotConnected:
        return FeetechBusClientTr::tr("The bus is not connected.");
    case Code::NoServo:
        return FeetechBusClientTr::tr("No servo is selected.");
    case Code::SharedId:
        return sharedIdRefusal(quint8(id));
    case Code::UnknownModel:
        if (m_servoId)
            return FeetechBusClientTr::tr(
                       "Servo %1 is of an unknown model; nothing is written to it.")
                .arg(id);
        return FeetechBusClientTr::tr(
            "This servo's model is unknown; its memory is shown read-only.");
    case Code::Busy:
        return FeetechBusClientTr::tr("Another operation is still running.");
    case Code::ServoHeld:
        return m_detail;
    case Code::NotMovable:
        return FeetechBusClientTr::tr(
            "This servo has no goal position register: it cannot be moved.");
    case Code::NoMiddleCalibration:
        return FeetechBusClientTr::tr(
            "This servo has no middle calibration (SCS servos have no offset "
            "register).");
    case Code::NoStatusRegister:
        return FeetechBusClientTr::tr(
            "This servo has no status register: there is nothing to recover.");
    case Code::IdInUse:
        return FeetechBusClientTr::tr("ID %1 is already in use on this bus.").arg(m_value);
    case Code::NothingToWrite:
        return FeetechBusClientTr::tr("Nothing to write.");
    case Code::NothingToMove:
        return FeetechBusClientTr::tr("Nothing to move.");
    case Code::BadValue:
        if (m_servoId)
            return FeetechBusClientTr::tr("Servo %1: %2").arg(id).arg(m_detail);
        return m_detail;
    case Code::NotAFrame:
        return FeetechBusClientTr::tr(
            "That is not a whole Feetech frame (header, length and checksum).");
    case Code::NotAFeetechRate:
        return FeetechBusClientTr::tr("%1 bps is not a Feetech baud rate.").arg(m_value);
    case Code::NoServoToCheck:
        return FeetechBusClientTr::tr("No servo to check: scan the bus first.");
    case Code::NotConfirmed:
        return FeetechBusClientTr::tr(
                   "The move test moves servo %1: it runs only once that is confirmed.")
            .arg(id);
    case Code::NoServoToMonitor:
        return FeetechBusClientTr::tr("Choose at least one servo to monitor.");
    case Code::NegativeRate:
        return FeetechBusClientTr::tr("The rate cannot be negative.");
    case Code::UndecodableFeedback:
        return FeetechBusClientTr::tr(
                   "Servo %1 is of an unknown model: its feedback cannot be decoded.")
            .arg(id);
    case Code::JointNotFound:
        return FeetechBusClientTr::tr(
                   "The recording moves servo %1, which the scan did not find: nothing was "
                   "moved.")
            .arg(id);
    case Code::SeveralRates:
        return FeetechBusClientTr::tr(
            "The servos to record answer at different baud rates: choose servos at "
            "one rate.");
    case Code::BusShared:
        return FeetechBusClientTr::tr(
            "The bus is shared with another program: this would change the port's rate "
            "under it. Stop sharing first.");
    case Code::AlreadyShared:
        return FeetechBusClientTr::tr("The bus is shared already.");
    case Code::NoSharePath:
        return FeetechBusClientTr::tr("Name the path the other program opens.");
    }
    return {};
}

bool refused(const Refusal &refusal, Refusal *out)
{
    if (!refusal)
        return false;
    if (out)
        *out = refusal;
    return true;
}

} // namespace feetech
