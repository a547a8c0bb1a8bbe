// The thirteen PTK parameters and where each sits in the eight query replies and twelve writes.
#pragma once

#include "parametermodel.h"
#include "ptkframe.h"

#include <QString>
#include <QStringList>
#include <QStringView>
#include <QVector>

#include <array>
#include <optional>

namespace ptk {

enum class Parameter {
    Gain,
    Damping,
    Deadband,
    Neutral,
    MinAngle,
    MaxAngle,
    MinPulse,
    MaxPulse,
    Inversion,
    MaxPower,
    OverloadPower,
    OverloadTime,
    SoftStart,
};
constexpr int kParameterCount = 13;

enum class Group { Response, Travel, Power };

// Metadata that drives editors, validators and the CLI. Ranges are the RE firmware editor's
// (spec "Parameters and ranges"), in user units.
struct ParameterInfo
{
    Parameter parameter;
    const char *key; // stable snake_case key used by profiles and servoctl
    const char *label; // English; translate with QCoreApplication::translate("ptk", label)
    Group group;
    const char *unit; // user unit ("" when none)
    int wirePerUnit; // wire value = user value × wirePerUnit (pulse widths travel as µs × 4)
    int minimum;
    int maximum;
    bool isSwitch; // 0 / 1 (off / on)
};

const std::array<ParameterInfo, kParameterCount> &parameterInfos();
const ParameterInfo &info(Parameter parameter);
const ParameterInfo *findParameter(QStringView key);
QString translatedLabel(Parameter parameter);
QString translatedGroup(Group group);

// The thirteen parameters as parameter-model definitions: raw values are wire values, shown
// and entered in user units (pulse widths in µs), on/off parameters with Off / On choices.
QVector<model::Definition> modelDefinitions();

// Which parameter travels in which 16-bit word of a frame. A word with no parameter is zero.
struct FrameLayout
{
    const char *name; // "N1".."N12" as the spec numbers them
    quint8 command;
    std::optional<Parameter> word0;
    std::optional<Parameter> word1;
};

// The eight queries in PTK's own order (the read map) and the twelve writes in the order they
// must go out (the write map, command 69 with its zero payload included).
const std::array<FrameLayout, 8> &queryLayouts();
const std::array<FrameLayout, 12> &writeLayouts();
const FrameLayout *findQuery(quint8 command);
const FrameLayout *findWrite(quint8 command);

// Parameter values in wire units; a value is absent until it has been read or set.
class ParameterSet
{
public:
    void set(Parameter parameter, quint16 wireValue) { m_values[index(parameter)] = wireValue; }
    std::optional<quint16> value(Parameter parameter) const { return m_values[index(parameter)]; }
    bool has(Parameter parameter) const { return m_values[index(parameter)].has_value(); }
    bool isComplete() const;
    bool operator==(const ParameterSet &other) const { return m_values == other.m_values; }

    // The seed document's sample servo (soft start as given).
    static ParameterSet seedSample(bool softStart);

private:
    static std::size_t index(Parameter parameter) { return std::size_t(parameter); }
    std::array<std::optional<quint16>, kParameterCount> m_values;
};

// Conversions between wire values and user units, with the range check writes rely on.
double toUserValue(Parameter parameter, quint16 wireValue);
std::optional<quint16> fromUserValue(Parameter parameter, double userValue,
                                     QString *error = nullptr);

// "NAME=VALUE" assignments in user units ("on"/"off"/"true"/"false" for switches) into wire
// values, all or nothing: *error names the first bad name or value.
std::optional<ParameterSet> parseAssignments(const QStringList &assignments,
                                             QString *error = nullptr);

// Stores the parameters a reply to `query` carries; returns which ones it set.
QVector<Parameter> applyReply(const FrameLayout &query, const Reply &reply, ParameterSet &values);
// The reply a servo holding `values` gives to `query` (absent values read as zero).
Reply replyFor(const FrameLayout &query, const ParameterSet &values);

// The write request for one layout; nothing if a parameter it carries has no value.
std::optional<Request> writeRequest(const FrameLayout &layout, const ParameterSet &values);
// The full N1..N12 sequence; nothing unless every parameter has a value.
std::optional<QVector<Request>> writeSequence(const ParameterSet &values);
// What a servo does with a write it receives; returns which parameters it set.
QVector<Parameter> applyWrite(const FrameLayout &layout, const Request &request,
                              ParameterSet &values);

} // namespace ptk
