// servosim's options: the command line, the --servo and --hand specs, the robots it plays.
#pragma once

#include "faultsettings.h"
#include "hand.h"
#include "optionerror.h"
#include "robottemplate.h"
#include "usbadapter.h"
#include "virtualfeetechbus.h"

#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace sim {

using FeetechServoSpec = VirtualFeetechBus::ServoSpec;

// A scripted sweep of the hand (sim/hand.h), from the command line or standard input.
struct HandSweep
{
    quint8 id = 1;
    int from = 0;
    int to = 0;
    double seconds = 1.0;
    int cycles = 0; // 0: until released
    Hand::Way way = Hand::Way::Direct;
};

// ID:MODEL[@BAUD], as --servo and the plug command take it; `source` names it in errors.
std::optional<FeetechServoSpec> parseServoSpec(const QString &text, const QString &source,
                                               OptionError *error);
// FIELDS are ID FROM TO SECONDS [CYCLES] [up|down], already split; `source` names them in errors.
std::optional<HandSweep> parseHandSweep(const QStringList &fields, const QString &source,
                                        OptionError *error);
// The built-in robot templates servosim plays: so100, so101 (follower arms), so100-leader,
// so101-leader. Nothing and *error (UnknownRobot) for another name.
std::optional<feetech::RobotTemplate> simulatedRobot(const QString &name, OptionError *error);
// The robot's joints as servos on the bus, at the template's rate.
QVector<FeetechServoSpec> robotServos(const feetech::RobotTemplate &robot);

struct SimulatorOptions
{
    enum class Kind { Ptk, Feetech };
    Kind kind = Kind::Ptk;
    QString linkPath; // the pty's link, or the in-process port's name
    // The window's demo: offered as a port inside this program (seriallink::InProcessPort) that
    // the link reaches without a pseudo-terminal, not as a pty.
    bool inProcess = false;
    bool echo = false; // answer every host byte back first, like a single-wire adapter
    FaultSettings faults;
    quint32 seed = 1;
    QString logPath;
    qint64 replyDelayUs = 0; // added to every reply's turnaround
    // --adapter: replies reach the program as through this USB adapter; none: as a pty gives
    // them (ideal).
    std::optional<AdapterProfile> adapter;
    // --adapter instant: a device that answers the moment a frame is complete, in no wire time
    // and with no return delay (a virtual port, an emulator, a USB CDC device).
    bool instant = false;
    QString ptkValues; // "gain=20,..." starting values of the PTK servo
    QVector<FeetechServoSpec> servos;
    QString statePath; // Feetech: keeps EEPROM across runs
    bool allowSharedIds = false; // two --servo at one ID and rate, replies colliding
    // --robot: its joints are the first servos, set up with its settings, horns at rest.
    std::optional<feetech::RobotTemplate> robot;
    QVector<HandSweep> sweeps; // --hand, started with the bus
    QStringList commands; // --command: standard-input commands run before "ready"
};

// Parses servosim's arguments (program name excluded); nothing and *error on a bad one.
std::optional<SimulatorOptions> parseSimulatorArguments(const QStringList &arguments,
                                                        QString *error);
QString simulatorUsage();

} // namespace sim
