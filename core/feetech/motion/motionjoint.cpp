// A recorded joint's CSV column and its words.
#include "motionjoint.h"

#include <QCoreApplication>

namespace {

// The context its sentences have always been translated in.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(MotionRecording)
};

} // namespace

namespace feetech {

QString MotionJoint::column() const
{
    return name.isEmpty() ? QStringLiteral("id_%1").arg(id)
                          : QStringLiteral("%1@%2").arg(name).arg(id);
}

QString MotionJoint::describe() const
{
    return name.isEmpty() ? Tr::tr("servo %1").arg(id) : Tr::tr("%1 (servo %2)").arg(name).arg(id);
}

} // namespace feetech
