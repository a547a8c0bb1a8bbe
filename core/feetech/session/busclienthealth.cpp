// Feetech bus client: the health check of the servos found, and its confirmed move test.
#include "busclient.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

void BusClient::connectHealth(Session *session)
{
    connect(session, &Session::healthRead, this, &BusClient::healthRead);
    connect(session, &Session::moveTested, this,
            [this](const MoveTestResult &result) { m_moveTested = result; });
}

void BusClient::onHealthWorkFinished(const OperationResult &result)
{
    // After the reply: the client is idle again when these are heard.
    if (result.operation == Operation::HealthCheck && m_checkingHealth) {
        m_checkingHealth = false;
        emit healthCheckFinished(result.ok, result.message);
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

OperationReply *BusClient::checkHealth(const QVector<int> &indexes, int reads, QString *error)
{
    QString why;
    if (!isConnected())
        why = Tr::tr("The bus is not connected.");
    else if (isBusy())
        why = Tr::tr("Another operation is still running.");
    else if (indexes.isEmpty())
        why = Tr::tr("No servo to check: scan the bus first.");
    QVector<ServoInfo> servos;
    for (const int index : indexes) {
        if (index < 0 || index >= servoCount())
            why = Tr::tr("No servo is selected.");
        else
            servos.append(servo(index).info);
    }
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return nullptr;
    }
    m_checkingHealth = true;
    // Several servos, none of them the target: the check reports each on its own.
    return submit(Operation::HealthCheck, 0, 0, Work::Foreground,
                  [servos, reads](Session &s) { s.checkHealth(servos, reads); });
}

void BusClient::cancelHealthCheck()
{
    // Not queued behind the check: the flag must be seen while it runs.
    Session *session = m_worker.session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancelHealthCheck(); }, Qt::QueuedConnection);
}

QString BusClient::moveTestBlocker(int index) const
{
    return identifyBlocker(index);
}

OperationReply *BusClient::moveTest(int index, bool confirmed, QString *error)
{
    QString why = moveTestBlocker(index);
    if (why.isEmpty() && !confirmed)
        why = Tr::tr("The move test moves servo %1: it runs only once that is confirmed.")
                  .arg(servo(index).info.id);
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return nullptr;
    }
    m_moveTested.reset();
    return startOperation(Operation::MoveTest, index, error, Work::Foreground,
                          [](Session &s, const ServoInfo &target) { s.moveTest(target); });
}

} // namespace feetech
