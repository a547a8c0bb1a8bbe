// The Feetech session's guard operations: the guard's settings, its urgent hold or torque off,
// and the latched-overload recovery, queued like every other operation.
#include "feetechsession.h"
#include "overloadrecovery.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

} // namespace

namespace feetech {

void Session::setGuardSettings(const GuardSettings &settings)
{
    m_guard->setSettings(settings);
}

void Session::runGuardAction(std::function<void(std::function<void()> finished)> work)
{
    const auto start = [this, work = std::move(work)] {
        work([this] {
            m_running = false;
            QMetaObject::invokeMethod(this, &Session::startNextOperation, Qt::QueuedConnection);
        });
    };
    // Behind All torque off only: a servo pushing against a block must not wait for an apply.
    m_queue.insert(afterTorqueOff(), {Operation::Guard, start, 0});
    if (!m_running)
        startNextOperation();
}

void Session::recoverOverload(const ServoInfo &servo, bool checkOnly)
{
    const quint64 epoch = m_torqueOffEpoch;
    enqueue(Operation::RecoverOverload, [this, servo, checkOnly, epoch] {
        if (!checkOnly && refusedAfterTorqueOff(Operation::RecoverOverload, epoch))
            return;
        auto target = std::make_shared<ServoInfo>(servo);
        auto latched = std::make_shared<std::optional<bool>>();
        m_bus->runSteps(
            {m_bus->setBaud(servo.baud),
             feetech::recoverOverload(*m_bus, target, checkOnly, latched)},
            [this, servo, checkOnly, latched](bool ok, const QString &message) {
                OperationResult result {Operation::RecoverOverload, ok, message, servo, {}};
                result.stillLatched = ok && latched->value_or(false);
                if (result.stillLatched) {
                    result.ok = false;
                    result.message = powerCycleSteps(servo).join(QLatin1Char('\n'));
                } else if (ok) {
                    result.message = checkOnly
                        ? Tr::tr("Servo ID %1: the overload bit is clear; switch its torque on "
                                 "when you are ready.")
                              .arg(servo.id)
                        : Tr::tr("Servo ID %1 recovered: the overload bit is clear and it holds "
                                 "where it stands with torque on.")
                              .arg(servo.id);
                    if (!checkOnly) {
                        const Register *torque = registerAt(servo, u"torque_enable");
                        const auto on = servo.table().torqueValue(TorqueMode::On);
                        if (torque && on)
                            m_guard->noteWrites(servo,
                                                {{torque->address, QByteArray(1, char(*on))}});
                    }
                }
                m_bus->logNote(result.message, !result.ok);
                finishOperation(result);
            });
    });
}

} // namespace feetech
