// The servo commands that are no register edits, submitted through the bus client.
#include "servocommands.h"

#include "busclient.h"
#include "busoperations.h"
#include "feetechpacket.h"
#include "registertable.h"

namespace feetech {

ServoCommands::ServoCommands(BusClient *client)
    : QObject(client)
    , m_client(client)
{ }

Refusal ServoCommands::blocker(int index) const
{
    // An unknown model may be rebooted or cleared; a shared ID is not sent anything.
    const ServoList *servos = m_client->servos();
    if (index >= 0 && index < servos->count() && servos->at(index).info.sharedId)
        return Refusal::sharedId(servos->at(index).info.id);
    if (m_client->isBusy())
        return Refusal(Refusal::Code::Busy);
    return {};
}

OperationReply *ServoCommands::calibrateMiddle(int index, Refusal *refusal)
{
    if (refused(m_client->writeBlocker(index), refusal))
        return nullptr;
    if (middleCalibration(m_client->servos()->at(index).info) == MiddleCalibration::Unsupported) {
        refused(Refusal(Refusal::Code::NoMiddleCalibration), refusal);
        return nullptr;
    }
    return m_client->startOperation(Operation::CalibrateMiddle, index, refusal,
                                    BusClient::Work::Foreground, &operations::calibrateMiddle);
}

OperationReply *ServoCommands::factoryReset(int index, Refusal *refusal)
{
    if (refused(m_client->writeBlocker(index), refusal))
        return nullptr;
    if (refused(m_client->share()->isActive() ? Refusal(Refusal::Code::BusShared) : Refusal(),
                refusal))
        return nullptr;
    return m_client->startOperation(Operation::FactoryReset, index, refusal,
                                    BusClient::Work::Foreground, &operations::factoryReset);
}

OperationReply *ServoCommands::reboot(int index, Refusal *refusal)
{
    if (refused(blocker(index), refusal))
        return nullptr;
    return m_client->startOperation(Operation::Reboot, index, refusal, BusClient::Work::Foreground,
                                    &operations::reboot);
}

OperationReply *ServoCommands::clearStatus(int index, Refusal *refusal)
{
    if (refused(blocker(index), refusal))
        return nullptr;
    return m_client->startOperation(Operation::ClearStatus, index, refusal,
                                    BusClient::Work::Foreground, &operations::clearStatus);
}

OperationReply *ServoCommands::lockEeprom(int index, Refusal *refusal)
{
    if (refused(m_client->isBusy() ? Refusal(Refusal::Code::Busy) : Refusal(), refusal))
        return nullptr;
    return m_client->startOperation(Operation::LockEeprom, index, refusal,
                                    BusClient::Work::Foreground, &operations::lockEeprom);
}

OperationReply *ServoCommands::sendPacket(const QByteArray &frame, qint32 baud,
                                          std::optional<quint8> replyId, int replyDataSize,
                                          Refusal *refusal)
{
    Refusal why;
    if (!m_client->link()->isConnected())
        why = Refusal(Refusal::Code::NotConnected);
    else if (!decodePacket(frame))
        why = Refusal(Refusal::Code::NotAFrame);
    else if (!baudCode(baud))
        why = Refusal::notAFeetechRate(baud);
    if (refused(why, refusal))
        return nullptr;
    return m_client->submit(operations::sendPacket(frame, baud, replyId, replyDataSize),
                            replyId.value_or(kBroadcastId), baud, BusClient::Work::Foreground);
}

} // namespace feetech
