// A joint of a recorded motion: its name and servo ID, as a CSV column and in a sentence.
#pragma once

#include <QString>

namespace feetech {

struct MotionJoint
{
    QString name; // empty: the joint is known by its servo's ID alone
    quint8 id = 0;

    // Its CSV column: "id_3" without a name, "shoulder_pan@1" with one.
    QString column() const;
    // "shoulder_pan (servo 1)", or "servo 3".
    QString describe() const;
};

} // namespace feetech
