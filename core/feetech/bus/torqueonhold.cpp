// Torque on never jumps (the goal set to the present position before torque is switched on),
// and the checks before and after a test that moves a servo and puts it back.
#include "torqueonhold.h"

#include "feetechsessiontr.h"
#include "registerkeys.h"
#include "registertable.h"
#include "servoparameters.h"

#include <QCoreApplication>

namespace feetech {

using namespace registerkeys;

namespace {

// The value `reg` holds in `bytes` read from its own address.
std::optional<qint32> valueOf(const RegisterTable &table, const Register &reg,
                              const QByteArray &bytes)
{
    for (const DecodedRegister &item : decodeRegisters(table, reg.address, bytes)) {
        if (item.reg->key == reg.key)
            return item.value;
    }
    return std::nullopt;
}

// Reads the present position, writes it as the goal and reads the goal back.
Step writeGoalAtPresent(BusExchange &bus, std::shared_ptr<ServoInfo> servo,
                        std::shared_ptr<std::optional<qint32>> heldAt);

} // namespace

bool needsHoldBeforeTorqueOn(const ServoInfo &servo, const QVector<RegisterWrite> &writes)
{
    if (!servo.hasTable())
        return false;
    const RegisterTable &table = servo.table();
    const Register *torque = table.find(kTorqueEnable);
    const Register *goal = table.find(kGoalPosition);
    const auto on = table.torqueValue(TorqueMode::On);
    if (!torque || !goal || !table.find(kPresentPosition) || !on)
        return false;
    bool switchesOn = false;
    for (const RegisterWrite &write : writes) {
        if (goal->overlaps(write.address, int(write.bytes.size())))
            return false; // the goal is set on purpose: that motion was asked for
        const int offset = torque->address - write.address;
        if (offset >= 0 && offset < write.bytes.size())
            switchesOn = switchesOn || qint32(quint8(write.bytes.at(offset))) == *on;
    }
    return switchesOn;
}

Step holdBeforeTorqueOn(BusExchange &bus, std::shared_ptr<ServoInfo> servo)
{
    return [&bus, servo](StepDone next) {
        const RegisterTable &table = servo->table();
        const Register &torque = *table.find(kTorqueEnable);
        auto torqueNow = std::make_shared<std::optional<qint32>>();
        bus.read(servo, torque.address, torque.size, ReadSource::ReadBack,
                 [&table, &torque, torqueNow](const QByteArray &bytes) {
                     *torqueNow = valueOf(table, torque, bytes);
                 })([&bus, servo, &table, torqueNow, next](bool ok, const QString &message) {
            if (!ok) {
                next(false, message);
                return;
            }
            if (*torqueNow && table.torqueMode(**torqueNow) == TorqueMode::On) {
                next(true, {}); // already holding: its goal is its own business
                return;
            }
            auto otherMode = std::make_shared<bool>(false);
            holdAtPresentPosition(bus, servo, {},
                                  otherMode)([next, otherMode](bool held, const QString &why) {
                // Outside position mode the goal is no position: there is nothing to hold.
                if (!held && *otherMode) {
                    next(true, {});
                    return;
                }
                next(held,
                     held ? QString() : FeetechSessionTr::tr("%1 Torque stays off.").arg(why));
            });
        });
    };
}

Step holdAtPresentPosition(BusExchange &bus, std::shared_ptr<ServoInfo> servo,
                           std::shared_ptr<std::optional<qint32>> heldAt,
                           std::shared_ptr<bool> notInPositionMode)
{
    return [&bus, servo, heldAt, notInPositionMode](StepDone next) {
        const RegisterTable &table = servo->table();
        const Register *mode = table.find(kMode);
        if (!mode) {
            writeGoalAtPresent(bus, servo, heldAt)(next);
            return;
        }
        // In wheel, PWM or step mode the goal is no position (in step mode a goal is a
        // relative move): writing the present position there would move the horn or do
        // nothing. Only position mode (0) is held.
        auto modeNow = std::make_shared<std::optional<qint32>>();
        bus.read(servo, mode->address, mode->size, ReadSource::ReadBack,
                 [&table, mode, modeNow](const QByteArray &bytes) {
                     *modeNow = valueOf(table, *mode, bytes);
                 })([&bus, servo, heldAt, notInPositionMode, modeNow,
                     next](bool ok, const QString &message) {
            if (!ok) {
                next(false, message);
                return;
            }
            if (!*modeNow) {
                bus.fail(next, OperationFailure::BadReply,
                         FeetechSessionTr::tr("The operating mode could not be read."));
                return;
            }
            if (**modeNow != 0) {
                if (notInPositionMode)
                    *notInPositionMode = true;
                bus.fail(next, OperationFailure::Unsupported,
                         FeetechSessionTr::tr(
                             "Servo %1 is not in position mode (mode %2): its goal is not a "
                             "position, so it cannot be held there.")
                             .arg(servo->id)
                             .arg(**modeNow));
                return;
            }
            writeGoalAtPresent(bus, servo, heldAt)(next);
        });
    };
}

namespace {

Step writeGoalAtPresent(BusExchange &bus, std::shared_ptr<ServoInfo> servo,
                        std::shared_ptr<std::optional<qint32>> heldAt)
{
    return [&bus, servo, heldAt](StepDone next) {
        const RegisterTable &table = servo->table();
        const Register &present = *table.find(kPresentPosition);
        const Register &goal = *table.find(kGoalPosition);
        auto where = std::make_shared<std::optional<qint32>>();
        bus.read(servo, present.address, present.size, ReadSource::ReadBack,
                 [&table, &present, where](const QByteArray &bytes) {
                     *where = valueOf(table, present, bytes);
                 })(
            [&bus, servo, &table, &goal, where, heldAt, next](bool ok, const QString &message) {
                if (!ok) {
                    next(false, message);
                    return;
                }
                if (!*where) {
                    bus.fail(next, OperationFailure::BadReply,
                             FeetechSessionTr::tr("The present position could not be read."));
                    return;
                }
                QString error;
                const auto writes = encodeWrites(table, {{goal.key, **where}}, &error);
                if (!writes || writes->size() != 1) {
                    bus.fail(
                        next, OperationFailure::InvalidRequest,
                        FeetechSessionTr::tr("The goal cannot be set to the present position (%1).")
                            .arg(error));
                    return;
                }
                if (heldAt)
                    *heldAt = *where;
                const RegisterWrite hold = writes->first();
                bus.runSteps(
                    {bus.write(servo->id, hold.address, hold.bytes, servo->repliesToWrites(),
                               FeetechSessionTr::tr("Setting the goal to the present position")),
                     bus.read(servo, goal.address, goal.size, ReadSource::ReadBack)},
                    next);
            });
    };
}

} // namespace

QString whyNotToMove(const ServoInfo &servo, const QHash<QString, qint32> &before,
                     bool *torqueWasOn)
{
    // Register 33: every family's mode 0 holds a position.
    if (before.contains(kMode) && before.value(kMode) != 0) {
        return FeetechSessionTr::tr("%1 is not in position mode (mode %2): it is not moved.")
            .arg(servoName(servo))
            .arg(before.value(kMode));
    }
    const auto torque = servo.table().torqueMode(before.value(kTorqueEnable));
    if (torque != TorqueMode::On && torque != TorqueMode::Off) {
        return FeetechSessionTr::tr(
                   "%1 holds torque enable %2, neither on nor off: it is not moved.")
            .arg(servoName(servo))
            .arg(before.value(kTorqueEnable));
    }
    *torqueWasOn = torque == TorqueMode::On;
    return {};
}

QString notRestoredAsItWas(const QStringList &keys, const QHash<QString, qint32> &before,
                           const QHash<QString, qint32> &now)
{
    QStringList differ;
    for (const QString &key : keys) {
        if (now.value(key) != before.value(key))
            differ.append(FeetechSessionTr::tr("%1 reads %2, not %3")
                              .arg(key)
                              .arg(now.value(key))
                              .arg(before.value(key)));
    }
    if (differ.isEmpty())
        return {};
    return FeetechSessionTr::tr("it was not restored as it was: %1.")
        .arg(differ.join(QStringLiteral(", ")));
}

} // namespace feetech
