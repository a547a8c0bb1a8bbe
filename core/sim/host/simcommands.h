// servosim's commands on standard input: one line in, one reply line out ("ok ..." or
// "error ..."), and the servo list the GUI's Simulator dock shows too.
#pragma once

#include <QString>
#include <QVector>

#include <optional>

namespace sim {

class Simulator;
class VirtualFeetechBus;

// One simulated Feetech servo as a user sees it on the bench.
struct SimulatedServo
{
    int index = 0; // place on the bus, from 0; shown as #index+1
    int id = 0;
    qint32 baud = 0;
    QString model;
    int position = 0; // present position
    int maxPosition = 4095;
    bool torqueOn = false;
    bool sweeping = false; // the hand is sweeping it
    // Bench cases (see the power, break-chain, supply, heat, block and latch commands).
    bool powered = true; // its own switch and the daisy chain
    bool blocked = false; // something holds the horn
    bool overloadLatched = false;
    double heatPerSecond = 0.0; // °C/s on top of its own heating
    int temperature = 0; // °C, as its register says
    double supplyVolts = 0.0;
};

// What is wrong on the bench for `servo`, as short words for a list ("no power, blocked horn");
// empty when nothing is.
QString benchCondition(const SimulatedServo &servo);

QVector<SimulatedServo> simulatedServos(VirtualFeetechBus &bus);

// A servo named by ID (the only one at that ID) or by place as "#N" (from 1, as list shows).
std::optional<int> servoIndex(const VirtualFeetechBus &bus, const QString &reference,
                              QString *error);

// Runs one command line on the simulator (in its thread) and returns the reply line; an empty
// reply for a blank line. Brings the simulator to the present moment first.
QString runSimulatorCommand(const QString &line, Simulator &simulator);
QString simulatorCommandHelp();

} // namespace sim
