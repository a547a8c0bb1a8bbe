// Why the bus client or one of its services does not start an operation: a code, and a sentence.
#pragma once

#include <QString>

#include <optional>

namespace feetech {

// A value type: empty (false) when nothing was refused. Callers and tests decide on code();
// describe() is the translated sentence shown to the user. The servo, value and detail are what
// the sentence needs, no more.
class Refusal
{
public:
    // Stable: callers and tests compare with these, never with the sentence.
    enum class Code {
        None,
        NotConnected,
        NoServo, // the index names no servo found
        SharedId, // servoId: two or more servos answer at it
        UnknownModel, // with servoId: one of several servos (Move all)
        Busy, // another operation is still running
        ServoHeld, // detail: why the holder (a motion test) holds it
        NotMovable, // no goal position or torque register
        NoMiddleCalibration,
        NoStatusRegister, // nothing to recover from an overload
        IdInUse, // value: the ID asked for
        NothingToWrite,
        NothingToMove,
        BadValue, // detail: the register and why; with servoId: one of several servos
        NotAFrame, // a hand-built packet that is no whole Feetech frame
        NotAFeetechRate, // value: the baud rate
        NoServoToCheck, // a health check of no servo
        NotConfirmed, // servoId: the move test waits for the user's consent
        NoServoToMonitor, // a telemetry subscription of no servo
        NegativeRate, // a telemetry rate below 0
        UndecodableFeedback, // servoId: an unknown model, whose feedback block is not known
        JointNotFound, // servoId: a recording's joint whose servo the scan did not find
        SeveralRates, // a recording of servos at different baud rates
        BusShared, // the bus is shared with another program and this would get in its way
        AlreadyShared, // the bus is shared already
        NoSharePath, // no path given for the other program to open
    };

    Refusal() = default;
    explicit Refusal(Code code)
        : m_code(code)
    { }

    static Refusal sharedId(quint8 servoId);
    static Refusal unknownModel(quint8 servoId);
    static Refusal servoHeld(const QString &holderReason);
    static Refusal idInUse(int id);
    static Refusal badValue(const QString &reason);
    static Refusal badValue(quint8 servoId, const QString &reason);
    static Refusal notAFeetechRate(qint32 baud);
    static Refusal notConfirmed(quint8 servoId);
    static Refusal undecodableFeedback(quint8 servoId);
    static Refusal jointNotFound(quint8 servoId);

    Code code() const { return m_code; }
    explicit operator bool() const { return m_code != Code::None; }
    std::optional<quint8> servoId() const { return m_servoId; }
    qint64 value() const { return m_value; }
    QString detail() const { return m_detail; }

    QString describe() const;

    friend bool operator==(const Refusal &a, const Refusal &b)
    {
        return a.m_code == b.m_code && a.m_servoId == b.m_servoId && a.m_value == b.m_value
            && a.m_detail == b.m_detail;
    }
    friend bool operator!=(const Refusal &a, const Refusal &b) { return !(a == b); }

private:
    Refusal(Code code, std::optional<quint8> servoId, qint64 value, const QString &detail)
        : m_code(code)
        , m_servoId(servoId)
        , m_value(value)
        , m_detail(detail)
    { }

    Code m_code = Code::None;
    std::optional<quint8> m_servoId;
    qint64 m_value = 0;
    QString m_detail;
};

// Whether `refusal` refuses anything; it goes where `out` points then (when it points anywhere).
bool refused(const Refusal &refusal, Refusal *out);

} // namespace feetech
