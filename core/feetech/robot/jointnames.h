// The joints of the arm on a bus: when the servos found match a robot template (each servo one
// of its joints, by ID and model), the GUI names servos by joint, "shoulder_pan (ID 1)".
#pragma once

#include "bustypes.h"
#include "robottemplate.h"

#include <QCoreApplication>
#include <QHash>
#include <QString>
#include <QVector>

namespace feetech {

class BusClient;

class JointNames
{
    Q_DECLARE_TR_FUNCTIONS(JointNames)

public:
    JointNames() = default; // names no joint

    // The first of `templates` that `servos` match: at least two servos, each at one of its
    // joints' IDs with that joint's model, no ID twice. None matched: no joint is named.
    JointNames(const QVector<RobotTemplate> &templates, const QVector<ServoInfo> &servos);
    // The client's servos against the templates ServoBench offers (built in and the user's).
    static JointNames of(const BusClient &client);

    bool isEmpty() const { return m_joints.isEmpty(); }
    QString robot() const { return m_robot; } // the template matched, as it names itself
    // The joint at `servo`, as the template names it ("shoulder_pan"); empty when none.
    QString joint(const ServoAddress &servo) const { return m_joints.value(servo); }
    // How the GUI names `servo`: "shoulder_pan (ID 1)" in the user's language, else "ID 1".
    QString label(const ServoAddress &servo) const;

private:
    QString m_robot;
    QHash<ServoAddress, QString> m_joints;
};

} // namespace feetech
