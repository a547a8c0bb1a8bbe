// A simulator on a thread of its own, for the tests and the GUI's demo servos.
#pragma once

#include "simulator.h"

#include <QThread>

#include <functional>
#include <memory>

namespace sim {

// Runs a simulator on its own thread (tests and the GUI's demo mode).
class SimulatorThread
{
public:
    SimulatorThread() = default;
    ~SimulatorThread();
    SimulatorThread(const SimulatorThread &) = delete;
    SimulatorThread &operator=(const SimulatorThread &) = delete;

    bool start(const SimulatorOptions &options, QString *error);
    void stop();
    bool isRunning() const { return m_simulator != nullptr; }
    QString linkPath() const { return m_linkPath; }

    // Runs `work` in the simulator's thread and waits for it: the only safe way to look at or
    // change the simulated devices while they run.
    void call(const std::function<void(Simulator &)> &work);

private:
    QThread m_thread;
    std::unique_ptr<Simulator> m_simulator;
    QString m_linkPath;
};

} // namespace sim
