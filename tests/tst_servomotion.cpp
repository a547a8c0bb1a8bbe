// Tests the simulated servo's physics: moves toward the goal, load, current, heat, protections.
#include "servomotion.h"

#include <QtTest>

using sim::MotionCommand;
using sim::MotionControl;
using sim::ServoMotion;

namespace {

constexpr double kStep = 0.001; // the simulator's integration step, seconds
constexpr double kSupply = 7.4;

MotionCommand positionCommand(double goal, double speed, double acceleration)
{
    MotionCommand command;
    command.torqueEnable = 1;
    command.control = MotionControl::Position;
    command.goal = goal;
    command.maxSpeed = speed;
    command.acceleration = acceleration;
    return command;
}

void run(ServoMotion &motion, const MotionCommand &command, double seconds)
{
    for (int i = 0; i < int(std::lround(seconds / kStep)); ++i)
        motion.step(command, kStep);
}

} // namespace

class TestServoMotion : public QObject
{
    Q_OBJECT

private slots:
    void aFullCircleServoStartsAtTheMiddleAndAnScsServoAtHalfItsRange()
    {
        QCOMPARE(ServoMotion(true, kSupply).position(), 2048.0);
        QCOMPARE(ServoMotion(false, kSupply).position(), 512.0);
    }

    void positionApproachesTheGoalAtTheSetSpeed()
    {
        ServoMotion motion(true, kSupply);
        const MotionCommand command = positionCommand(3048, 500, ServoMotion::kFastAcceleration);
        run(motion, command, 1.0);
        // 1000 steps at 500 step/s: halfway after one second, cruising at the set speed.
        QVERIFY2(qAbs(motion.position() - 2548.0) < 20.0,
                 qPrintable(QString::number(motion.position())));
        QVERIFY(qAbs(motion.velocity() - 500.0) < 1.0);
        QVERIFY(motion.turning());
        run(motion, command, 1.5);
        QCOMPARE(motion.position(), 3048.0);
        QCOMPARE(motion.velocity(), 0.0);
        QVERIFY(!motion.turning());
    }

    void aLowAccelerationRampsTheSpeedUp()
    {
        ServoMotion motion(true, kSupply);
        run(motion, positionCommand(4000, 3400, 1000), 0.1);
        // 1000 step/s² for 0.1 s: about 100 step/s, far below the speed limit.
        QVERIFY2(qAbs(motion.velocity() - 100.0) < 2.0,
                 qPrintable(QString::number(motion.velocity())));
    }

    void positionsWrapAroundTheFullCircle()
    {
        ServoMotion motion(true, kSupply);
        motion.setPosition(4096 + 10);
        QCOMPARE(motion.position(), 10.0);
        motion.setPosition(-6);
        QCOMPARE(motion.position(), 4090.0);
        QCOMPARE(motion.presentCoordinate(100), 3990.0);
    }

    void anScsServoStopsAtItsEndStops()
    {
        ServoMotion motion(false, kSupply);
        MotionCommand command;
        command.torqueEnable = 1;
        command.control = MotionControl::Wheel;
        command.acceleration = ServoMotion::kFastAcceleration;
        command.openLoopSpeed = 1000;
        run(motion, command, 1.0);
        QCOMPARE(motion.position(), double(ServoMotion::kScsMaxPosition));
        QCOMPARE(motion.velocity(), 0.0);
    }

    void aFreeHornStaysWhereItIsAndDrawsIdleCurrent()
    {
        ServoMotion motion(true, kSupply);
        MotionCommand command = positionCommand(3000, 1000, 1000);
        command.torqueEnable = 0;
        run(motion, command, 0.5);
        QCOMPARE(motion.position(), 2048.0);
        QCOMPARE(motion.loadPermille(), 0.0);
        QCOMPARE(motion.amps(), ServoMotion::kIdleAmps);
    }

    void aDampedHornCoastsToAStop()
    {
        ServoMotion motion(true, kSupply);
        run(motion, positionCommand(4000, 1000, ServoMotion::kFastAcceleration), 0.5);
        QVERIFY(motion.velocity() > 900.0);
        MotionCommand damped;
        damped.torqueEnable = 2;
        run(motion, damped, 1.0);
        QCOMPARE(motion.velocity(), 0.0);
    }

    void anExternalLoadRaisesLoadCurrentAndSupplySag()
    {
        ServoMotion motion(true, kSupply);
        const MotionCommand hold = positionCommand(2048, 1000, 1000);
        run(motion, hold, 0.01);
        const double idleVolts = motion.terminalVolts();
        motion.setExternalLoad(500);
        run(motion, hold, 0.01);
        QCOMPARE(motion.loadPermille(), 500.0);
        QCOMPARE(motion.amps(), ServoMotion::kIdleAmps + 0.5 * ServoMotion::kStallAmps);
        QVERIFY(motion.terminalVolts() < idleVolts);
    }

    void aLoadAtTheTorqueLimitBlocksTheHorn()
    {
        ServoMotion motion(true, kSupply);
        MotionCommand command = positionCommand(3000, 1000, ServoMotion::kFastAcceleration);
        command.torqueLimit = 400;
        motion.setExternalLoad(400);
        run(motion, command, 0.5);
        QCOMPARE(motion.position(), 2048.0);
        QCOMPARE(motion.loadPermille(), 400.0);
    }

    void temperatureRisesTowardItsSteadyStateUnderLoad()
    {
        ServoMotion motion(true, kSupply);
        motion.setExternalLoad(1000);
        const MotionCommand hold = positionCommand(2048, 1000, 1000);
        run(motion, hold, 60.0);
        const double afterAMinute = motion.temperature();
        QVERIFY(afterAMinute > ServoMotion::kDefaultAmbientCelsius + 5.0);
        const double steady = ServoMotion::kDefaultAmbientCelsius
            + ServoMotion::kThermalRiseCelsiusPerAmp
                * (ServoMotion::kIdleAmps + ServoMotion::kStallAmps);
        QVERIFY(afterAMinute < steady);
    }

    void holdingAnOverloadForTheProtectionTimeTripsIt()
    {
        ServoMotion motion(true, kSupply);
        MotionCommand command = positionCommand(2048, 1000, 1000);
        command.overloadTorque = 800;
        command.protectionSeconds = 0.2;
        command.holdingTorque = 200;
        motion.setExternalLoad(900);
        run(motion, command, 0.1);
        QVERIFY(!motion.overloaded());
        run(motion, command, 0.15);
        QVERIFY(motion.overloaded());
        // Tripped, the motor may push only its holding torque.
        QCOMPARE(motion.loadPermille(), 200.0);
        motion.clearOverload();
        QVERIFY(!motion.overloaded());
    }

    void overheatingStopsTheMotorAndAsksForTorqueOff()
    {
        ServoMotion motion(true, kSupply);
        MotionCommand command = positionCommand(4000, 1000, ServoMotion::kFastAcceleration);
        command.maxTemperature = 70;
        QVERIFY(!motion.step(command, kStep));
        motion.setTemperature(70.0);
        QVERIFY(motion.step(command, kStep));
        QCOMPARE(motion.velocity(), 0.0);
    }

    void stoppingKeepsPositionAndTemperature()
    {
        ServoMotion motion(true, kSupply);
        run(motion, positionCommand(3000, 1000, ServoMotion::kFastAcceleration), 0.3);
        motion.setTemperature(40.0);
        const double position = motion.position();
        motion.stop();
        QCOMPARE(motion.position(), position);
        QCOMPARE(motion.temperature(), 40.0);
        QCOMPARE(motion.velocity(), 0.0);
        QCOMPARE(motion.amps(), ServoMotion::kIdleAmps);
    }
};

QTEST_APPLESS_MAIN(TestServoMotion)
#include "tst_servomotion.moc"
