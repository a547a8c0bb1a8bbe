// Simulated servos inside the application, so ServoBench can be tried before hardware arrives.
#pragma once

#include "simulatorthread.h"

#include <QTemporaryDir>

#include <memory>

namespace sim {

// Starts each simulator on first use, on a pseudo-terminal in a private temporary folder, and
// stops them all when destroyed.
class DemoServos
{
public:
    DemoServos() = default;
    ~DemoServos();
    DemoServos(const DemoServos &) = delete;
    DemoServos &operator=(const DemoServos &) = delete;

    // The port of the simulated PTK servo (empty and *error when it cannot start).
    QString ptkPort(QString *error);
    // The port of the simulated Feetech bus: three STS3215, an SCS15 and an HLS at 1 Mbps.
    QString feetechPort(QString *error);
    // The port of a simulated SO-101 follower arm: six STS3215 at IDs 1-6, 1 Mbps, set up.
    QString armPort(QString *error);
    // The port of a simulated SO-101 leader arm (six STS3215 at IDs 1-6, 1 Mbps), its elbow and
    // wrist swept to and fro by the simulator's hand: a leader for the simulated arm to follow.
    QString leaderArmPort(QString *error);

    // The running simulators, null until their port was asked for: for the Simulator dock.
    SimulatorThread *feetechSimulator() const { return m_feetech.get(); }
    SimulatorThread *armSimulator() const { return m_arm.get(); }
    SimulatorThread *leaderArmSimulator() const { return m_leaderArm.get(); }

private:
    bool ensureFolder(QString *error);
    QString startFeetech(std::unique_ptr<SimulatorThread> &slot, SimulatorOptions options,
                         const QString &name, QString *error);
    QString startArm(std::unique_ptr<SimulatorThread> &slot, const QString &robot,
                     const QString &name, const QVector<HandSweep> &sweeps, QString *error);

    std::unique_ptr<QTemporaryDir> m_folder;
    std::unique_ptr<SimulatorThread> m_ptk;
    std::unique_ptr<SimulatorThread> m_feetech;
    std::unique_ptr<SimulatorThread> m_arm;
    std::unique_ptr<SimulatorThread> m_leaderArm;
};

} // namespace sim
