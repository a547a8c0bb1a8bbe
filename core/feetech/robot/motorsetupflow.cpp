// The motor set-up flow: the joints' states as the finds, set-ups and checks report them.
#include "motorsetupflow.h"

#include "busclient.h"

#include <QCoreApplication>

namespace {

struct MotorSetupFlowTr
{
    Q_DECLARE_TR_FUNCTIONS(MotorSetupFlow)
};

} // namespace

namespace feetech {

MotorSetupFlow::MotorSetupFlow(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
{
    connect(m_client->motorSetup(), &MotorSetupService::finished, this,
            &MotorSetupFlow::onFinished);
    connect(m_client->motorSetup(), &MotorSetupService::jointsChecked, this,
            &MotorSetupFlow::onChecked);
}

void MotorSetupFlow::setRobot(const RobotTemplate &robot)
{
    m_robot = robot;
    m_joints = QVector<Joint>(m_robot.joints.size());
    m_current = m_robot.joints.isEmpty() ? -1 : 0;
    m_found.reset();
}

bool MotorSetupFlow::isBusFree() const
{
    return m_client->link()->isConnected() && !isWorking() && !m_client->isBusy();
}

void MotorSetupFlow::start(Work work)
{
    m_work = work;
    m_stopping = false;
}

bool MotorSetupFlow::checkBus(Refusal *refusal)
{
    if (!isBusFree() || m_joints.isEmpty())
        return false;
    if (!m_client->motorSetup()->checkJoints(m_robot.baud, jointChecks(m_robot), refusal))
        return false;
    start(Work::Checking);
    return true;
}

bool MotorSetupFlow::find(Refusal *refusal)
{
    if (isWorking() || m_current < 0)
        return false;
    m_found.reset();
    if (!m_client->motorSetup()->find(currentTarget(), refusal))
        return false;
    start(Work::Finding);
    return true;
}

bool MotorSetupFlow::setUp(Refusal *refusal)
{
    if (isWorking() || m_current < 0 || !m_found)
        return false;
    if (!m_client->motorSetup()->setUp(currentTarget(), refusal))
        return false;
    start(Work::SettingUp);
    return true;
}

bool MotorSetupFlow::stop()
{
    if (!isWorking() || m_stopping)
        return false;
    m_stopping = true;
    m_client->motorSetup()->cancel();
    return true;
}

bool MotorSetupFlow::chooseJoint(int joint)
{
    if (joint < 0 || joint >= m_joints.size() || isWorking() || joint == m_current)
        return false;
    m_current = joint;
    m_found.reset();
    return true;
}

void MotorSetupFlow::onFinished(const MotorSetupResult &result)
{
    const Work work = m_work;
    m_work = Work::None;
    m_stopping = false;
    if (work == Work::Finding && !result.setUp)
        onFound(result);
    else if (work == Work::SettingUp && result.setUp)
        onSetUp(result);
    emit finished(work, result);
}

void MotorSetupFlow::onFound(const MotorSetupResult &result)
{
    if (m_current < 0)
        return;
    Joint &joint = m_joints[m_current];
    if (!result.ok) {
        if (!result.stopped) {
            joint.state = JointState::Failed;
            joint.reason = result.message;
        }
        return;
    }
    m_found = result.search.servo;
    joint.reason.clear();
    if (joint.state == JointState::Failed)
        joint.state = JointState::ToDo;
}

void MotorSetupFlow::onSetUp(const MotorSetupResult &result)
{
    m_found.reset();
    if (m_current < 0)
        return;
    Joint &joint = m_joints[m_current];
    if (!result.ok) {
        // A stop before anything was written leaves the joint as it was.
        if (!result.stopped || result.steps.size() > 1) {
            joint.state = JointState::Failed;
            joint.reason = result.message;
        }
        return;
    }
    joint.state = JointState::Done;
    joint.reason.clear();
    m_current = nextToDo(m_current);
}

void MotorSetupFlow::onChecked(const QVector<JointCheck> &joints, bool ok, const QString &message)
{
    if (m_work != Work::Checking)
        return;
    m_work = Work::None;
    m_stopping = false;
    if (!ok) {
        emit checked(false, message, 0);
        return;
    }
    int done = 0;
    for (int i = 0; i < joints.size() && i < m_joints.size(); ++i) {
        const JointCheck &check = joints.at(i);
        Joint &joint = m_joints[i];
        // Done is what the bus says now: a joint set up earlier whose servo no longer answers
        // (unplugged, or moved to another ID since) is to be checked or set up again, so the
        // wizard's count is the check's own.
        if (check.done()) {
            joint = {JointState::Done, {}};
        } else if (check.found) { // something else answers there: not set up as this joint
            joint = {JointState::ToDo, check.problem()};
        } else if (joint.state == JointState::Done) {
            joint = {JointState::ToDo,
                     MotorSetupFlowTr::tr("set up earlier, but ID %1 does not answer now")
                         .arg(check.id)};
        } else if (joint.state == JointState::ToDo) {
            joint.reason.clear(); // what an earlier check found there has gone
        }
        done += joint.state == JointState::Done ? 1 : 0;
    }
    if (m_current < 0 || m_joints.at(m_current).state == JointState::Done)
        m_current = nextToDo(m_current < 0 ? -1 : m_current);
    m_found.reset();
    emit checked(true, message, done);
}

int MotorSetupFlow::nextToDo(int from) const
{
    for (int step = 1; step <= m_joints.size(); ++step) {
        const int joint = (from + step) % int(m_joints.size());
        if (m_joints.at(joint).state != JointState::Done)
            return joint;
    }
    return -1;
}

MotorTarget MotorSetupFlow::currentTarget() const
{
    return motorTarget(m_robot, m_robot.joints.at(m_current));
}

int MotorSetupFlow::jointAnsweringAt(const ServoInfo &servo) const
{
    for (int i = 0; i < m_robot.joints.size(); ++i) {
        if (i != m_current && m_robot.joints.at(i).id == servo.id && m_robot.baud == servo.baud)
            return i;
    }
    return -1;
}

} // namespace feetech
