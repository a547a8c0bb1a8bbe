// Motor set-up through the bus client: find, set up and check through the session's queue.
#include "motorsetupservice.h"

#include "busclient.h"

namespace feetech {

MotorSetupService::MotorSetupService(BusClient *client)
    : QObject(client)
    , m_client(client)
{
    Session *session = client->session();
    connect(session, &Session::motorSetupProgress, this, &MotorSetupService::progress);
    connect(session, &Session::motorSetupFinished, this,
            [this](const MotorSetupResult &result) { m_result = result; });
    connect(session, &Session::jointsChecked, this,
            [this](const QVector<JointCheck> &joints) { m_jointsChecked = joints; });
}

OperationReply *MotorSetupService::start(Operation operation, Refusal *refusal,
                                         const std::function<void(Session &)> &work)
{
    Refusal why;
    if (!m_client->isConnected())
        why = Refusal(Refusal::Code::NotConnected);
    else if (m_client->isBusy())
        why = Refusal(Refusal::Code::Busy);
    if (refused(why, refusal))
        return nullptr;
    m_result.reset();
    m_jointsChecked.reset();
    // No servo of the list is its target: the work finds its own servo.
    OperationReply *reply = m_client->submit(operation, 0, 0, BusClient::Work::Foreground, work);
    connect(reply, &OperationReply::finished, this, &MotorSetupService::onWorkFinished);
    return reply;
}

OperationReply *MotorSetupService::find(const MotorTarget &target, Refusal *refusal)
{
    return start(Operation::FindMotor, refusal, [target](Session &s) { s.findMotor(target); });
}

OperationReply *MotorSetupService::setUp(const MotorTarget &target, Refusal *refusal)
{
    return start(Operation::SetUpMotor, refusal, [target](Session &s) { s.setUpMotor(target); });
}

OperationReply *MotorSetupService::checkJoints(qint32 baud, const QVector<JointCheck> &joints,
                                               Refusal *refusal)
{
    return start(Operation::CheckJoints, refusal,
                 [baud, joints](Session &s) { s.checkJoints(baud, joints); });
}

void MotorSetupService::cancel()
{
    // Not queued behind the work: the flag must be seen while it runs.
    Session *session = m_client->session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancelMotorSetup(); }, Qt::QueuedConnection);
}

void MotorSetupService::onWorkFinished(const OperationResult &result)
{
    if (result.operation == Operation::CheckJoints) {
        const QVector<JointCheck> joints = m_jointsChecked.value_or(QVector<JointCheck>());
        const bool ok = result.ok && m_jointsChecked.has_value();
        m_jointsChecked.reset();
        emit jointsChecked(joints, ok, result.message);
        return;
    }
    // The link went down under it: the session reported only the operation's end.
    MotorSetupResult reported;
    if (m_result) {
        reported = *m_result;
    } else {
        reported.setUp = result.operation == Operation::SetUpMotor;
        reported.search.verdict = MotorSearch::Verdict::Failed;
        reported.message = result.message;
    }
    m_result.reset();
    // A servo of the list that was set up now answers elsewhere.
    const int index = m_client->servos()->indexOf(reported.from.address());
    const bool moved = reported.from.id != reported.to.id || reported.from.baud != reported.to.baud;
    if (reported.setUp && reported.ok && index >= 0 && moved)
        m_client->servos()->move(index, reported.to);
    emit finished(reported);
}

} // namespace feetech
