// The overload and thermal guard's settings for the servos found, its news, and the recovery of
// a servo whose overload protection tripped.
#include "busguard.h"

#include "busclient.h"
#include "busoperations.h"

namespace feetech {

BusGuard::BusGuard(BusClient *client)
    : QObject(client)
    , m_client(client)
{
    qRegisterMetaType<feetech::GuardEvent>();
    qRegisterMetaType<feetech::GuardSettings>();
    connect(client->session(), &Session::guardEvent, this, [this](const GuardEvent &guarded) {
        m_lastEvent.insert({guarded.id, guarded.baud}, guarded);
        emit event(guarded);
        const int index = m_client->servos()->indexOf({guarded.id, guarded.baud});
        if (index >= 0)
            m_client->servos()->noteUpdated(index);
    });
    // The servo's own limit registers, once read, give its defaults.
    connect(client->servos(), &ServoList::servoUpdated, this, [this] { send(); });
    connect(client->servos(), &ServoList::servosChanged, this, [this] {
        m_lastEvent.clear();
        send();
    });
}

GuardLimits BusGuard::limits(int index) const
{
    if (index < 0 || index >= m_client->servos()->count()
        || !m_client->servos()->at(index).info.hasTable())
        return {};
    const Servo &entry = m_client->servos()->at(index);
    const auto set = m_settings.servos.constFind({entry.info.id, entry.info.baud});
    if (set != m_settings.servos.constEnd())
        return *set;
    return defaults(index);
}

GuardLimits BusGuard::defaults(int index) const
{
    if (index < 0 || index >= m_client->servos()->count()
        || !m_client->servos()->at(index).info.hasTable())
        return {};
    const Servo &entry = m_client->servos()->at(index);
    const model::ParameterModel *parameters = entry.parameters.get();
    return defaultGuardLimits(
        entry.info.table(), [parameters](QStringView key) -> std::optional<qint32> {
            const auto value = parameters->deviceValue(key.toString());
            return value ? std::optional<qint32>(qint32(*value)) : std::nullopt;
        });
}

void BusGuard::setSettings(const GuardSettings &settings)
{
    m_settings = settings;
    send();
}

void BusGuard::send()
{
    GuardSettings settings;
    settings.enabled = m_settings.enabled;
    for (int i = 0; i < m_client->servos()->count(); ++i) {
        if (m_client->servos()->at(i).info.hasTable())
            settings.servos.insert(
                {m_client->servos()->at(i).info.id, m_client->servos()->at(i).info.baud},
                limits(i));
    }
    if (m_sent && m_sent->enabled == settings.enabled && m_sent->servos == settings.servos)
        return;
    m_sent = settings;
    m_client->runInSession([settings](Session &s) { s.setGuardSettings(settings); });
}

std::optional<GuardEvent> BusGuard::lastEvent(int index) const
{
    if (index < 0 || index >= m_client->servos()->count())
        return std::nullopt;
    const auto event = m_lastEvent.constFind(m_client->servos()->at(index).info.address());
    if (event == m_lastEvent.constEnd())
        return std::nullopt;
    return *event;
}

OperationReply *BusGuard::recoverOverload(int index, bool checkOnly, Refusal *refusal)
{
    if (refused(m_client->writeBlocker(index), refusal))
        return nullptr;
    if (!m_client->servos()->at(index).info.table().find(u"status")) {
        refused(Refusal(Refusal::Code::NoStatusRegister), refusal);
        return nullptr;
    }
    return m_client->startOperation(Operation::RecoverOverload, index, refusal,
                                    BusClient::Work::Foreground,
                                    [checkOnly](const ServoInfo &info) {
                                        return operations::recoverOverload(info, checkOnly);
                                    });
}

} // namespace feetech
