// Test helper: a hand that turns simulated servos' horns (torque off) through scripted
// positions, a little every tick of the test thread's event loop.
#pragma once

#include "feetechbus.h"
#include "simulatorthread.h"
#include "virtualfeetechservo.h"

#include <QMap>
#include <QObject>
#include <QTimer>
#include <QVector>

#include <algorithm>
#include <functional>

namespace testsupport {

class ScriptedHand : public QObject
{
public:
    // Steps a horn moves at most per tick: far below the half turn that would look like a
    // crossing of the encoder's seam, even when several ticks come between two samples.
    static constexpr int kStepPerTick = 60;
    // Ticks a horn rests at each waypoint, so that telemetry sees every extreme.
    static constexpr int kRestTicks = 8;
    static constexpr int kTickMs = 10;

    explicit ScriptedHand(sim::SimulatorThread &simulator)
        : m_simulator(simulator)
    {
        m_timer.setInterval(kTickMs);
        connect(&m_timer, &QTimer::timeout, this, &ScriptedHand::tick);
    }

    // Puts servo `id`'s horn at `position` (a physical position, in any turn) at once.
    void place(quint8 id, int position)
    {
        m_joints[id].position = position;
        m_simulator.call([&](sim::Simulator &simulator) {
            if (sim::VirtualFeetechServo *servo = simulator.feetechBus()->findServo(id))
                servo->setPhysicalPosition(wrap(position));
        });
    }
    // Moves servo `id`'s horn from where it was placed through `waypoints` (unwrapped: 4196 is
    // 100 steps past the seam), then runs `then` on the servo in the simulator's thread.
    void script(quint8 id, const QVector<int> &waypoints,
                std::function<void(sim::VirtualFeetechServo &)> then = {})
    {
        Joint &joint = m_joints[id];
        joint.waypoints = waypoints;
        joint.then = std::move(then);
    }
    // Starts moving once `ready` says so (checked every tick): at once without it.
    void start(std::function<bool()> ready = {})
    {
        m_ready = std::move(ready);
        m_timer.start();
    }
    bool done() const
    {
        return std::all_of(m_joints.begin(), m_joints.end(),
                           [](const Joint &joint) { return joint.waypoints.isEmpty(); });
    }

private:
    struct Joint
    {
        int position = 0;
        int rest = 0;
        QVector<int> waypoints;
        std::function<void(sim::VirtualFeetechServo &)> then;
    };

    static double wrap(int position) { return double(((position % 4096) + 4096) % 4096); }

    void tick()
    {
        if (m_ready && !m_ready())
            return;
        m_ready = {};
        m_simulator.call([this](sim::Simulator &simulator) {
            for (auto it = m_joints.begin(); it != m_joints.end(); ++it) {
                Joint &joint = it.value();
                if (joint.waypoints.isEmpty())
                    continue;
                sim::VirtualFeetechServo *servo = simulator.feetechBus()->findServo(it.key());
                const int target = joint.waypoints.first();
                if (joint.position != target) {
                    joint.position +=
                        std::clamp(target - joint.position, -kStepPerTick, kStepPerTick);
                    if (servo)
                        servo->setPhysicalPosition(wrap(joint.position));
                    continue;
                }
                if (joint.rest < kRestTicks) {
                    ++joint.rest;
                    continue;
                }
                joint.rest = 0;
                joint.waypoints.removeFirst();
                if (joint.waypoints.isEmpty() && joint.then && servo)
                    joint.then(*servo);
            }
        });
        if (done())
            m_timer.stop();
    }

    sim::SimulatorThread &m_simulator;
    QTimer m_timer;
    QMap<quint8, Joint> m_joints;
    std::function<bool()> m_ready;
};

// WRITE instructions the simulated bus logged to `logPath` for servo `id` starting at `address`.
inline int writesReceived(const QString &logPath, quint8 id, int address)
{
    int count = 0;
    for (const feetech::Packet &packet :
         feetechRequestsReceived(logPath, feetech::Instruction::Write, id)) {
        if (!packet.parameters.isEmpty() && quint8(packet.parameters.at(0)) == address)
            ++count;
    }
    return count;
}

} // namespace testsupport
