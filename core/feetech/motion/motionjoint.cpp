// A recorded joint's CSV column and its words.
#include "motionjoint.h"
#include "motionrecordingtr.h"

#include <QCoreApplication>

namespace feetech {

QString MotionJoint::column() const
{
    return name.isEmpty() ? QStringLiteral("id_%1").arg(id)
                          : QStringLiteral("%1@%2").arg(name).arg(id);
}

QString MotionJoint::describe() const
{
    return name.isEmpty() ? MotionRecordingTr::tr("servo %1").arg(id)
                          : MotionRecordingTr::tr("%1 (servo %2)").arg(name).arg(id);
}

} // namespace feetech
