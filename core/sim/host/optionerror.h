// Why servosim refuses an option's value (--faults, --robot, --servo and --hand, and the plug and
// sweep commands' fields): a code, and a sentence.
#pragma once

#include <QString>
#include <QStringList>

namespace sim {

// A value type: empty (false) when nothing was refused. Callers and tests decide on code();
// describe() is the translated sentence servosim prints. The text at fault, the option or
// command that gave it and a number are what the sentences need, no more.
class OptionError
{
public:
    // Stable: callers and tests compare with these, never with the sentence.
    enum class Code {
        None,
        FaultNotNameValue, // text: the --faults item without NAME=VALUE
        FaultNotANumber, // text: the value that is no number
        FaultDelayOutOfRange, // the delay is not 0 to 60000 ms
        FaultNotAProbability, // text: the fault whose value is not 0 to 1
        UnknownFault, // text: the fault's name
        NotAServoSpec, // source; text: not ID:MODEL[@BAUD]
        ServoIdOverMax, // source; text; value: the ID
        ServoWithoutModel, // source; text
        ServoBadBaud, // source; text
        SweepFields, // source: not ID FROM TO SECONDS [CYCLES] [up|down]
        SweepBadId, // source; text: the ID field
        SweepBadPositions, // source: FROM or TO is no position
        SweepBadSeconds, // source; text: the SECONDS field
        SweepBadCycles, // source; text: the CYCLES field
        UnknownRobot, // text: the name asked for
        BadRobotTemplate, // text: why the built-in template did not load (its FileError sentence)
    };

    OptionError() = default;
    explicit OptionError(Code code, const QString &text = {}, const QString &source = {},
                         qint64 value = 0)
        : m_code(code)
        , m_text(text)
        , m_source(source)
        , m_value(value)
    { }

    Code code() const { return m_code; }
    explicit operator bool() const { return m_code != Code::None; }
    QString text() const { return m_text; }
    QString source() const { return m_source; }
    qint64 value() const { return m_value; }

    QString describe() const;
    // The built-in robot templates servosim plays, as --robot names them.
    static QStringList simulatedRobotNames();

private:
    QString sweepReason() const;

    Code m_code = Code::None;
    QString m_text;
    QString m_source;
    qint64 m_value = 0;
};

// Whether `error` refuses anything; it goes where `out` points then (when it points anywhere).
bool refused(const OptionError &error, OptionError *out);

} // namespace sim
