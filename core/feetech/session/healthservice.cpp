// The health check of the servos found, and its confirmed move test, through the bus client.
#include "healthservice.h"

#include "busclient.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

HealthService::HealthService(BusClient *client)
    : QObject(client)
    , m_client(client)
{
    connect(client->session(), &Session::healthRead, this, &HealthService::reading);
    connect(client->session(), &Session::moveTested, this,
            [this](const MoveTestResult &result) { m_moveTested = result; });
}

void HealthService::onWorkFinished(const OperationResult &result)
{
    // After the client's own bookkeeping: it is idle again when these are heard.
    if (result.operation == Operation::HealthCheck && m_checking) {
        m_checking = false;
        emit checkFinished(result.ok, result.message);
    } else if (result.operation == Operation::MoveTest) {
        MoveTestResult reported = m_moveTested.value_or(MoveTestResult {});
        if (!m_moveTested) { // the link went down under it
            reported.id = result.servo.id;
            reported.baud = result.servo.baud;
            reported.message = result.message;
        }
        m_moveTested.reset();
        emit moveTested(reported);
    }
}

OperationReply *HealthService::check(const QVector<int> &indexes, int reads, QString *error)
{
    QString why;
    if (!m_client->isConnected())
        why = Tr::tr("The bus is not connected.");
    else if (m_client->isBusy())
        why = Tr::tr("Another operation is still running.");
    else if (indexes.isEmpty())
        why = Tr::tr("No servo to check: scan the bus first.");
    QVector<ServoInfo> servos;
    for (const int index : indexes) {
        if (index < 0 || index >= m_client->servos()->count())
            why = Tr::tr("No servo is selected.");
        else
            servos.append(m_client->servos()->at(index).info);
    }
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return nullptr;
    }
    m_checking = true;
    // Several servos, none of them the target: the check reports each on its own.
    OperationReply *reply =
        m_client->submit(Operation::HealthCheck, 0, 0, BusClient::Work::Foreground,
                         [servos, reads](Session &s) { s.checkHealth(servos, reads); });
    connect(reply, &OperationReply::finished, this, &HealthService::onWorkFinished);
    return reply;
}

void HealthService::cancel()
{
    // Not queued behind the check: the flag must be seen while it runs.
    Session *session = m_client->session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancelHealthCheck(); }, Qt::QueuedConnection);
}

QString HealthService::moveTestBlocker(int index) const
{
    return m_client->identifyBlocker(index).describe();
}

OperationReply *HealthService::moveTest(int index, bool confirmed, QString *error)
{
    QString why = moveTestBlocker(index);
    if (why.isEmpty() && !confirmed)
        why = Tr::tr("The move test moves servo %1: it runs only once that is confirmed.")
                  .arg(m_client->servos()->at(index).info.id);
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return nullptr;
    }
    m_moveTested.reset();
    Refusal refusal;
    OperationReply *reply =
        m_client->startOperation(Operation::MoveTest, index, &refusal, BusClient::Work::Foreground,
                                 [](Session &s, const ServoInfo &target) { s.moveTest(target); });
    if (reply)
        connect(reply, &OperationReply::finished, this, &HealthService::onWorkFinished);
    else if (error)
        *error = refusal.describe();
    return reply;
}

} // namespace feetech
