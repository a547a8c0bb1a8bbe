// What an operation has while the session runs it: the bus and the flows on it, and the
// session's ways to report on it, let others use the bus between its steps and end its turn.
#pragma once

#include "bustypes.h"
#include "guidedflows.h"

#include <chrono>
#include <functional>

namespace feetech {

class ApplyFlow;
class BusExchange;
class BusScan;
class GuardKeeper;
class HealthCheck;
class HealthMoveTest;
class JointIdentify;
class MotionReplay;
class MotorSetup;
class Session;

// Made by the session, which hands it to each operation as it submits and starts it; an
// operation keeps it (by pointer) for the callbacks of its steps.
class OperationContext
{
public:
    explicit OperationContext(Session &session);

    BusExchange &bus() const;
    BusScan &scan() const;
    GuidedFlows &flows() const;
    ApplyFlow &apply() const;
    MotorSetup &motorSetup() const;
    JointIdentify &identify() const;
    MotionReplay &replay() const;
    HealthCheck &health() const;
    HealthMoveTest &moveTest() const;
    GuardKeeper &guard() const;
    bool isLinkOpen() const;

    // Ends the running operation's turn with its result (the ticket is filled in).
    void finish(const OperationResult &result) const;
    GuidedFlows::Finish finisher() const;
    // A step of a chain that goes on (OperationResult::final unset).
    void reportStep(const OperationResult &step) const;
    void reportProgress(const OperationProgress &progress) const;
    // Ends the running operation's turn on the bus; `resume` runs as the next operation, of
    // kind `next`, behind any All torque off asked for meanwhile.
    void continueLater(Operation next, std::function<void()> resume) const;
    // Ends its turn for `delay`: meanwhile only telemetry and All torque off use the bus, then
    // `resume` runs as the next operation, told whether All torque off was asked for since the
    // operation was submitted.
    void pauseFor(std::chrono::milliseconds delay,
                  std::function<void(bool torqueOffMeanwhile)> resume) const;
    // What a reply said of a servo outside the bus's own reads: its status byte (a PING), or
    // register bytes (a read-back done by hand).
    void noteStatus(quint8 id, qint32 baud, quint8 statusByte) const;
    void noteMemory(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                    quint8 statusByte) const;

private:
    Session &m_session;
};

} // namespace feetech
