// Identify a joint through the bus client, and the servos held by what moves them meanwhile.
#include "identifyservice.h"

#include "busclient.h"
#include "busoperations.h"

namespace feetech {

IdentifyService::IdentifyService(BusClient *client)
    : QObject(client)
    , m_client(client)
{
    // A link that went down ends the identify with it.
    connect(client->link(), &seriallink::LinkMirror::statusChanged, this,
            [this](const auto &status) {
                if (status.state == seriallink::ConnectionState::Disconnected
                    || status.state == seriallink::ConnectionState::Lost)
                    m_running.reset();
            });
}

Refusal IdentifyService::blocker(int index) const
{
    if (const Refusal blocker = m_client->writeBlocker(index))
        return blocker;
    const ServoInfo &info = m_client->servos()->at(index).info;
    const QString held = m_held.value(info.address());
    if (!held.isEmpty())
        return Refusal::servoHeld(held);
    if (!info.table().find(u"goal_position") || !info.table().find(u"torque_enable"))
        return Refusal(Refusal::Code::NotMovable);
    return {};
}

OperationReply *IdentifyService::start(int index, Refusal *refusal)
{
    if (refused(blocker(index), refusal))
        return nullptr;
    const ServoAddress address = m_client->servos()->at(index).info.address();
    OperationReply *reply =
        m_client->startOperation(Operation::Identify, index, refusal, BusClient::Work::Foreground,
                                 &operations::identifyJoint);
    if (!reply)
        return nullptr;
    m_running = address;
    connect(reply, &OperationReply::finished, this, [this] { m_running.reset(); });
    return reply;
}

bool IdentifyService::isRunning(int index) const
{
    return m_running && index >= 0 && index < m_client->servos()->count()
        && *m_running == m_client->servos()->at(index).info.address();
}

void IdentifyService::hold(int index, const QString &reason)
{
    if (index < 0 || index >= m_client->servos()->count())
        return;
    m_held.insert(m_client->servos()->at(index).info.address(), reason);
    m_client->servos()->noteUpdated(index); // what it may do now has changed
}

void IdentifyService::release(const ServoAddress &address)
{
    const int index = m_client->servos()->indexOf(address);
    if (m_held.remove(address) > 0 && index >= 0)
        m_client->servos()->noteUpdated(index);
}

} // namespace feetech
