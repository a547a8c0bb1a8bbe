// The health check of the servos found, and its confirmed move test, through the bus client.
#include "healthservice.h"

#include "busclient.h"
#include "busoperations.h"

namespace feetech {

HealthService::HealthService(BusClient *client)
    : QObject(client)
    , m_client(client)
{ }

void HealthService::onWorkFinished(const OperationResult &result)
{
    // After the client's own bookkeeping: it is idle again when these are heard.
    if (result.operation == Operation::HealthCheck && m_checking) {
        m_checking = false;
        emit checkFinished(result.ok, result.message);
    } else if (result.operation == Operation::MoveTest) {
        MoveTestResult reported = result.detail.value<MoveTestResult>();
        if (!result.detail.canConvert<MoveTestResult>()) { // the link went down under it
            reported.id = result.servo.id;
            reported.baud = result.servo.baud;
            reported.message = result.message;
        }
        emit moveTested(reported);
    }
}

OperationReply *HealthService::check(const QVector<int> &indexes, int reads, Refusal *refusal)
{
    Refusal why;
    if (!m_client->link()->isConnected())
        why = Refusal(Refusal::Code::NotConnected);
    else if (m_client->isBusy())
        why = Refusal(Refusal::Code::Busy);
    else if (indexes.isEmpty())
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
    // Several servos, none of them the target: the check reports each on its own.
    OperationReply *reply =
        m_client->submit(operations::checkHealth(servos, reads), 0, 0, BusClient::Work::Foreground);
    connect(reply, &OperationReply::progress, this, [this](const OperationProgress &progress) {
        emit reading(progress.detail.value<HealthReading>(), progress.done, progress.total);
    });
    connect(reply, &OperationReply::finished, this, &HealthService::onWorkFinished);
    return reply;
}

void HealthService::cancel()
{
    // Not queued behind the check: the flag must be seen while it runs.
    Session *session = m_client->session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancel(Operation::HealthCheck); }, Qt::QueuedConnection);
}

Refusal HealthService::moveTestBlocker(int index) const
{
    return m_client->identify()->blocker(index);
}

OperationReply *HealthService::moveTest(int index, bool confirmed, Refusal *refusal)
{
    Refusal why = moveTestBlocker(index);
    if (!why && !confirmed)
        why = Refusal::notConfirmed(m_client->servos()->at(index).info.id);
    if (refused(why, refusal))
        return nullptr;
    OperationReply *reply = m_client->startOperation(
        Operation::MoveTest, index, refusal, BusClient::Work::Foreground, &operations::moveTest);
    if (reply)
        connect(reply, &OperationReply::finished, this, &HealthService::onWorkFinished);
    return reply;
}

} // namespace feetech
