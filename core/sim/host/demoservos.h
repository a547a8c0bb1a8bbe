// Simulated servos inside the application, so ServoBench can be tried before hardware arrives.
#pragma once

#include "simrefusal.h"
#include "simulatorthread.h"

#include <QTemporaryDir>

#include <memory>

namespace sim {

// Starts each simulator on first use, offered as a port inside this program
// (seriallink::InProcessPort) under a name the user reads ("Simulated SO-101 arm"), its EEPROM
// kept in a private temporary folder, and stops them all when destroyed. No pseudo-terminal: a
// link reaches them by queued calls between its thread and theirs.
class DemoServos
{
public:
    DemoServos() = default;
    ~DemoServos();
    DemoServos(const DemoServos &) = delete;
    DemoServos &operator=(const DemoServos &) = delete;

    // Each port is the name a link opens (LinkSession, PortProbe), empty when its simulator cannot
    // start, and *why says why: NoDemoFolder (the private folder could not be made), NoDemoRobot
    // (an arm's built-in template did not load) or DemoNotStarted (the simulator refused to start).

    // The port of the simulated PTK servo.
    QString ptkPort(SimRefusal *why);
    // The port of the simulated Feetech bus: three STS3215, an SCS15 and an HLS at 1 Mbps.
    QString feetechPort(SimRefusal *why);
    // The port of a simulated SO-101 follower arm: six STS3215 at IDs 1-6, 1 Mbps, set up.
    QString armPort(SimRefusal *why);
    // The port of a simulated SO-101 leader arm (six STS3215 at IDs 1-6, 1 Mbps), its elbow and
    // wrist swept to and fro by the simulator's hand: a leader for the simulated arm to follow.
    QString leaderArmPort(SimRefusal *why);

    // The running simulators, null until their port was asked for: for the Simulator dock.
    SimulatorThread *feetechSimulator() const { return m_feetech.get(); }
    SimulatorThread *armSimulator() const { return m_arm.get(); }
    SimulatorThread *leaderArmSimulator() const { return m_leaderArm.get(); }

private:
    bool ensureFolder(SimRefusal *why);
    // Starts `options` into `slot`; its port, or empty and *why (DemoNotStarted).
    QString start(std::unique_ptr<SimulatorThread> &slot, const SimulatorOptions &options,
                  SimRefusal *why);
    // `name` names its EEPROM's file, `portName` the port.
    QString startFeetech(std::unique_ptr<SimulatorThread> &slot, SimulatorOptions options,
                         const QString &name, const QString &portName, SimRefusal *why);
    QString startArm(std::unique_ptr<SimulatorThread> &slot, const QString &robot,
                     const QString &name, const QString &portName, const QVector<HandSweep> &sweeps,
                     SimRefusal *why);

    std::unique_ptr<QTemporaryDir> m_folder;
    std::unique_ptr<SimulatorThread> m_ptk;
    std::unique_ptr<SimulatorThread> m_feetech;
    std::unique_ptr<SimulatorThread> m_arm;
    std::unique_ptr<SimulatorThread> m_leaderArm;
};

} // namespace sim
