// The latched-overload recovery: torque off and on, the status read back, the power cycle.
#include "overloadrecovery.h"

#include "feetechguardtr.h"
#include "overloadguard.h"
#include "registertable.h"
#include "torqueonhold.h"

#include <QCoreApplication>

namespace feetech {

Step recoverOverload(BusExchange &bus, std::shared_ptr<ServoInfo> servo, bool checkOnly,
                     std::shared_ptr<std::optional<bool>> latched)
{
    return [&bus, servo, checkOnly, latched](StepDone next) {
        const RegisterTable &table = servo->table();
        const Register *torque = table.find(u"torque_enable");
        const Register *status = table.find(u"status");
        const auto off = table.torqueValue(TorqueMode::Off);
        const auto on = table.torqueValue(TorqueMode::On);
        if (!torque || !status || !off || !on || !table.find(u"goal_position")) {
            bus.fail(
                next, OperationFailure::Unsupported,
                FeetechGuardTr::tr("%1 has no torque, goal or status register to recover with.")
                    .arg(servoName(*servo)));
            return;
        }
        const auto torqueWrite = [&bus, servo, torque](qint32 value, const QString &what) {
            return bus.write(servo->id, torque->address, QByteArray(1, char(value)),
                             servo->repliesToWrites(), what);
        };
        std::vector<Step> steps;
        if (!checkOnly) {
            steps.push_back(torqueWrite(*off, FeetechGuardTr::tr("Recovery: torque off")));
            steps.push_back(holdAtPresentPosition(bus, servo));
            steps.push_back(torqueWrite(*on, FeetechGuardTr::tr("Recovery: torque on again")));
        }
        const quint8 bit = overloadStatusBit(table);
        steps.push_back(bus.read(servo, status->address, status->size, ReadSource::ReadBack,
                                 [latched, bit](const QByteArray &bytes) {
                                     if (!bytes.isEmpty())
                                         *latched = (quint8(bytes.at(0)) & bit) != 0;
                                 }));
        const Register *torqueRegister = torque;
        const qint32 offValue = *off;
        bus.runSteps(std::move(steps),
                     [&bus, servo, latched, torqueRegister, offValue,
                      next](bool ok, const QString &message) {
                         if (!ok) {
                             next(false, message); // the failed step has said its kind
                             return;
                         }
                         if (!latched->has_value()) {
                             bus.fail(next, OperationFailure::BadReply,
                                      FeetechGuardTr::tr("The status of %1 could not be read.")
                                          .arg(servoName(*servo)));
                             return;
                         }
                         if (!**latched) {
                             next(true, {});
                             return;
                         }
                         // Still tripped: the servo keeps its torque off; the register says so too.
                         bus.runSteps(
                             {bus.write(servo->id, torqueRegister->address,
                                        QByteArray(1, char(offValue)), servo->repliesToWrites(),
                                        FeetechGuardTr::tr("Recovery: torque off (still tripped)")),
                              bus.read(servo, torqueRegister->address, torqueRegister->size,
                                       ReadSource::ReadBack)},
                             next);
                     });
    };
}

QStringList powerCycleSteps(const ServoInfo &servo)
{
    return {FeetechGuardTr::tr(
                "The overload bit of servo ID %1 stays set after torque off and on: only a "
                "power cycle clears it.")
                .arg(servo.id),
            FeetechGuardTr::tr("1. Free the horn: remove whatever blocks it or the load it holds."),
            FeetechGuardTr::tr(
                "2. Switch the servos' power supply off (the USB adapter may stay connected)."),
            FeetechGuardTr::tr("3. Wait five seconds, then switch the power on again."),
            FeetechGuardTr::tr(
                "4. Check again: only the status is read; torque stays off until you switch it "
                "on.")};
}

} // namespace feetech
