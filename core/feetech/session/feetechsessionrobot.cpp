// The Feetech session's robot-arm operations: motor set-up (find, set up, check the joints)
// and identifying a joint, queued like every other operation.
#include "feetechsession.h"

#include <QCoreApplication>

#include <algorithm>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

} // namespace

namespace feetech {

// ---- identify

void Session::identifyJoint(const ServoInfo &servo)
{
    const quint64 epoch = m_torqueOffEpoch;
    m_identify->clearCancel();
    enqueue(Operation::Identify, [this, servo, epoch] {
        if (refusedAfterTorqueOff(Operation::Identify, epoch))
            return;
        m_guard->noteDriven(servo);
        m_identifying = true;
        m_identify->run(
            servo,
            [this](const OperationResult &result) {
                m_identifying = false;
                finishOperation(result);
            },
            [this, epoch](std::chrono::milliseconds delay,
                          std::function<void(bool torqueOff)> resume) {
                pauseFor(Operation::Identify, delay,
                         [this, epoch, resume] { resume(epoch != m_torqueOffEpoch); });
            });
    });
}

// ---- motor set-up

void Session::findMotor(const MotorTarget &target)
{
    m_motorSetup->clearCancel();
    enqueue(Operation::FindMotor, [this, target] {
        m_motorSetup->find(target, [this](const MotorSearch &search) {
            MotorSetupResult result;
            result.ok = search.foundOne();
            result.search = search;
            result.stopped = search.stopped;
            result.from = result.to = search.servo;
            result.message = search.message;
            emit motorSetupFinished(result);
            finishOperation({Operation::FindMotor, result.ok, result.message, search.servo, {}});
        });
    });
}

void Session::setUpMotor(const MotorTarget &target)
{
    m_motorSetup->clearCancel();
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::SetUpMotor, [this, target, epoch] {
        if (refusedAfterTorqueOff(Operation::SetUpMotor, epoch))
            return;
        m_motorSetup->setUp(target, [this](const MotorSetupResult &result) {
            emit motorSetupFinished(result);
            finishOperation({Operation::SetUpMotor, result.ok, result.message, result.to, {}});
        });
    });
}

void Session::checkJoints(qint32 baud, const QVector<JointCheck> &joints)
{
    m_motorSetup->clearCancel();
    enqueue(Operation::CheckJoints, [this, baud, joints] {
        m_motorSetup->check(baud, joints, [this](const QVector<JointCheck> &checked) {
            emit jointsChecked(checked);
            const auto done = std::count_if(checked.begin(), checked.end(),
                                            [](const JointCheck &joint) { return joint.done(); });
            finishOperation(
                {Operation::CheckJoints,
                 true,
                 Tr::tr("%1 of %n joint(s) already set up.", nullptr, int(checked.size()))
                     .arg(done),
                 {},
                 {}});
        });
    });
}

void Session::cancelMotorSetup()
{
    m_motorSetup->cancel();
}

void Session::cancelIdentify()
{
    m_identify->cancel();
}

} // namespace feetech
