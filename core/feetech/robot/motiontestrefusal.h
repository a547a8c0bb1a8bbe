// Why a motion test does not start: a code, the numbers its sentence needs, and the sentence.
#pragma once

#include "goalrange.h"
#include "refusal.h"

#include <QString>

namespace feetech {

// A value type: empty (false) when nothing was refused. Callers and tests decide on code();
// describe() is the translated sentence shown to the user.
class MotionTestRefusal
{
public:
    // Stable: callers and tests compare with these, never with the sentence.
    enum class Code {
        None,
        AlreadyRunning,
        NotConnected,
        NoServo, // the plan's index names no servo found
        BeingIdentified, // servoId(): its joint is being identified
        UnknownModel, // ServoBench does not move a servo of an unknown model
        NotMovable, // no goal position or torque register
        NotInPositionMode, // servoId()
        OutsideRange, // from(), to() and range(): the goal positions the servo accepts
        TooClose, // limit(): from and to must lie further apart than the reach tolerance
        SettingOutOfRange, // label(), minimum(), maximum(): the goal speed or the acceleration
        BadRecordLength, // limit(): the longest recording, in seconds
        BadLegCount, // maximum(): the most legs a sweep has
        ServoGone, // servoId(): the servo left the bus
        ClientRefused, // clientRefusal(): the bus client refused a write or the stream
    };

    MotionTestRefusal() = default;
    explicit MotionTestRefusal(Code code)
        : m_code(code)
    { }

    static MotionTestRefusal beingIdentified(quint8 servoId);
    static MotionTestRefusal notInPositionMode(quint8 servoId);
    static MotionTestRefusal outsideRange(qint32 from, qint32 to, const PositionRange &range);
    static MotionTestRefusal tooClose(double reachTolerance);
    static MotionTestRefusal settingOutOfRange(const QString &label, qint64 minimum,
                                               qint64 maximum);
    static MotionTestRefusal badRecordLength(double maximumSeconds);
    static MotionTestRefusal badLegCount(int maximumLegs);
    static MotionTestRefusal servoGone(quint8 servoId);
    static MotionTestRefusal clientRefused(const Refusal &refusal);

    Code code() const { return m_code; }
    explicit operator bool() const { return m_code != Code::None; }
    quint8 servoId() const { return m_servoId; }
    qint32 from() const { return m_from; }
    qint32 to() const { return m_to; }
    PositionRange range() const { return m_range; }
    double limit() const { return m_limit; }
    QString label() const { return m_label; }
    qint64 minimum() const { return m_minimum; }
    qint64 maximum() const { return m_maximum; }
    Refusal clientRefusal() const { return m_clientRefusal; }

    QString describe() const;

private:
    Code m_code = Code::None;
    quint8 m_servoId = 0;
    qint32 m_from = 0;
    qint32 m_to = 0;
    PositionRange m_range;
    double m_limit = 0.0;
    QString m_label;
    qint64 m_minimum = 0;
    qint64 m_maximum = 0;
    Refusal m_clientRefusal;
};

} // namespace feetech
