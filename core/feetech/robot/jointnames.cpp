// Servos named by the joints of the robot template they match.
#include "jointnames.h"

#include "busclient.h"

#include <QSet>

namespace feetech {

namespace {

const RobotJoint *jointAt(const RobotTemplate &robot, const ServoInfo &servo)
{
    for (const RobotJoint &joint : robot.joints) {
        if (joint.id == servo.id && joint.model.compare(servo.model.name, Qt::CaseInsensitive) == 0)
            return &joint;
    }
    return nullptr;
}

} // namespace

JointNames::JointNames(const QVector<RobotTemplate> &templates, const QVector<ServoInfo> &servos)
{
    // One servo matches too much (a factory-new servo at ID 1 is no shoulder).
    if (servos.size() < 2)
        return;
    QSet<int> ids;
    for (const ServoInfo &servo : servos) {
        if (servo.sharedId)
            return;
        ids.insert(servo.id);
    }
    if (ids.size() != servos.size())
        return; // an ID twice (at two rates, or shared): which joint would be which?
    for (const RobotTemplate &robot : templates) {
        QHash<ServoAddress, QString> joints;
        for (const ServoInfo &servo : servos) {
            const RobotJoint *joint = jointAt(robot, servo);
            if (!joint)
                break;
            joints.insert(servo.address(), joint->name);
        }
        if (joints.size() == servos.size()) {
            m_robot = robot.name;
            m_joints = joints;
            return;
        }
    }
}

JointNames JointNames::of(const BusClient &client)
{
    QVector<ServoInfo> servos;
    for (int index = 0; index < client.servos()->count(); ++index)
        servos.append(client.servos()->at(index).info);
    if (servos.size() < 2)
        return {}; // the templates need not be read from disk
    return JointNames(availableRobotTemplates(), servos);
}

QString JointNames::label(const ServoAddress &servo) const
{
    const QString joint = m_joints.value(servo);
    if (joint.isEmpty())
        return tr("ID %1").arg(servo.id);
    return tr("%1 (ID %2)").arg(jointDisplayName(joint)).arg(servo.id);
}

} // namespace feetech
