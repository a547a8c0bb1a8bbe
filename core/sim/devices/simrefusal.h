// Why a simulated device refuses: the Feetech bus a bus description, a change or a state file,
// its hand a turn of a horn, the PTK servo its starting values, the demo's servos to start. A
// code, and a sentence.
#pragma once

#include <QString>

namespace sim {

// A value type: empty (false) when nothing was refused. Callers and tests decide on code();
// describe() is the translated sentence servosim prints and the simulator dock shows. The servo,
// values, name and file are what the sentence needs, no more.
class SimRefusal
{
public:
    // Stable: callers and tests compare with these, never with the sentence.
    enum class Code {
        None,
        NoServos, // a bus description without a servo
        UnknownModel, // servo: the ID; name: the model asked for
        NoRegisterTable, // servo: the ID; name: a known model the simulator has no table for
        IdOutOfRange, // servo: the ID asked for
        NotAFeetechRate, // servo: the ID; value: the baud rate
        IdTaken, // servo: the ID; value: the baud rate two servos share
        NoSuchPlace, // servo: the place (1-based); value: how many servos the bus has
        NoSuchId, // servo: the ID
        SharedId, // servo: the ID; name: the places of the servos sharing it ("#1, #2")
        CannotWriteState, // file; name: the system's reason
        CannotReadState, // file; name: the reason the file could not be read
        StateNotJson, // file; name: the parser's reason
        StateNotThisFormat, // file
        StateServoCount, // file; value: servos in the file; other: servos on the bus
        StateModelDiffers, // file; servo: the place; name: the file's model; other: see bus model
        StateImageSize, // file; servo: the place
        StateImageModel, // file; servo: the place; value, other: major, minor; name: bus model
        StateImageIdOrBaud, // file; servo: the place
        PositionOutOfRange, // servo: the place; id; value: the position; other: the highest
        TorqueOn, // servo: the place; id: the hand cannot turn a servo holding its position
        SweepTooLong, // the sweep's time is not above 0 and at most Hand::kMaxSweepSeconds
        TooManyCycles, // the sweep's cycles are not 0 to Hand::kMaxSweepCycles
        NoSeam, // servo: the place; id; other: the highest position of an SCS servo
        BadPtkValues, // name: why the PTK servo's starting values (--values) do not parse
        NoDemoFolder, // name: why the demo's private folder could not be made (the system's words)
        NoDemoRobot, // name: why the demo arm's built-in robot template did not load (its sentence)
        DemoNotStarted, // name: why the demo's simulator did not start (its sentence)
    };

    SimRefusal() = default;
    explicit SimRefusal(Code code)
        : m_code(code)
    { }
    SimRefusal(Code code, int servo, qint64 value = 0, const QString &name = {})
        : m_code(code)
        , m_servo(servo)
        , m_value(value)
        , m_name(name)
    { }

    // A refusal of the servo at `place` (1-based) and `id`.
    static SimRefusal ofServo(Code code, int place, int id, qint64 value = 0, qint64 other = 0);
    // A refusal of the state file `file`.
    static SimRefusal stateFile(Code code, const QString &file, int servo = 0, qint64 value = 0,
                                qint64 other = 0, const QString &name = {},
                                const QString &busModel = {});

    Code code() const { return m_code; }
    explicit operator bool() const { return m_code != Code::None; }
    int servo() const { return m_servo; }
    int id() const { return m_id; }
    qint64 value() const { return m_value; }
    qint64 other() const { return m_other; }
    QString name() const { return m_name; }
    QString file() const { return m_file; }

    QString describe() const;

private:
    QString stateReason() const;

    Code m_code = Code::None;
    int m_servo = 0;
    int m_id = 0;
    qint64 m_value = 0;
    qint64 m_other = 0;
    QString m_name;
    QString m_busModel;
    QString m_file;
};

// Whether `refusal` refuses anything; it goes where `out` points then (when it points anywhere).
bool refused(const SimRefusal &refusal, SimRefusal *out);

} // namespace sim
