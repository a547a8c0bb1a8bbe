// PTK read map, write map and parameter metadata as data (spec/ptk-protocol.md).
#include "ptkparameters.h"

#include <QCoreApplication>

#include <cmath>

namespace ptk {

namespace {

using P = Parameter;

const std::array<ParameterInfo, kParameterCount> kInfos {{
    {P::Gain, "gain", QT_TRANSLATE_NOOP("ptk", "Gain"), Group::Response, "", 1, 0, 30, false},
    {P::Damping, "damping", QT_TRANSLATE_NOOP("ptk", "Damping"), Group::Response, "", 1, 0, 255,
     false},
    {P::Deadband, "deadband", QT_TRANSLATE_NOOP("ptk", "Deadband"), Group::Response, "", 1, 0, 255,
     false},
    {P::Neutral, "neutral", QT_TRANSLATE_NOOP("ptk", "Neutral"), Group::Travel, "", 1, 2000, 6000,
     false},
    {P::MinAngle, "min_angle", QT_TRANSLATE_NOOP("ptk", "Minimum angle"), Group::Travel, "", 1, 0,
     255, false},
    {P::MaxAngle, "max_angle", QT_TRANSLATE_NOOP("ptk", "Maximum angle"), Group::Travel, "", 1, 0,
     255, false},
    {P::MinPulse, "min_pulse_us", QT_TRANSLATE_NOOP("ptk", "Minimum pulse width"), Group::Travel,
     "µs", 4, 500, 1500, false},
    {P::MaxPulse, "max_pulse_us", QT_TRANSLATE_NOOP("ptk", "Maximum pulse width"), Group::Travel,
     "µs", 4, 1500, 2500, false},
    {P::Inversion, "inversion", QT_TRANSLATE_NOOP("ptk", "Inversion"), Group::Travel, "", 1, 0, 1,
     true},
    {P::MaxPower, "max_power", QT_TRANSLATE_NOOP("ptk", "Maximum power"), Group::Power, "", 1, 0,
     1200, false},
    {P::OverloadPower, "overload_power", QT_TRANSLATE_NOOP("ptk", "Overload protection power"),
     Group::Power, "", 1, 0, 1200, false},
    {P::OverloadTime, "overload_time_ms", QT_TRANSLATE_NOOP("ptk", "Overload protection time"),
     Group::Power, "ms", 1, 0, 60000, false},
    {P::SoftStart, "soft_start", QT_TRANSLATE_NOOP("ptk", "Soft start"), Group::Power, "", 1, 0, 1,
     true},
}};

const std::array<FrameLayout, 8> kQueries {{
    {"N1", 56, P::OverloadPower, P::OverloadTime},
    {"N2", 61, P::Gain, P::Damping},
    {"N3", 63, P::MaxPower, std::nullopt},
    {"N4", 80, P::MinPulse, P::MaxPulse},
    {"N5", 81, P::MinAngle, P::MaxAngle},
    {"N6", 82, P::Neutral, std::nullopt},
    {"N7", 83, P::Deadband, std::nullopt},
    {"N8", 84, P::Inversion, P::SoftStart},
}};

const std::array<FrameLayout, 12> kWrites {{
    {"N1", 1, P::Gain, std::nullopt},
    {"N2", 5, P::Damping, std::nullopt},
    {"N3", 18, P::OverloadPower, P::OverloadTime},
    {"N4", 24, P::MaxPower, std::nullopt},
    {"N5", 64, std::nullopt, P::MinAngle},
    {"N6", 65, std::nullopt, P::MaxAngle},
    {"N7", 66, std::nullopt, P::Neutral},
    {"N8", 67, std::nullopt, P::Deadband},
    {"N9", 68, std::nullopt, P::Inversion},
    {"N10", 69, std::nullopt, std::nullopt}, // meaning unknown; PTK always sends it, zeroed
    {"N11", 72, P::MinPulse, P::MaxPulse},
    {"N12", 70, std::nullopt, P::SoftStart},
}};

template<std::size_t N>
const FrameLayout *findLayout(const std::array<FrameLayout, N> &layouts, quint8 command)
{
    for (const FrameLayout &layout : layouts) {
        if (layout.command == command)
            return &layout;
    }
    return nullptr;
}

} // namespace

const std::array<ParameterInfo, kParameterCount> &parameterInfos()
{
    return kInfos;
}

const ParameterInfo &info(Parameter parameter)
{
    return kInfos[std::size_t(parameter)];
}

const ParameterInfo *findParameter(QStringView key)
{
    for (const ParameterInfo &candidate : kInfos) {
        if (key == QLatin1String(candidate.key))
            return &candidate;
    }
    return nullptr;
}

QString translatedLabel(Parameter parameter)
{
    return QCoreApplication::translate("ptk", info(parameter).label);
}

QVector<model::Definition> modelDefinitions()
{
    QVector<model::Definition> definitions;
    for (const ParameterInfo &meta : parameterInfos()) {
        model::Definition definition;
        definition.key = QLatin1String(meta.key);
        definition.label = translatedLabel(meta.parameter);
        definition.group = translatedGroup(meta.group);
        definition.unit = QString::fromUtf8(meta.unit);
        definition.scale = 1.0 / meta.wirePerUnit;
        definition.minimum = qint64(meta.minimum) * meta.wirePerUnit;
        definition.maximum = qint64(meta.maximum) * meta.wirePerUnit;
        definition.access = model::Access::ReadWrite;
        definition.storage = model::Storage::Ptk;
        if (meta.isSwitch)
            definition.choices = {{0, QCoreApplication::translate("ptk", "Off")},
                                  {1, QCoreApplication::translate("ptk", "On")}};
        definitions.append(definition);
    }
    return definitions;
}

std::optional<ParameterSet> parseAssignments(const QStringList &assignments, QString *error)
{
    const auto fail = [&](const QString &message) {
        if (error)
            *error = message;
        return std::nullopt;
    };
    ParameterSet values;
    for (const QString &assignment : assignments) {
        const int eq = assignment.indexOf(u'=');
        if (eq <= 0)
            return fail(
                QCoreApplication::translate("ptk", "\"%1\" is not NAME=VALUE").arg(assignment));
        const QString key = assignment.left(eq).trimmed();
        const QString text = assignment.mid(eq + 1).trimmed();
        const ParameterInfo *meta = findParameter(key);
        if (!meta) {
            QStringList known;
            for (const ParameterInfo &candidate : parameterInfos())
                known.append(QLatin1String(candidate.key));
            return fail(QCoreApplication::translate("ptk", "unknown parameter \"%1\" (known: %2)")
                            .arg(key, known.join(QStringLiteral(", "))));
        }
        double number = 0;
        bool ok = false;
        if (meta->isSwitch && (text == QLatin1String("on") || text == QLatin1String("true"))) {
            number = 1;
            ok = true;
        } else if (meta->isSwitch
                   && (text == QLatin1String("off") || text == QLatin1String("false"))) {
            ok = true;
        } else {
            number = text.toDouble(&ok);
        }
        if (!ok)
            return fail(
                QCoreApplication::translate("ptk", "%1: \"%2\" is not a number").arg(key, text));
        const auto wire = fromUserValue(meta->parameter, number, error);
        if (!wire)
            return std::nullopt;
        values.set(meta->parameter, *wire);
    }
    return values;
}

QString translatedGroup(Group group)
{
    switch (group) {
    case Group::Response:
        return QCoreApplication::translate("ptk", "Response");
    case Group::Travel:
        return QCoreApplication::translate("ptk", "Travel");
    case Group::Power:
        return QCoreApplication::translate("ptk", "Power");
    }
    return {};
}

const std::array<FrameLayout, 8> &queryLayouts()
{
    return kQueries;
}

const std::array<FrameLayout, 12> &writeLayouts()
{
    return kWrites;
}

const FrameLayout *findQuery(quint8 command)
{
    return findLayout(kQueries, command);
}

const FrameLayout *findWrite(quint8 command)
{
    return findLayout(kWrites, command);
}

bool ParameterSet::isComplete() const
{
    for (const auto &value : m_values) {
        if (!value)
            return false;
    }
    return true;
}

ParameterSet ParameterSet::seedSample(bool softStart)
{
    ParameterSet set;
    set.set(P::OverloadPower, 800);
    set.set(P::OverloadTime, 2000);
    set.set(P::Gain, 29);
    set.set(P::Damping, 12);
    set.set(P::MaxPower, 1200);
    set.set(P::MinPulse, 2000);
    set.set(P::MaxPulse, 10000);
    set.set(P::MinAngle, 65);
    set.set(P::MaxAngle, 65);
    set.set(P::Neutral, 4096);
    set.set(P::Deadband, 15);
    set.set(P::Inversion, 1);
    set.set(P::SoftStart, softStart ? 1 : 0);
    return set;
}

double toUserValue(Parameter parameter, quint16 wireValue)
{
    return double(wireValue) / info(parameter).wirePerUnit;
}

std::optional<quint16> fromUserValue(Parameter parameter, double userValue, QString *error)
{
    const ParameterInfo &meta = info(parameter);
    if (!std::isfinite(userValue) || userValue < meta.minimum || userValue > meta.maximum) {
        if (error) {
            *error = QCoreApplication::translate("ptk", "%1 must be between %2 and %3%4")
                         .arg(QLatin1String(meta.key))
                         .arg(meta.minimum)
                         .arg(meta.maximum)
                         .arg(*meta.unit ? u' ' + QString::fromUtf8(meta.unit) : QString());
        }
        return std::nullopt;
    }
    return quint16(std::lround(userValue * meta.wirePerUnit));
}

QVector<Parameter> applyReply(const FrameLayout &query, const Reply &reply, ParameterSet &values)
{
    QVector<Parameter> updated;
    if (query.word0) {
        values.set(*query.word0, reply.word0);
        updated.append(*query.word0);
    }
    if (query.word1) {
        values.set(*query.word1, reply.word1);
        updated.append(*query.word1);
    }
    return updated;
}

Reply replyFor(const FrameLayout &query, const ParameterSet &values)
{
    const auto word = [&](std::optional<Parameter> parameter) -> quint16 {
        return parameter ? values.value(*parameter).value_or(0) : 0;
    };
    return {word(query.word0), word(query.word1)};
}

std::optional<Request> writeRequest(const FrameLayout &layout, const ParameterSet &values)
{
    Request request {layout.command, 0, 0};
    for (const auto &[slot, target] :
         {std::pair {layout.word0, &request.word0}, std::pair {layout.word1, &request.word1}}) {
        if (!slot)
            continue;
        const auto value = values.value(*slot);
        if (!value)
            return std::nullopt;
        *target = *value;
    }
    return request;
}

std::optional<QVector<Request>> writeSequence(const ParameterSet &values)
{
    QVector<Request> sequence;
    for (const FrameLayout &layout : kWrites) {
        const auto request = writeRequest(layout, values);
        if (!request)
            return std::nullopt;
        sequence.append(*request);
    }
    return sequence;
}

QVector<Parameter> applyWrite(const FrameLayout &layout, const Request &request,
                              ParameterSet &values)
{
    return applyReply(layout, Reply {request.word0, request.word1}, values);
}

} // namespace ptk
