// Feetech bus client: identifying a joint, and the servos something outside the session holds.
#include "busclient.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechBusClient)
};

} // namespace

namespace feetech {

QString BusClient::identifyBlocker(int index) const
{
    const QString blocker = writeBlocker(index);
    if (!blocker.isEmpty())
        return blocker;
    const ServoInfo &info = servo(index).info;
    const QString held = m_held.value({info.id, info.baud});
    if (!held.isEmpty())
        return held;
    if (!info.table().find(u"goal_position") || !info.table().find(u"torque_enable"))
        return Tr::tr("This servo has no goal position register: it cannot be moved.");
    return {};
}

OperationReply *BusClient::identifyJoint(int index, QString *error)
{
    const QString blocker = identifyBlocker(index);
    if (!blocker.isEmpty()) {
        if (error)
            *error = blocker;
        return nullptr;
    }
    const ServoInfo &info = servo(index).info;
    m_identifying = std::pair(info.id, info.baud);
    return startOperation(Operation::Identify, index, error, Work::Foreground,
                          [](Session &s, const ServoInfo &target) { s.identifyJoint(target); });
}

bool BusClient::isIdentifying(int index) const
{
    return m_identifying && index >= 0 && index < servoCount()
        && *m_identifying == std::pair(servo(index).info.id, servo(index).info.baud);
}

void BusClient::holdServo(int index, const QString &reason)
{
    if (index < 0 || index >= servoCount())
        return;
    m_held.insert({servo(index).info.id, servo(index).info.baud}, reason);
    emit servoUpdated(index); // what it may do now has changed
}

void BusClient::releaseServo(quint8 id, qint32 baud)
{
    if (m_held.remove({id, baud}) > 0 && indexOf(id, baud) >= 0)
        emit servoUpdated(indexOf(id, baud));
}

} // namespace feetech
