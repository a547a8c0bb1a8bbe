// The motor set-up of a robot's joints, one servo at a time: find, set up and check the bus.
#pragma once

#include "robottemplate.h"

#include <QObject>
#include <QVector>

#include <optional>

namespace feetech {

class BusClient;
class Refusal;

// Works through the client's motor set-up service, asynchronously. A joint set up is done; a
// check of the bus makes done exactly the joints whose servo answers at its ID now, as its model
// and with its settings (a joint set up earlier whose servo is unplugged is to do again).
class MotorSetupFlow : public QObject
{
    Q_OBJECT

public:
    enum class JointState { ToDo, Done, Failed };
    enum class Work { None, Checking, Finding, SettingUp };
    Q_ENUM(JointState)
    Q_ENUM(Work)

    explicit MotorSetupFlow(BusClient *client, QObject *parent = nullptr);

    // Starts over with `robot`: every joint to do, the first one current.
    void setRobot(const RobotTemplate &robot);
    const RobotTemplate &robot() const { return m_robot; }
    int jointCount() const { return int(m_joints.size()); }
    int currentJoint() const { return m_current; } // -1 once every joint is done
    JointState jointState(int joint) const { return m_joints.at(joint).state; }
    QString jointReason(int joint) const { return m_joints.at(joint).reason; }
    Work work() const { return m_work; }
    bool isWorking() const { return m_work != Work::None; }
    bool isStopping() const { return m_stopping; }
    // What the last find found, to be set up.
    const std::optional<ServoInfo> &found() const { return m_found; }
    // Whether the bus is free for a check, a find or a set-up.
    bool isBusFree() const;

    // Each returns whether the work started; when the service refused it, *refusal says why
    // (it stays empty when the flow cannot start it now, e.g. while working).
    bool checkBus(Refusal *refusal);
    bool find(Refusal *refusal);
    bool setUp(Refusal *refusal);
    // Stops the work before its next step; false when there is none or it is already stopping.
    bool stop();
    // Makes `joint` the one to set up next (a joint done may be set up again); false when it
    // cannot be chosen now or already is the current one.
    bool chooseJoint(int joint);
    // The joint whose servo answers where `servo` does, other than the current one; -1: none.
    int jointAnsweringAt(const ServoInfo &servo) const;

signals:
    // A find or set-up ended; the joints' states already say what it changed.
    void finished(feetech::MotorSetupFlow::Work work, const feetech::MotorSetupResult &result);
    // A check ended; `done` joints are set up (when ok).
    void checked(bool ok, const QString &message, int done);

private:
    struct Joint
    {
        JointState state = JointState::ToDo;
        QString reason; // why it failed, or what a check found at its ID
    };

    void start(Work work);
    void onFinished(const MotorSetupResult &result);
    void onFound(const MotorSetupResult &result);
    void onSetUp(const MotorSetupResult &result);
    void onChecked(const QVector<JointCheck> &joints, bool ok, const QString &message);
    // The next joint not done after `from` (wrapping around); -1 when every joint is done.
    int nextToDo(int from) const;
    MotorTarget currentTarget() const;

    BusClient *m_client = nullptr;
    RobotTemplate m_robot;
    QVector<Joint> m_joints;
    int m_current = -1;
    Work m_work = Work::None;
    bool m_stopping = false;
    std::optional<ServoInfo> m_found;
};

} // namespace feetech
