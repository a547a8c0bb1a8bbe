// Writing a servo's edits: locked register writes, and the apply chain (registers, ID, baud).
#pragma once

#include "applyrefusal.h"
#include "busexchange.h"
#include "bustypes.h"
#include "guidedflows.h"

#include <QMetaType>
#include <QObject>
#include <QStringList>

#include <optional>

namespace model {
class ParameterModel;
}

namespace feetech {

// Everything pending on one servo, in the order it must be written: the registers first (while
// the servo is still where we know it), then the ID, then the baud rate.
struct ApplyPlan
{
    QVector<RegisterWrite> writes; // every pending register but the ID and the baud rate
    QStringList writtenKeys; // the keys of `writes`, for the model
    std::optional<int> newId;
    QVector<int> idsInUse; // refused as a new ID
    std::optional<qint32> newBaud;
    bool isEmpty() const { return writes.isEmpty() && !newId && !newBaud; }
};

// What an Apply covers: the registers only (an ID or baud edit waits for its own flow), or
// everything pending.
enum class ApplyScope { Registers, Everything };

// The plan for the edits pending in `parameters` of `servo`; nothing, and why in *refusal, when
// there is nothing to write, the new ID is in use or a value cannot be written (checked in that
// order). The model is left as it is.
std::optional<ApplyPlan> planApply(const ServoInfo &servo, const model::ParameterModel &parameters,
                                   const QVector<int> &idsInUse, ApplyScope scope,
                                   ApplyRefusal *refusal);

// Lives in the session's thread; the session runs one write or apply at a time, as an operation.
class ApplyFlow : public QObject
{
    Q_OBJECT

public:
    ApplyFlow(BusExchange &bus, GuidedFlows &flows, QObject *parent = nullptr);

    // EEPROM registers go unlock → write → lock, RAM ones straight; then every written
    // register is read back. The ID, the baud rate, the lock itself and torque enable's
    // calibrate value are refused: they have their flows.
    void write(const ServoInfo &servo, const QVector<RegisterWrite> &writes,
               GuidedFlows::Finish finish);
    // Hands the next step of a chain back to whoever runs the bus: it calls `resume` when the
    // bus is free again (an emergency stop asked for meanwhile goes first).
    using Yield = std::function<void(Operation next, std::function<void()> resume)>;
    // Runs the plan's steps in order, each only once the one before succeeded, following the
    // servo to wherever the step before left it. Every step's result but the last goes to
    // `stepDone` (with `final` unset) and the chain yields the bus; the last result, or the
    // first failure, goes to `finish`.
    void apply(const ServoInfo &servo, const ApplyPlan &plan, GuidedFlows::Finish stepDone,
               GuidedFlows::Finish finish, Yield yield);

signals:
    void progress(int done, int total);

private:
    struct PlanStep
    {
        Operation operation = Operation::Write;
        std::function<void(const ServoInfo &servo, GuidedFlows::Finish finish)> run;
    };
    struct Chain
    {
        std::vector<PlanStep> steps;
        GuidedFlows::Finish stepDone;
        GuidedFlows::Finish finish;
        Yield yield;
    };
    void runChain(const ServoInfo &servo, std::shared_ptr<Chain> chain, std::size_t index);
    // Closing the EEPROM lock after a failure, asked again while the servo does not confirm.
    static constexpr int kRelockAttempts = 4;
    Step relock(std::shared_ptr<ServoInfo> target, int attempts);
    // relock, its outcome in `locked`; the run goes on either way.
    Step relockNoting(std::shared_ptr<ServoInfo> target, std::shared_ptr<bool> locked);
    // Why `writes` may not go out to `servo` (empty when they may).
    QString refusal(const ServoInfo &servo, const QVector<RegisterWrite> &writes) const;

    BusExchange &m_bus;
    GuidedFlows &m_flows;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::ApplyPlan)
