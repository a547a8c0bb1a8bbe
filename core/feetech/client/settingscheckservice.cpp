// The settings check of the servos found and its fixes, through the bus client.
#include "settingscheckservice.h"

#include "busclient.h"
#include "busoperations.h"

namespace feetech {

SettingsCheckService::SettingsCheckService(BusClient *client)
    : QObject(client)
    , m_client(client)
{ }

Refusal SettingsCheckService::blocker() const
{
    if (!m_client->link()->isConnected())
        return Refusal(Refusal::Code::NotConnected);
    if (m_client->isBusy())
        return Refusal(Refusal::Code::Busy);
    return {};
}

OperationReply *SettingsCheckService::check(const QVector<int> &indexes,
                                            const SettingsExpectations &expected, Refusal *refusal)
{
    Refusal why = blocker();
    if (!why && indexes.isEmpty())
        why = Refusal(Refusal::Code::NoServoToCheck);
    QVector<ServoInfo> servos;
    for (const int index : indexes) {
        if (index < 0 || index >= m_client->servos()->count())
            why = Refusal(Refusal::Code::NoServo);
        else
            servos.append(m_client->servos()->at(index).info);
    }
    if (refused(why, refusal))
        return nullptr;
    m_checking = true;
    m_readings.clear();
    m_expected = expected;
    OperationReply *reply = m_client->submit(operations::checkSettings(servos, expected.keys()), 0,
                                             0, BusClient::Work::Foreground);
    connect(reply, &OperationReply::progress, this, [this](const OperationProgress &progress) {
        m_readings.append(progress.detail.value<SettingsReading>());
    });
    connect(reply, &OperationReply::finished, this, [this](const OperationResult &result) {
        m_checking = false;
        emit checked(checkSettings(m_readings, m_expected), result.ok, result.message);
    });
    return reply;
}

OperationReply *SettingsCheckService::fix(const QVector<SettingsFinding> &findings,
                                          Refusal *refusal)
{
    Refusal why = blocker();
    QVector<SettingsFinding> fixable;
    for (const SettingsFinding &finding : findings) {
        if (finding.fixable())
            fixable.append(finding);
        const int index = m_client->servos()->indexOf(finding.servo.address());
        if (!why && index >= 0 && m_client->servos()->at(index).info.sharedId)
            why = Refusal::sharedId(finding.servo.id);
    }
    if (!why && fixable.isEmpty())
        why = Refusal(Refusal::Code::NothingToWrite);
    if (refused(why, refusal))
        return nullptr;
    m_fixing = true;
    const ServoInfo &first = fixable.first().servo;
    OperationReply *reply = m_client->submit(operations::fixSettings(fixable), first.id, first.baud,
                                             BusClient::Work::Foreground);
    connect(reply, &OperationReply::finished, this, [this](const OperationResult &result) {
        m_fixing = false;
        emit fixed(result.detail.value<QVector<SettingsFixOutcome>>(), result.message);
    });
    return reply;
}

} // namespace feetech
