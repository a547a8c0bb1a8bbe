// The physics of one simulated servo: the horn's motion toward its goal, the load and current
// the motor draws, the supply's sag and the motor's temperature. Pure logic: time passes
// through step().
#pragma once

#include <optional>

namespace sim {

// How the motor is driven (spec §8 operating modes, as far as the simulator plays them).
enum class MotionControl { Position, Wheel, OpenLoop };

// What the register file asks of the motor for one step, in steps, seconds and permille.
struct MotionCommand
{
    int torqueEnable = 0; // 0 free, 1 driven, 2 damped (coasts to a stop)
    MotionControl control = MotionControl::Position;
    double goal = 0.0; // position mode: the target in present coordinates
    double offset = 0.0; // present = physical - offset (full-circle servos)
    double maxSpeed = 0.0; // position mode, step/s
    double acceleration = 0.0; // position and wheel modes, step/s^2
    double openLoopSpeed = 0.0; // wheel and open-loop modes: the speed asked for, signed
    double torqueLimit = 1000.0; // what the motor may push
    std::optional<double> holdingTorque; // what it may push after an overload trip
    std::optional<double> overloadTorque; // load that trips the overload protection...
    double protectionSeconds = 0.0; // ...when held this long
    std::optional<int> maxTemperature; // degrees C at which the torque switches off
};

class ServoMotion
{
public:
    // Motion model. Speed 0 and acceleration 0 in the registers mean "the model's maximum".
    static constexpr double kMaxSpeedFullCircle = 3400.0; // STS / SMS / HLS, step/s
    static constexpr double kMaxSpeedScs = 1000.0; // SCS, step/s
    static constexpr double kFastAcceleration = 50000.0; // step/s^2 when register 41 is 0
    static constexpr double kDampingTimeConstantS = 0.05; // torque enable 2: speed decay
    static constexpr double kStoppedSpeed = 0.5; // step/s: below this the horn stands still

    // Load model (permille of full torque) and electrical / thermal model.
    static constexpr double kLoadPerAcceleration = 0.004; // permille per step/s^2 applied
    static constexpr double kFrictionLoad = 30.0; // permille while moving
    static constexpr double kViscousLoad = 0.01; // permille per step/s while moving
    static constexpr double kIdleAmps = 0.05;
    static constexpr double kStallAmps = 3.0; // added at |load| = 1000 permille
    static constexpr double kSupplyResistanceOhms = 0.2; // voltage sag with current
    static constexpr double kThermalRiseCelsiusPerAmp = 15.0; // steady state above ambient
    static constexpr double kThermalTimeConstantS = 120.0;
    static constexpr double kDefaultAmbientCelsius = 25.0;

    static constexpr int kFullCircleSteps = 4096;
    static constexpr int kScsMaxPosition = 1023;

    // A position on the 4096-step circle, in 0-4095.
    static double wrapFullCircle(double steps);
    static int wrapFullCircle(int steps);

    // A full-circle servo (STS, SMS, HLS) wraps at 4096 steps; an SCS stops at 0 and 1023.
    ServoMotion(bool fullCircle, double supplyVolts);

    // Advances by dt seconds. True when the motor overheated: it stopped, and the caller
    // switches the torque off in its registers.
    bool step(const MotionCommand &command, double dt);

    // Power-on: the horn stays where it is and as warm as it is, but nothing moves or draws.
    void stop();
    // Re-arming the torque clears an overload trip, unless it is latched.
    void clearOverload();
    // A latched overload (a fault the servo cannot clear by itself): the overload stays
    // tripped and the motor pushes nothing, whatever the torque enable says, until stop()
    // (a power cycle) or setOverloadLatched(false).
    void setOverloadLatched(bool latched);
    bool overloadLatched() const { return m_latched; }

    double maxSpeed() const { return m_fullCircle ? kMaxSpeedFullCircle : kMaxSpeedScs; }
    double position() const { return m_position; } // horn, encoder steps
    double presentCoordinate(double offset) const; // position - offset, in the position range
    double velocity() const { return m_velocity; }
    bool turning() const;
    double loadPermille() const { return m_loadPermille; }
    double amps() const { return m_amps; }
    double terminalVolts() const { return m_supplyVolts - m_amps * kSupplyResistanceOhms; }
    double temperature() const { return m_temperature; }
    double supplyVoltage() const { return m_supplyVolts; }
    bool overloaded() const { return m_overloaded; }

    // Environment.
    void setSupplyVoltage(double volts) { m_supplyVolts = volts; }
    void setAmbientTemperature(double celsius) { m_ambient = celsius; }
    void setExternalLoad(int permille); // signed, +-1000; |load| >= torque cap blocks the horn
    int externalLoad() const { return m_externalLoad; }
    void setTemperature(double celsius) { m_temperature = celsius; }
    void setPosition(double steps); // puts the horn there at once
    // A hand turning the free horn: at `steps` now, going `stepsPerSecond` (signed). The speed
    // is what the encoder sees until the next step() of a motor that drives or holds.
    void turnByHand(double steps, double stepsPerSecond);
    // Heat from outside the model (a stalled gearbox, a hot enclosure): the temperature rises
    // this much a second on top of the model's own heating, until set back to 0.
    void setTemperatureRise(double celsiusPerSecond) { m_extraHeatPerSecond = celsiusPerSecond; }
    double temperatureRise() const { return m_extraHeatPerSecond; }

private:
    double torqueCap(const MotionCommand &command) const;
    void move(const MotionCommand &command, double dt);
    void moveToGoal(const MotionCommand &command, double limit, bool blocked, double dt);
    void updateLoadAndHeat(const MotionCommand &command, double limit, double previousVelocity,
                           double dt);
    void updateOverload(const MotionCommand &command, double dt);

    bool m_fullCircle = true;
    double m_position = 0.0; // horn, encoder steps
    double m_velocity = 0.0; // step/s
    double m_appliedAcceleration = 0.0; // step/s^2, last step
    double m_loadPermille = 0.0;
    double m_amps = kIdleAmps;
    double m_temperature = kDefaultAmbientCelsius;
    double m_ambient = kDefaultAmbientCelsius;
    double m_supplyVolts = 0.0;
    int m_externalLoad = 0;
    double m_overloadSeconds = 0.0;
    bool m_overloaded = false;
    bool m_latched = false;
    double m_extraHeatPerSecond = 0.0;
};

} // namespace sim
