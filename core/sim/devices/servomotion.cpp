// Simulated servo physics: acceleration-limited moves, load, current, supply sag, heating and
// the overload and overheating protections (spec §8-§9 behaviour, simplified).
#include "servomotion.h"

#include <algorithm>
#include <cmath>

namespace sim {

namespace {

int sign(double value)
{
    return value > 0 ? 1 : (value < 0 ? -1 : 0);
}

} // namespace

double ServoMotion::wrapFullCircle(double steps)
{
    double wrapped = std::fmod(steps, double(kFullCircleSteps));
    if (wrapped < 0)
        wrapped += kFullCircleSteps;
    return wrapped;
}

int ServoMotion::wrapFullCircle(int steps)
{
    return ((steps % kFullCircleSteps) + kFullCircleSteps) % kFullCircleSteps;
}

ServoMotion::ServoMotion(bool fullCircle, double supplyVolts)
    : m_fullCircle(fullCircle)
    , m_supplyVolts(supplyVolts)
{
    m_position = fullCircle ? kFullCircleSteps / 2 : (kScsMaxPosition + 1) / 2;
}

bool ServoMotion::step(const MotionCommand &asked, double dt)
{
    MotionCommand command = asked;
    if (m_latched)
        command.torqueEnable = 0; // a latched fault: the motor pushes nothing
    const double previous = m_velocity;
    const double limit = command.torqueEnable == 1 && command.control != MotionControl::OpenLoop
        ? command.acceleration
        : kFastAcceleration;
    move(command, dt);
    if (m_fullCircle) {
        m_position = wrapFullCircle(m_position);
    } else if (m_position < 0.0 || m_position > kScsMaxPosition) {
        m_position = std::clamp(m_position, 0.0, double(kScsMaxPosition));
        m_velocity = 0.0; // end stop
    }
    updateLoadAndHeat(command, limit, previous, dt);
    updateOverload(command, dt);

    // Overheating switches the torque off.
    if (command.torqueEnable != 0 && command.maxTemperature
        && std::lround(m_temperature) >= *command.maxTemperature) {
        m_velocity = 0.0;
        return true;
    }
    return false;
}

double ServoMotion::torqueCap(const MotionCommand &command) const
{
    double cap = command.torqueLimit;
    if (m_overloaded && command.holdingTorque)
        cap = std::min(cap, *command.holdingTorque);
    return cap;
}

void ServoMotion::move(const MotionCommand &command, double dt)
{
    if (command.torqueEnable == 2) {
        m_velocity *= std::exp(-dt / kDampingTimeConstantS);
        if (std::abs(m_velocity) < 1.0)
            m_velocity = 0.0;
        m_position += m_velocity * dt;
        return;
    }
    if (command.torqueEnable != 1) {
        m_velocity = 0.0; // free: the horn stays where it is (nobody turns it)
        return;
    }
    const double cap = torqueCap(command);
    const bool blocked = cap <= 0 || std::abs(m_externalLoad) >= cap;
    const double limit =
        command.control == MotionControl::OpenLoop ? kFastAcceleration : command.acceleration;
    if (command.control == MotionControl::Position) {
        moveToGoal(command, limit, blocked, dt);
        return;
    }
    const double maxChange = limit * dt;
    m_velocity = blocked
        ? 0.0
        : m_velocity + std::clamp(command.openLoopSpeed - m_velocity, -maxChange, maxChange);
    m_position += m_velocity * dt;
}

void ServoMotion::moveToGoal(const MotionCommand &command, double limit, bool blocked, double dt)
{
    const double maxChange = limit * dt;
    const double here = presentCoordinate(command.offset);
    const double target = command.goal;
    const double distance = target - here;
    // As fast as allowed, but slow enough to stop at the target with this acceleration.
    const double desired =
        sign(distance) * std::min(command.maxSpeed, std::sqrt(2.0 * limit * std::abs(distance)));
    m_velocity =
        blocked ? 0.0 : m_velocity + std::clamp(desired - m_velocity, -maxChange, maxChange);
    double next = here + m_velocity * dt;
    // Reaching or passing the target ends the move there.
    if (!blocked && (distance == 0.0 || (next - target) * sign(distance) >= 0.0)
        && std::abs(distance) <= std::abs(m_velocity * dt) + 1e-9) {
        next = target;
        m_velocity = 0.0;
    }
    m_position = m_fullCircle ? wrapFullCircle(next + command.offset) : next;
}

void ServoMotion::updateLoadAndHeat(const MotionCommand &command, double limit,
                                    double previousVelocity, double dt)
{
    m_appliedAcceleration = std::clamp((m_velocity - previousVelocity) / dt, -limit, limit);

    // Load: what the motor has to push, capped at what it may push.
    if (command.torqueEnable == 0) {
        m_loadPermille = 0.0;
    } else {
        double load = kLoadPerAcceleration * m_appliedAcceleration + m_externalLoad;
        if (turning())
            load += sign(m_velocity) * (kFrictionLoad + kViscousLoad * std::abs(m_velocity));
        const double cap =
            command.torqueEnable == 1 ? std::min(1000.0, torqueCap(command)) : 1000.0;
        m_loadPermille = std::clamp(load, -cap, cap);
    }
    m_amps = kIdleAmps + std::abs(m_loadPermille) / 1000.0 * kStallAmps;

    const double steady = m_ambient + kThermalRiseCelsiusPerAmp * m_amps;
    m_temperature += (steady - m_temperature) * (1.0 - std::exp(-dt / kThermalTimeConstantS));
    m_temperature += m_extraHeatPerSecond * dt;
}

void ServoMotion::updateOverload(const MotionCommand &command, double dt)
{
    // |load| at or above the overload torque for the protection time trips it.
    if (command.torqueEnable == 0 || !command.overloadTorque) {
        m_overloadSeconds = 0.0;
        return;
    }
    if (std::abs(m_loadPermille) >= *command.overloadTorque) {
        m_overloadSeconds += dt;
        if (m_overloadSeconds >= command.protectionSeconds - 1e-9)
            m_overloaded = true;
    } else {
        m_overloadSeconds = 0.0;
    }
}

void ServoMotion::stop()
{
    m_velocity = 0.0;
    m_appliedAcceleration = 0.0;
    m_loadPermille = 0.0;
    m_amps = kIdleAmps;
    m_latched = false;
    clearOverload();
}

void ServoMotion::clearOverload()
{
    if (m_latched)
        return;
    m_overloaded = false;
    m_overloadSeconds = 0.0;
}

void ServoMotion::setOverloadLatched(bool latched)
{
    m_latched = latched;
    if (latched)
        m_overloaded = true;
    else
        clearOverload();
}

double ServoMotion::presentCoordinate(double offset) const
{
    return m_fullCircle ? wrapFullCircle(m_position - offset) : m_position;
}

bool ServoMotion::turning() const
{
    return std::abs(m_velocity) > kStoppedSpeed;
}

void ServoMotion::setExternalLoad(int permille)
{
    m_externalLoad = std::clamp(permille, -1000, 1000);
}

void ServoMotion::setPosition(double steps)
{
    m_position =
        m_fullCircle ? wrapFullCircle(steps) : std::clamp(steps, 0.0, double(kScsMaxPosition));
}

void ServoMotion::turnByHand(double steps, double stepsPerSecond)
{
    setPosition(steps);
    m_velocity = stepsPerSecond;
}

} // namespace sim
