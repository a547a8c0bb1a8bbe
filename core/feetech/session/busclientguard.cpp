// Feetech bus client: the overload and thermal guard's settings, its news, and the recovery of
// a servo whose overload protection tripped.
#include "busclient.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

void BusClient::connectGuard(Session *session)
{
    qRegisterMetaType<feetech::GuardEvent>();
    qRegisterMetaType<feetech::GuardSettings>();
    connect(session, &Session::guardEvent, this, [this](const GuardEvent &event) {
        m_lastGuardEvent.insert({event.id, event.baud}, event);
        emit guardEvent(event);
        const int index = indexOf(event.id, event.baud);
        if (index >= 0)
            emit servoUpdated(index);
    });
    // The servo's own limit registers, once read, give its defaults.
    connect(this, &BusClient::servoUpdated, this, [this] { sendGuardSettings(); });
    connect(this, &BusClient::servosChanged, this, [this] {
        m_lastGuardEvent.clear();
        sendGuardSettings();
    });
}

bool BusClient::eepromUnlocked(int index) const
{
    if (index < 0 || index >= servoCount() || !servo(index).read)
        return false;
    const model::ParameterModel *model = servo(index).parameters.get();
    const auto lock = model ? model->deviceValue(QStringLiteral("lock")) : std::nullopt;
    return lock && *lock == 0;
}

GuardLimits BusClient::guardLimits(int index) const
{
    if (index < 0 || index >= servoCount() || !servo(index).info.hasTable())
        return {};
    const Servo &entry = servo(index);
    const auto set = m_guardSettings.servos.constFind({entry.info.id, entry.info.baud});
    if (set != m_guardSettings.servos.constEnd())
        return *set;
    return guardDefaults(index);
}

GuardLimits BusClient::guardDefaults(int index) const
{
    if (index < 0 || index >= servoCount() || !servo(index).info.hasTable())
        return {};
    const Servo &entry = servo(index);
    const model::ParameterModel *parameters = entry.parameters.get();
    return defaultGuardLimits(
        entry.info.table(), [parameters](QStringView key) -> std::optional<qint32> {
            const auto value = parameters->deviceValue(key.toString());
            return value ? std::optional<qint32>(qint32(*value)) : std::nullopt;
        });
}

void BusClient::setGuardSettings(const GuardSettings &settings)
{
    m_guardSettings = settings;
    sendGuardSettings();
}

void BusClient::sendGuardSettings()
{
    GuardSettings settings;
    settings.enabled = m_guardSettings.enabled;
    for (int i = 0; i < servoCount(); ++i) {
        if (servo(i).info.hasTable())
            settings.servos.insert({servo(i).info.id, servo(i).info.baud}, guardLimits(i));
    }
    if (m_guardSent && m_guardSent->enabled == settings.enabled
        && m_guardSent->servos == settings.servos)
        return;
    m_guardSent = settings;
    m_worker.run([settings](Session &s) { s.setGuardSettings(settings); });
}

std::optional<GuardEvent> BusClient::lastGuardEvent(int index) const
{
    if (index < 0 || index >= servoCount())
        return std::nullopt;
    const auto event = m_lastGuardEvent.constFind({servo(index).info.id, servo(index).info.baud});
    if (event == m_lastGuardEvent.constEnd())
        return std::nullopt;
    return *event;
}

OperationReply *BusClient::recoverOverload(int index, bool checkOnly, QString *error)
{
    const QString blocker = writeBlocker(index);
    if (!blocker.isEmpty()) {
        if (error)
            *error = blocker;
        return nullptr;
    }
    if (!servo(index).info.table().find(u"status")) {
        if (error)
            *error = Tr::tr("This servo has no status register: there is nothing to recover.");
        return nullptr;
    }
    return startOperation(
        Operation::RecoverOverload, index, error, Work::Foreground,
        [checkOnly](Session &s, const ServoInfo &info) { s.recoverOverload(info, checkOnly); });
}

} // namespace feetech
