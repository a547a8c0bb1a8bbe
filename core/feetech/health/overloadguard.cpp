// The overload and thermal guard's rules: limits from the register table, decisions, messages.
#include "overloadguard.h"
#include "feetechguardtr.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace feetech {

namespace {

constexpr double kFallbackLoadPercent = 80.0;
constexpr double kFallbackMaxTemperature = 70.0;
constexpr std::chrono::milliseconds kLongestHold {1000};
constexpr std::chrono::milliseconds kShortestHold {200};

// The register's value in its unit (the servo's own where known, else the factory default).
std::optional<double> limitValue(const RegisterTable &table, QStringView key,
                                 const RegisterLookup &lookup)
{
    const Register *reg = table.find(key);
    if (!reg)
        return std::nullopt;
    std::optional<qint32> raw = lookup ? lookup(key) : std::nullopt;
    if (!raw)
        raw = reg->defaultValue;
    if (!raw)
        return std::nullopt;
    return double(*raw) * reg->scale;
}

QString figure(double value)
{
    return QString::number(value, 'f', std::abs(value) < 10.0 ? 1 : 0);
}

} // namespace

QString guardActionKey(GuardAction action)
{
    return action == GuardAction::Hold ? QStringLiteral("hold") : QStringLiteral("torque-off");
}

QString guardActionName(GuardAction action)
{
    return action == GuardAction::Hold ? FeetechGuardTr::tr("Hold where it stands")
                                       : FeetechGuardTr::tr("Torque off");
}

std::optional<GuardAction> guardActionFromKey(QStringView key)
{
    for (const GuardAction action : {GuardAction::Hold, GuardAction::TorqueOff}) {
        if (key.compare(guardActionKey(action), Qt::CaseInsensitive) == 0)
            return action;
    }
    return std::nullopt;
}

bool GuardLimits::operator==(const GuardLimits &other) const
{
    return enabled == other.enabled && loadPercent == other.loadPercent
        && currentMilliamps == other.currentMilliamps && holdTime == other.holdTime
        && maxTemperature == other.maxTemperature && temperatureMargin == other.temperatureMargin
        && temperatureWarnMargin == other.temperatureWarnMargin && action == other.action;
}

GuardLimits defaultGuardLimits(const RegisterTable &table, const RegisterLookup &lookup)
{
    GuardLimits limits;
    const auto overload = limitValue(table, u"overload_torque", lookup);
    limits.loadPercent = overload && *overload > 0 ? *overload : kFallbackLoadPercent;
    if (!overload) {
        // No overload torque to compare the load with: the protection current says when the
        // motor works too hard.
        const auto protection = limitValue(table, u"protection_current", lookup);
        if (protection && *protection > 0)
            limits.currentMilliamps = *protection;
    }
    // Act well before the servo's own protection would trip: within a quarter of its
    // protection time, so a late sample still comes in time.
    if (const auto protectionMs = limitValue(table, u"protection_time", lookup);
        protectionMs && *protectionMs > 0) {
        const auto quarter = std::chrono::milliseconds(std::llround(*protectionMs / 4.0));
        limits.holdTime = std::clamp(quarter, kShortestHold, kLongestHold);
    }
    const auto maxTemperature = limitValue(table, u"max_temperature", lookup);
    limits.maxTemperature =
        maxTemperature && *maxTemperature > 0 ? *maxTemperature : kFallbackMaxTemperature;
    return limits;
}

quint8 overloadStatusBit(const RegisterTable &table)
{
    if (const Register *status = table.find(u"status")) {
        for (const BitName &bit : status->bits) {
            if (bit.label.compare(QLatin1String("Load"), Qt::CaseInsensitive) == 0)
                return quint8(1u << bit.bit);
        }
    }
    return 0x20;
}

QString guardEventText(const GuardEvent &event, const GuardLimits &limits)
{
    const QString servo = FeetechGuardTr::tr("Servo ID %1").arg(event.id);
    const QString seconds = QString::number(double(limits.holdTime.count()) / 1000.0, 'f', 1);
    const QString action = event.action == GuardAction::Hold
        ? (event.heldAt
               ? FeetechGuardTr::tr("its goal was set to where it stands (%1)").arg(*event.heldAt)
               : FeetechGuardTr::tr("its goal was set to where it stands"))
        : FeetechGuardTr::tr("its torque was switched off");
    const QString seen = event.cause == GuardCause::Heat
        ? FeetechGuardTr::tr("temperature %1 °C, its maximum is %2 °C")
              .arg(figure(event.value), figure(limits.maxTemperature))
        : event.current ? FeetechGuardTr::tr("current %1 mA above the guard's %2 mA")
                              .arg(figure(std::abs(event.value)), figure(event.limit))
                        : FeetechGuardTr::tr("load %1 % above the guard's %2 %")
                              .arg(figure(std::abs(event.value)), figure(event.limit));
    switch (event.stage) {
    case GuardStage::Warning:
        if (event.cause == GuardCause::LatchedOverload)
            return FeetechGuardTr::tr(
                       "%1: its own overload protection tripped (status bit Load is set); its "
                       "torque is off. Use Recover to switch it off and on again.")
                .arg(servo);
        if (event.cause == GuardCause::Heat)
            return FeetechGuardTr::tr("Guard warning: %1 is hot (%2); the guard acts at %3 °C.")
                .arg(servo, seen, figure(limits.maxTemperature - limits.temperatureMargin));
        return FeetechGuardTr::tr(
                   "Guard warning: %1 is straining (%2); the guard acts if it lasts %3 s.")
            .arg(servo, seen, seconds);
    case GuardStage::Acted:
        if (!event.ok)
            return FeetechGuardTr::tr(
                       "Guard: %1 (%2) could not be stopped: %3. Switch its torque off.")
                .arg(servo, seen, event.message);
        return event.cause == GuardCause::Heat
            ? FeetechGuardTr::tr("Guard: %1 was too hot (%2): %3.").arg(servo, seen, action)
            : FeetechGuardTr::tr("Guard: %1 was overloaded for %2 s (%3): %4.")
                  .arg(servo, seconds, seen, action);
    case GuardStage::StillLoaded:
        return FeetechGuardTr::tr(
                   "Guard: %1 is held but still loaded (%2): free the horn or switch its torque "
                   "off before its own protection trips.")
            .arg(servo, seen);
    case GuardStage::Cleared:
        return FeetechGuardTr::tr("%1: the overload protection is no longer tripped.").arg(servo);
    }
    return {};
}

// ---- the guard

void OverloadGuard::setSettings(const GuardSettings &settings)
{
    m_settings = settings;
}

GuardLimits OverloadGuard::limitsFor(const ServoInfo &info) const
{
    const auto set = m_settings.servos.constFind({info.id, info.baud});
    if (set != m_settings.servos.constEnd())
        return *set;
    return info.hasTable() ? defaultGuardLimits(info.table()) : GuardLimits {};
}

QVector<GuardDecision> OverloadGuard::observe(const ServoInfo &info, const FeedbackSample &sample)
{
    QVector<GuardDecision> decisions;
    if (!m_settings.enabled || !info.hasTable())
        return decisions;
    const GuardLimits limits = limitsFor(info);
    if (!limits.enabled)
        return decisions;
    State &state = m_states[{info.id, info.baud}];
    // The servo's own protection: reported once while it stays tripped, and when it clears.
    const bool latched = (sample.servoStatus & overloadStatusBit(info.table())) != 0;
    if (latched != state.latchSeen) {
        state.latchSeen = latched;
        decisions.append({GuardCause::LatchedOverload,
                          latched ? GuardStage::Warning : GuardStage::Cleared, 0.0, 0.0, false});
    }
    observeOverload(state, limits, sample, decisions);
    observeHeat(state, limits, sample, decisions);
    return decisions;
}

void OverloadGuard::observeOverload(State &state, const GuardLimits &limits,
                                    const FeedbackSample &sample, QVector<GuardDecision> &out) const
{
    std::optional<GuardDecision> over;
    if (const auto load = sample.value(Quantity::Load);
        load && std::abs(*load) > limits.loadPercent)
        over = GuardDecision {GuardCause::Overload, GuardStage::Warning, *load, limits.loadPercent,
                              false};
    else if (const auto current = sample.value(Quantity::Current);
             current && limits.currentMilliamps && std::abs(*current) > *limits.currentMilliamps)
        over = GuardDecision {GuardCause::Overload, GuardStage::Warning, *current,
                              *limits.currentMilliamps, true};
    if (!over) {
        state.overloadSinceUs.reset();
        state.overloadWarned = state.overloadActed = state.stillLoadedSaid = false;
        return;
    }
    if (!state.overloadSinceUs)
        state.overloadSinceUs = sample.steadyUs;
    const qint64 lastedUs = sample.steadyUs - *state.overloadSinceUs;
    const qint64 holdUs = qint64(limits.holdTime.count()) * 1000;
    if (!state.overloadWarned && lastedUs >= holdUs / 2) {
        state.overloadWarned = true;
        out.append(*over);
    }
    if (lastedUs < holdUs)
        return;
    if (!state.overloadActed) {
        if (!state.overloadWarned) { // a sample gap longer than half the hold: warn first
            state.overloadWarned = true;
            out.append(*over);
        }
        state.overloadActed = true;
        over->stage = GuardStage::Acted;
        out.append(*over);
        // The action is one hold time old from here: still loaded after another one says so.
        state.overloadSinceUs = sample.steadyUs;
        return;
    }
    if (!state.stillLoadedSaid && limits.action == GuardAction::Hold) {
        state.stillLoadedSaid = true;
        over->stage = GuardStage::StillLoaded;
        out.append(*over);
    }
}

void OverloadGuard::observeHeat(State &state, const GuardLimits &limits,
                                const FeedbackSample &sample, QVector<GuardDecision> &out) const
{
    const auto temperature = sample.value(Quantity::Temperature);
    if (!temperature)
        return;
    const double warnAt = limits.maxTemperature - limits.temperatureWarnMargin;
    const double actAt = limits.maxTemperature - limits.temperatureMargin;
    if (*temperature < std::min(warnAt, actAt)) {
        state.heatWarned = state.heatActed = false; // cooled down: a new episode later
        return;
    }
    const GuardDecision heat {GuardCause::Heat, GuardStage::Warning, *temperature,
                              limits.maxTemperature, false};
    if (!state.heatWarned) {
        state.heatWarned = true;
        out.append(heat);
    }
    if (*temperature >= actAt && !state.heatActed) {
        state.heatActed = true;
        GuardDecision acted = heat;
        acted.stage = GuardStage::Acted;
        out.append(acted);
    }
}

void OverloadGuard::rearm(quint8 id, qint32 baud)
{
    const auto state = m_states.find({id, baud});
    if (state == m_states.end())
        return;
    // Only after an action: a goal asked for again and again against a block (a slider
    // dragged) must not put the action off for ever.
    if (state->overloadActed) {
        state->overloadSinceUs.reset();
        state->overloadWarned = state->overloadActed = state->stillLoadedSaid = false;
    }
    // Still hot: a new goal is held again at once, with a new message.
    state->heatActed = false;
}

void OverloadGuard::forget(quint8 id, qint32 baud)
{
    m_states.remove({id, baud});
}

} // namespace feetech
