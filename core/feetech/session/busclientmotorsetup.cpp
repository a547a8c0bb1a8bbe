// Feetech bus client, motor set-up: find, set up and check through the session's queue.
#include "busclient.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

namespace {

bool isMotorWork(Operation operation)
{
    return operation == Operation::FindMotor || operation == Operation::SetUpMotor
        || operation == Operation::CheckJoints;
}

} // namespace

void BusClient::connectMotorSetup(Session *session)
{
    connect(session, &Session::motorSetupProgress, this, &BusClient::motorSetupProgress);
    connect(session, &Session::motorSetupFinished, this,
            [this](const MotorSetupResult &result) { m_motorResult = result; });
    connect(session, &Session::jointsChecked, this,
            [this](const QVector<JointCheck> &joints) { m_jointsChecked = joints; });
}

OperationReply *BusClient::startMotorWork(Operation operation, QString *error,
                                          const std::function<void(Session &)> &work)
{
    QString why;
    if (!isConnected())
        why = Tr::tr("The bus is not connected.");
    else if (isBusy())
        why = Tr::tr("Another operation is still running.");
    if (!why.isEmpty()) {
        if (error)
            *error = why;
        return nullptr;
    }
    m_motorResult.reset();
    m_jointsChecked.reset();
    // No servo of the list is its target: the work finds its own servo.
    return submit(operation, 0, 0, Work::Foreground, work);
}

OperationReply *BusClient::findMotor(const MotorTarget &target, QString *error)
{
    return startMotorWork(Operation::FindMotor, error,
                          [target](Session &s) { s.findMotor(target); });
}

OperationReply *BusClient::setUpMotor(const MotorTarget &target, QString *error)
{
    return startMotorWork(Operation::SetUpMotor, error,
                          [target](Session &s) { s.setUpMotor(target); });
}

OperationReply *BusClient::checkJoints(qint32 baud, const QVector<JointCheck> &joints,
                                       QString *error)
{
    return startMotorWork(Operation::CheckJoints, error,
                          [baud, joints](Session &s) { s.checkJoints(baud, joints); });
}

void BusClient::cancelMotorSetup()
{
    // Not queued behind the work: the flag must be seen while it runs.
    Session *session = m_worker.session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancelMotorSetup(); }, Qt::QueuedConnection);
}

void BusClient::onMotorWorkFinished(const OperationResult &result)
{
    if (!isMotorWork(result.operation))
        return;
    if (result.operation == Operation::CheckJoints) {
        const QVector<JointCheck> joints = m_jointsChecked.value_or(QVector<JointCheck>());
        const bool ok = result.ok && m_jointsChecked.has_value();
        m_jointsChecked.reset();
        emit jointsChecked(joints, ok, result.message);
        return;
    }
    // The link went down under it: the session reported only the operation's end.
    MotorSetupResult reported;
    if (m_motorResult) {
        reported = *m_motorResult;
    } else {
        reported.setUp = result.operation == Operation::SetUpMotor;
        reported.search.verdict = MotorSearch::Verdict::Failed;
        reported.message = result.message;
    }
    m_motorResult.reset();
    // A servo of the list that was set up now answers elsewhere.
    const int index = indexOf(reported.from.id, reported.from.baud);
    const bool moved = reported.from.id != reported.to.id || reported.from.baud != reported.to.baud;
    if (reported.setUp && reported.ok && index >= 0 && moved) {
        m_servos.at(std::size_t(index))->info = reported.to;
        emit servosChanged();
    }
    emit motorSetupFinished(reported);
}

} // namespace feetech
