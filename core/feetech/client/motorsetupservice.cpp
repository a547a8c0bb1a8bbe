// Motor set-up through the bus client: find, set up and check through the session's queue.
#include "motorsetupservice.h"

#include "busclient.h"
#include "busoperations.h"

namespace feetech {

MotorSetupService::MotorSetupService(BusClient *client)
    : QObject(client)
    , m_client(client)
{ }

OperationReply *MotorSetupService::start(const BusOperation &operation, Refusal *refusal)
{
    Refusal why;
    if (!m_client->link()->isConnected())
        why = Refusal(Refusal::Code::NotConnected);
    else if (m_client->isBusy())
        why = Refusal(Refusal::Code::Busy);
    else if (m_client->share()->isActive() && Session::changesPortRate(operation.kind))
        why = Refusal(Refusal::Code::BusShared);
    if (refused(why, refusal))
        return nullptr;
    // No servo of the list is its target: the work finds its own servo.
    OperationReply *reply = m_client->submit(operation, 0, 0, BusClient::Work::Foreground);
    connect(reply, &OperationReply::progress, this, [this](const OperationProgress &progress) {
        emit this->progress(progress.done, progress.total, progress.text);
    });
    connect(reply, &OperationReply::finished, this, &MotorSetupService::onWorkFinished);
    return reply;
}

OperationReply *MotorSetupService::find(const MotorTarget &target, Refusal *refusal)
{
    return start(operations::findMotor(target), refusal);
}

OperationReply *MotorSetupService::setUp(const MotorTarget &target, Refusal *refusal)
{
    return start(operations::setUpMotor(target), refusal);
}

OperationReply *MotorSetupService::checkJoints(qint32 baud, const QVector<JointCheck> &joints,
                                               Refusal *refusal)
{
    m_checkBaud = baud;
    return start(operations::checkJoints(baud, joints), refusal);
}

void MotorSetupService::cancel()
{
    // Not queued behind the work: the flag must be seen while it runs.
    Session *session = m_client->session();
    QMetaObject::invokeMethod(
        session, [session] { session->cancel(Operation::SetUpMotor); }, Qt::QueuedConnection);
}

void MotorSetupService::onWorkFinished(const OperationResult &result)
{
    if (result.operation == Operation::CheckJoints) {
        // Without its joints when the link went down under it.
        const bool ok = result.ok && result.detail.canConvert<QVector<JointCheck>>();
        if (ok)
            followCheck(result.detail.value<QVector<JointCheck>>());
        emit jointsChecked(result.detail.value<QVector<JointCheck>>(), ok, result.message);
        return;
    }
    // The link went down under it: the session reported only the operation's end.
    MotorSetupResult reported;
    if (result.detail.canConvert<MotorSetupResult>()) {
        reported = result.detail.value<MotorSetupResult>();
    } else {
        reported.setUp = result.operation == Operation::SetUpMotor;
        reported.search.verdict = MotorSearch::Verdict::Failed;
        reported.message = result.message;
    }
    // A servo of the list that was set up now answers elsewhere.
    const int index = m_client->servos()->indexOf(reported.from.address());
    const bool moved = reported.from.id != reported.to.id || reported.from.baud != reported.to.baud;
    if (reported.setUp && reported.ok && index >= 0 && moved)
        m_client->servos()->move(index, reported.to);
    emit finished(reported);
}

void MotorSetupService::followCheck(const QVector<JointCheck> &joints)
{
    // The list shows what the check proved at each joint's ID: the servo that answers there
    // (moved or set up by a wizard since the scan), and no servo where nothing answers now.
    ServoList *servos = m_client->servos();
    for (const JointCheck &check : joints) {
        const int index = servos->indexOf({quint8(check.id), m_checkBaud});
        if (!check.found) {
            servos->remove(index);
        } else if (index < 0) {
            servos->add(*check.found);
        } else if (servos->at(index).info.model.name != check.found->model.name) {
            servos->move(index, *check.found);
        }
    }
}

} // namespace feetech
