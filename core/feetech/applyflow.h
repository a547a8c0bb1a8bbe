// Writing a servo's edits: locked register writes, and the apply chain (registers, ID, baud).
#pragma once

#include "feetech/busexchange.h"
#include "feetech/bustypes.h"
#include "feetech/guidedflows.h"

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

// The plan for the edits pending in `parameters` of `servo`; nothing and *error when a value
// cannot be written or there is nothing to write. The model is left as it is.
std::optional<ApplyPlan> planApply(const ServoInfo &servo, const model::ParameterModel &parameters,
                                   const QVector<int> &idsInUse, QString *error);

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
    // Runs the plan's steps in order, each only once the one before succeeded, following the
    // servo to wherever the step before left it. Every step's result goes to `stepDone`; the
    // last one (or the first failure) to `finish` instead, with `final` set.
    void apply(const ServoInfo &servo, const ApplyPlan &plan, GuidedFlows::Finish stepDone,
               GuidedFlows::Finish finish);

signals:
    void progress(int done, int total);

private:
    using PlanStep = std::function<void(const ServoInfo &servo, GuidedFlows::Finish finish)>;
    void runChain(const ServoInfo &servo, std::shared_ptr<std::vector<PlanStep>> steps,
                  std::size_t index, GuidedFlows::Finish stepDone, GuidedFlows::Finish finish);
    // Why `writes` may not go out to `servo` (empty when they may).
    QString refusal(const ServoInfo &servo, const QVector<RegisterWrite> &writes) const;

    BusExchange &m_bus;
    GuidedFlows &m_flows;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::ApplyPlan)
