// Apply flow: the plan from a servo's pending edits, locked register writes, and the chain.
#include "applyflow.h"

#include "feetechsessiontr.h"
#include "parametermodel.h"
#include "servoparameters.h"
#include "torqueonhold.h"

#include <QCoreApplication>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

const QString kIdKey = QStringLiteral("id");
const QString kBaudKey = QStringLiteral("baud_rate");

QString lockLeftOpenWarning()
{
    return FeetechSessionTr::tr(
        "The EEPROM lock could not be closed again: the servo's EEPROM may be left "
        "open. Read the servo again and lock it when it answers.");
}

} // namespace

std::optional<ApplyPlan> planApply(const ServoInfo &servo, const model::ParameterModel &parameters,
                                   const QVector<int> &idsInUse, ApplyScope scope,
                                   ApplyRefusal *refusal)
{
    const auto refuse = [refusal](const ApplyRefusal &why) {
        if (refusal)
            *refusal = why;
        return std::nullopt;
    };
    const bool everything = scope == ApplyScope::Everything;
    ApplyPlan plan;
    QVector<model::WriteItem> items;
    for (const model::Definition &definition : parameters.definitions()) {
        const auto pending = parameters.pendingValue(definition.key);
        if (!pending)
            continue;
        if (definition.key == kIdKey) {
            if (everything)
                plan.newId = int(*pending);
        } else if (definition.key == kBaudKey) {
            if (everything)
                plan.newBaud = baudForCode(int(*pending));
        } else {
            items.append({definition.key, *pending});
        }
    }
    if (items.isEmpty() && !plan.newId && !plan.newBaud)
        return refuse(ApplyRefusal(ApplyRefusal::Code::NothingToWrite));
    if (plan.newId && idsInUse.contains(*plan.newId) && *plan.newId != servo.id)
        return refuse(ApplyRefusal::idInUse(*plan.newId));
    QString why;
    const auto writes = encodeWrites(servo.table(), items, &why);
    if (!writes)
        return refuse(ApplyRefusal::badValue(why));
    plan.writes = *writes;
    for (const model::WriteItem &item : std::as_const(items))
        plan.writtenKeys.append(item.key);
    plan.idsInUse = idsInUse;
    return plan;
}

ApplyFlow::ApplyFlow(BusExchange &bus, GuidedFlows &flows, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
    , m_flows(flows)
{ }

QString ApplyFlow::refusal(const ServoInfo &servo, const QVector<RegisterWrite> &writes) const
{
    if (!servo.hasTable())
        return FeetechSessionTr::tr(
                   "Servo %1 is of an unknown model; its memory is shown read-only and nothing "
                   "is written to it.")
            .arg(servo.id);
    const Register *lockRegister = registerAt(servo, u"lock");
    const Register *torque = registerAt(servo, u"torque_enable");
    for (const RegisterWrite &item : writes) {
        for (const Register *guarded : {registerAt(servo, kIdKey), registerAt(servo, kBaudKey)}) {
            if (guarded && guarded->overlaps(item.address, int(item.bytes.size())))
                return FeetechSessionTr::tr(
                    "The ID and the baud rate change how the servo is reached; use "
                    "Change ID or Change baud rate.");
        }
        if (lockRegister && item.address == lockRegister->address)
            return FeetechSessionTr::tr(
                "The EEPROM lock is opened and closed by ServoBench around each EEPROM "
                "write; it is not written by hand.");
        const bool calibrates = torque && item.address == torque->address && !item.bytes.isEmpty()
            && servo.table().torqueValue(TorqueMode::CalibrateMiddle)
                == qint32(quint8(item.bytes.at(0)));
        if (calibrates)
            return FeetechSessionTr::tr(
                "Torque enable 128 recalibrates the middle; use Calibrate middle.");
    }
    return {};
}

void ApplyFlow::write(const ServoInfo &servo, const QVector<RegisterWrite> &writes,
                      GuidedFlows::Finish finish)
{
    const QString refused = refusal(servo, writes);
    if (!refused.isEmpty()) {
        OperationResult result {Operation::Write, false, refused, servo, {}};
        result.failure =
            servo.hasTable() ? OperationFailure::InvalidRequest : OperationFailure::Unsupported;
        finish(result);
        return;
    }
    auto target = std::make_shared<ServoInfo>(servo);
    const bool eeprom =
        std::any_of(writes.begin(), writes.end(), [](const RegisterWrite &w) { return w.eeprom; });
    const bool hold = needsHoldBeforeTorqueOn(servo, writes);
    const int total = int(writes.size()) * 2 + (eeprom ? 2 : 0) + (hold ? 1 : 0);
    auto done = std::make_shared<int>(0);
    const auto counted = [this, done, total](Step step) -> Step {
        return [this, done, total, step = std::move(step)](StepDone next) {
            step([this, done, total, next](bool ok, const QString &message) {
                emit progress(++*done, total);
                next(ok, message);
            });
        };
    };
    std::vector<Step> steps {m_bus.setBaud(servo.baud)};
    if (hold)
        steps.push_back(counted(holdBeforeTorqueOn(m_bus, target)));
    if (eeprom)
        steps.push_back(counted(m_bus.lock(target, false)));
    // From here on a failure leaves the outcome open: a write may have landed unacknowledged.
    auto sent = std::make_shared<bool>(false);
    steps.push_back(BusExchange::markDone(sent));
    for (const RegisterWrite &item : writes)
        steps.push_back(
            counted(m_bus.write(servo.id, item.address, item.bytes, servo.repliesToWrites(),
                                FeetechSessionTr::tr("Writing address %1").arg(item.address))));
    if (eeprom)
        steps.push_back(counted(m_bus.lock(target, true)));
    for (const RegisterWrite &item : writes)
        steps.push_back(counted(
            m_bus.read(target, item.address, int(item.bytes.size()), ReadSource::ReadBack)));
    emit progress(0, total);
    m_bus.runSteps(
        std::move(steps),
        [this, finish, servo, target, eeprom, writes, sent](bool ok, const QString &message) {
            if (ok) {
                finish({Operation::Write,
                        true,
                        FeetechSessionTr::tr("Written and read back."),
                        servo,
                        {}});
                return;
            }
            const OperationFailure failure = m_bus.stepFailure();
            // Never leave the EEPROM open: lock it again, whatever failed (an unlock may have
            // landed unconfirmed even when nothing else went out).
            std::vector<Step> settle;
            auto locked = std::make_shared<bool>(!eeprom);
            if (eeprom)
                settle.push_back(relockNoting(target, locked));
            // Then read back what was written, each register on its own, so that every write
            // whose answer was lost is settled by what the servo holds; what no read-back
            // settles stays unknown.
            if (*sent) {
                for (const RegisterWrite &item : writes)
                    settle.push_back(BusExchange::tolerant(m_bus.read(
                        target, item.address, int(item.bytes.size()), ReadSource::ReadBack)));
            }
            m_bus.runSteps(std::move(settle),
                           [finish, servo, message, failure, locked, sent](bool, const QString &) {
                               OperationResult result {Operation::Write, false, message, servo, {}};
                               result.failure = failure;
                               if (!*locked)
                                   result.message += u' ' + lockLeftOpenWarning();
                               result.writesSent = *sent;
                               finish(result);
                           });
        });
}

Step ApplyFlow::relockNoting(std::shared_ptr<ServoInfo> target, std::shared_ptr<bool> locked)
{
    return [this, target, locked](StepDone next) {
        relock(target, kRelockAttempts)([locked, next](bool ok, const QString &) {
            *locked = ok;
            next(true, {}); // the read-backs go on either way
        });
    };
}

Step ApplyFlow::relock(std::shared_ptr<ServoInfo> target, int attempts)
{
    return [this, target, attempts](StepDone next) {
        m_bus.lock(target, true)([this, target, attempts, next](bool ok, const QString &message) {
            if (ok || attempts <= 1) {
                next(ok, message);
                return;
            }
            relock(target, attempts - 1)(next);
        });
    };
}

void ApplyFlow::apply(const ServoInfo &servo, const ApplyPlan &plan, GuidedFlows::Finish stepDone,
                      GuidedFlows::Finish finish, Yield yield)
{
    auto chain = std::make_shared<Chain>();
    chain->stepDone = std::move(stepDone);
    chain->finish = std::move(finish);
    chain->yield = std::move(yield);
    if (!plan.writes.isEmpty())
        chain->steps.push_back(
            {Operation::Write,
             [this, writes = plan.writes](const ServoInfo &at, GuidedFlows::Finish f) {
                 write(at, writes, std::move(f));
             }});
    if (plan.newId)
        chain->steps.push_back({Operation::ChangeId,
                                [this, id = *plan.newId, inUse = plan.idsInUse](
                                    const ServoInfo &at, GuidedFlows::Finish f) {
                                    m_flows.changeId(at, id, inUse, std::move(f));
                                }});
    if (plan.newBaud)
        chain->steps.push_back(
            {Operation::ChangeBaud,
             [this, baud = *plan.newBaud](const ServoInfo &at, GuidedFlows::Finish f) {
                 m_flows.changeBaud(at, baud, std::move(f));
             }});
    if (chain->steps.empty()) {
        OperationResult result {
            Operation::Write, false, FeetechSessionTr::tr("Nothing to write."), servo, {}};
        result.failure = OperationFailure::NothingToDo;
        chain->finish(result);
        return;
    }
    runChain(servo, chain, 0);
}

void ApplyFlow::runChain(const ServoInfo &servo, std::shared_ptr<Chain> chain, std::size_t index)
{
    chain->steps.at(index).run(servo, [this, chain, index](const OperationResult &result) {
        // A later step must not act on a servo that is not where we think it is.
        if (!result.ok || index + 1 == chain->steps.size()) {
            OperationResult last = result;
            last.final = true;
            chain->finish(last);
            return;
        }
        OperationResult step = result;
        step.final = false;
        chain->stepDone(step);
        const ServoInfo movedTo = result.servo;
        chain->yield(chain->steps.at(index + 1).operation,
                     [this, chain, index, movedTo] { runChain(movedTo, chain, index + 1); });
    });
}

} // namespace feetech
