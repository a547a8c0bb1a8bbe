// Feetech guided flows: each one planned as a list of steps and run on the bus exchange.
#include "guidedflows.h"

#include "feetechsessiontr.h"
#include "linksession.h"

#include <QCoreApplication>
#include <QTimer>

#include <memory>

namespace feetech {

GuidedFlows::GuidedFlows(BusExchange &bus, QObject *parent)
    : QObject(parent)
    , m_bus(bus)
{ }

void GuidedFlows::changeId(const ServoInfo &servo, int newId, const QVector<int> &idsInUse,
                           Finish finish)
{
    OperationResult result {Operation::ChangeId, false, {}, servo, {}};
    const Register *idRegister = registerAt(servo, u"id");
    if (!idRegister) {
        result.failure = OperationFailure::Unsupported;
        result.message =
            FeetechSessionTr::tr("Servo %1 is of an unknown model; its ID is not changed.")
                .arg(servo.id);
    } else if (newId < 0 || newId > kMaxServoId) {
        result.failure = OperationFailure::InvalidRequest;
        result.message =
            FeetechSessionTr::tr("ID %1 is out of range (0 to %2).").arg(newId).arg(kMaxServoId);
    } else if (newId == servo.id) {
        result.failure = OperationFailure::NothingToDo;
        result.message = FeetechSessionTr::tr("The servo already has ID %1.").arg(newId);
    } else if (idsInUse.contains(newId)) {
        result.failure = OperationFailure::IdInUse;
        result.message =
            FeetechSessionTr::tr("ID %1 is already in use on this bus; nothing was written.")
                .arg(newId);
    }
    if (!result.message.isEmpty()) {
        finish(result);
        return;
    }
    auto target = std::make_shared<ServoInfo>(servo);
    auto moved = std::make_shared<ServoInfo>(servo);
    moved->id = quint8(newId);
    const quint8 oldId = servo.id;
    auto unlocked = std::make_shared<bool>(false);
    // From the moment the unlock is sent the EEPROM may be open, even if its reply is lost.
    std::vector<Step> steps {m_bus.setBaud(servo.baud), m_bus.ping(quint8(newId), false, 1),
                             BusExchange::markDone(unlocked), m_bus.lock(target, false)};
    // The reply may come from the old ID or the new one (spec §13), or not at all.
    steps.push_back(m_bus.addressWrite(oldId, idRegister->address, quint8(newId), quint8(newId)));
    steps.push_back(m_bus.lock(moved, true));
    steps.push_back(m_bus.identify(moved));
    m_bus.runSteps(
        std::move(steps),
        [this, finish, result, moved, target, newId, unlocked](bool ok,
                                                               const QString &message) mutable {
            if (ok) {
                result.ok = true;
                result.servo = *moved;
                result.message = FeetechSessionTr::tr("Servo %1 now answers as ID %2.")
                                     .arg(target->id)
                                     .arg(newId);
                finish(result);
                return;
            }
            result.message = message;
            result.failure = m_bus.stepFailure();
            if (!*unlocked) { // refused before anything was written
                finish(result);
                return;
            }
            // Wherever it is now, its EEPROM is locked again: at the new ID (ignored
            // when nothing answers there), then at the old one.
            m_bus.relock({moved}, [this, finish, result, target]() mutable {
                m_bus.runSteps(
                    {m_bus.ping(target->id, true, 1), m_bus.lock(target, true)},
                    [this, finish, result](bool stillThere, const QString &) mutable {
                        if (stillThere)
                            result.message +=
                                u' ' + FeetechSessionTr::tr("The servo still has its old ID.");
                        finish(result);
                    });
            });
        });
}

void GuidedFlows::changeBaud(const ServoInfo &servo, qint32 newBaud, Finish finish)
{
    OperationResult result {Operation::ChangeBaud, false, {}, servo, {}};
    const Register *baudRegister = registerAt(servo, u"baud_rate");
    const std::optional<int> code = feetech::baudCode(newBaud);
    if (!baudRegister) {
        result.failure = OperationFailure::Unsupported;
        result.message =
            FeetechSessionTr::tr("Servo %1 is of an unknown model; its baud rate is not "
                                 "changed.")
                .arg(servo.id);
    } else if (!code || *code > baudRegister->maximum) {
        result.failure = OperationFailure::InvalidRequest;
        result.message = FeetechSessionTr::tr("%1 is not a baud rate this servo supports.")
                             .arg(baudText(newBaud));
    } else if (newBaud == servo.baud) {
        result.failure = OperationFailure::NothingToDo;
        result.message =
            FeetechSessionTr::tr("The servo already runs at %1.").arg(baudText(newBaud));
    }
    if (!result.message.isEmpty()) {
        finish(result);
        return;
    }
    auto target = std::make_shared<ServoInfo>(servo);
    auto moved = std::make_shared<ServoInfo>(servo);
    moved->baud = newBaud;
    auto unlocked = std::make_shared<bool>(false);
    // No servo may already answer with this ID at the new rate: both would then answer
    // every request there.
    std::vector<Step> steps {m_bus.setBaud(newBaud), m_bus.ping(servo.id, false, 1),
                             m_bus.setBaud(servo.baud), BusExchange::markDone(unlocked),
                             m_bus.lock(target, false)};
    // The answer may already come at the new rate and be lost.
    steps.push_back(m_bus.addressWrite(servo.id, baudRegister->address, quint8(*code), {}));
    steps.push_back(m_bus.setBaud(newBaud));
    steps.push_back(m_bus.lock(moved, true));
    steps.push_back(m_bus.identify(moved));
    steps.push_back([this, moved, code](StepDone next) {
        if (moved->baudCode != *code)
            m_bus.fail(next, OperationFailure::NotVerified,
                       FeetechSessionTr::tr("The servo reports baud code %1 instead of %2.")
                           .arg(moved->baudCode)
                           .arg(*code));
        else
            next(true, {});
    });
    m_bus.runSteps(
        std::move(steps),
        [this, finish, result, moved, target, newBaud, unlocked](bool ok,
                                                                 const QString &message) mutable {
            if (ok) {
                result.ok = true;
                result.servo = *moved;
                result.message = FeetechSessionTr::tr("Servo %1 now runs at %2 and answers there.")
                                     .arg(moved->id)
                                     .arg(baudText(newBaud));
                finish(result);
                return;
            }
            result.message = message;
            result.failure = m_bus.stepFailure();
            if (!*unlocked) {
                finish(result);
                return;
            }
            // Lock it at the new rate in case it got there, then follow it back: maybe it
            // never took the new rate.
            m_bus.relock({moved}, [this, finish, result, target]() mutable {
                m_bus.runSteps(
                    {m_bus.setBaud(target->baud), m_bus.ping(target->id, true, 1),
                     m_bus.lock(target, true)},
                    [this, finish, result, target](bool stillThere, const QString &) mutable {
                        result.message += u' '
                            + (stillThere
                                   ? FeetechSessionTr::tr("It still answers at %1.")
                                         .arg(baudText(target->baud))
                                   : FeetechSessionTr::tr("It answers at neither rate; scan all "
                                                          "baud rates to find it."));
                        finish(result);
                    });
            });
        });
}

void GuidedFlows::calibrateMiddle(const ServoInfo &servo, Finish finish)
{
    const MiddleCalibration method = middleCalibration(servo);
    const Register *offset = registerAt(servo, u"position_offset");
    const Register *torque = registerAt(servo, u"torque_enable");
    const auto calibrateValue =
        servo.hasTable() ? servo.table().torqueValue(TorqueMode::CalibrateMiddle) : std::nullopt;
    if (method == MiddleCalibration::Unsupported || !offset || !torque
        || (method == MiddleCalibration::TorqueEnable128 && !calibrateValue)) {
        OperationResult result {
            Operation::CalibrateMiddle,
            false,
            FeetechSessionTr::tr("Middle calibration is not available on this servo "
                                 "(SCS servos have no offset register)."),
            servo,
            {}};
        result.failure = OperationFailure::Unsupported;
        finish(result);
        return;
    }
    auto target = std::make_shared<ServoInfo>(servo);
    std::vector<Step> steps {m_bus.setBaud(servo.baud), m_bus.lock(target, false)};
    if (method == MiddleCalibration::Instruction)
        steps.push_back(m_bus.instruction(servo.id, feetech::calibrate(servo.id),
                                          servo.repliesToWrites(),
                                          FeetechSessionTr::tr("Middle calibration")));
    else
        steps.push_back(m_bus.write(servo.id, torque->address, QByteArray(1, char(*calibrateValue)),
                                    servo.repliesToWrites(),
                                    FeetechSessionTr::tr("Middle calibration")));
    steps.push_back(m_bus.lock(target, true));
    steps.push_back(m_bus.read(target, offset->address, offset->size, ReadSource::ReadBack));
    m_bus.runSteps(
        std::move(steps), [this, finish, servo, target](bool ok, const QString &message) {
            OperationResult result {
                Operation::CalibrateMiddle,
                ok,
                ok ? FeetechSessionTr::tr("The present position is now the middle.") : message,
                servo,
                {}};
            if (!ok)
                result.failure = m_bus.stepFailure();
            if (ok)
                finish(result);
            else
                m_bus.relock({target}, [this, finish, result] { finish(result); });
        });
}

void GuidedFlows::factoryReset(const ServoInfo &servo, Finish finish)
{
    if (!servo.hasTable()) {
        OperationResult result {
            Operation::FactoryReset,
            false,
            FeetechSessionTr::tr("Servo %1 is of an unknown model; it is not reset.").arg(servo.id),
            servo,
            {}};
        result.failure = OperationFailure::Unsupported;
        finish(result);
        return;
    }
    auto target = std::make_shared<ServoInfo>(servo);
    std::vector<Step> steps {m_bus.setBaud(servo.baud), m_bus.lock(target, false),
                             m_bus.instruction(servo.id, feetech::recovery(servo.id),
                                               servo.repliesToWrites(),
                                               FeetechSessionTr::tr("Factory reset"))};
    // Factory values include the baud rate: look for the servo at every rate, its old one
    // first.
    steps.push_back([this, finish, target](StepDone next) {
        QVector<qint32> rates {target->baud};
        for (const qint32 rate : baudRates()) {
            if (rate != target->baud)
                rates.append(rate);
        }
        m_bus.searchBauds(target, rates, next);
    });
    steps.push_back(m_bus.identify(target));
    steps.push_back(m_bus.lock(target, true));
    m_bus.runSteps(std::move(steps), [this, finish, target](bool ok, const QString &message) {
        OperationResult result {
            Operation::FactoryReset,
            ok,
            ok ? FeetechSessionTr::tr("Factory values restored; servo %1 answers at %2.")
                     .arg(target->id)
                     .arg(baudText(target->baud))
               : message,
            *target,
            {}};
        if (!ok)
            result.failure = m_bus.stepFailure();
        if (ok)
            finish(result);
        else
            m_bus.relock({target}, [this, finish, result] { finish(result); });
    });
}

void GuidedFlows::reboot(const ServoInfo &servo, Finish finish)
{
    auto target = std::make_shared<ServoInfo>(servo);
    std::vector<Step> steps {m_bus.setBaud(servo.baud)};
    if (const Register *torque = registerAt(servo, u"torque_enable"))
        steps.push_back(
            m_bus.write(servo.id, torque->address,
                        QByteArray(1, char(servo.table().torqueValue(TorqueMode::Off).value_or(0))),
                        servo.repliesToWrites(), FeetechSessionTr::tr("Torque off")));
    steps.push_back(m_bus.instruction(servo.id, feetech::reboot(servo.id), false,
                                      FeetechSessionTr::tr("Reboot")));
    auto clock = std::make_shared<QElapsedTimer>();
    steps.push_back([clock](StepDone next) {
        clock->start();
        next(true, {});
    });
    m_bus.runSteps(std::move(steps), [this, finish, servo, clock](bool ok, const QString &message) {
        if (!ok) {
            OperationResult result {Operation::Reboot, false, message, servo, {}};
            result.failure = m_bus.stepFailure();
            finish(result);
            return;
        }
        waitForReboot(servo, clock, finish);
    });
}

void GuidedFlows::waitForReboot(const ServoInfo &servo, std::shared_ptr<QElapsedTimer> clock,
                                Finish finish)
{
    const quint64 generation = m_bus.link().generation();
    QTimer::singleShot(
        m_bus.timing().rebootPollInterval, this, [this, finish, servo, clock, generation] {
            if (generation != m_bus.link().generation())
                return;
            m_bus.runSteps({m_bus.ping(servo.id, true, 0)},
                           [this, finish, servo, clock](bool back, const QString &) {
                               if (back) {
                                   finish({Operation::Reboot,
                                           true,
                                           FeetechSessionTr::tr(
                                               "Servo %1 restarted and answers again after %2 ms.")
                                               .arg(servo.id)
                                               .arg(clock->elapsed()),
                                           servo,
                                           {}});
                               } else if (clock->elapsed() >= m_bus.timing().rebootGiveUp.count()) {
                                   OperationResult result {
                                       Operation::Reboot,
                                       false,
                                       FeetechSessionTr::tr(
                                           "Servo %1 has not answered within %2 ms of the restart.")
                                           .arg(servo.id)
                                           .arg(clock->elapsed()),
                                       servo,
                                       {}};
                                   result.failure = OperationFailure::NoAnswer;
                                   finish(result);
                               } else {
                                   waitForReboot(servo, clock, finish);
                               }
                           });
        });
}

} // namespace feetech
