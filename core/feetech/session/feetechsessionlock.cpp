// The Feetech session's EEPROM lock operation: closes a lock left open and reads it back.
#include "feetechsession.h"

#include <QCoreApplication>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(FeetechSession)
};

} // namespace

namespace feetech {

void Session::lockEeprom(const ServoInfo &servo)
{
    enqueue(Operation::LockEeprom, [this, servo] {
        const Register *lock = registerAt(servo, u"lock");
        if (!lock) {
            finishOperation({Operation::LockEeprom,
                             false,
                             Tr::tr("The servo's model has no known EEPROM lock register."),
                             servo,
                             {}});
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        // What the servo says after the write, not that the write was answered, is the result.
        auto readBack = std::make_shared<std::optional<int>>();
        std::vector<Step> steps {m_bus->setBaud(servo.baud), m_bus->lock(target, true),
                                 m_bus->read(target, lock->address, lock->size,
                                             ReadSource::ReadBack,
                                             [readBack](const QByteArray &bytes) {
                                                 if (!bytes.isEmpty())
                                                     *readBack = quint8(bytes.at(0));
                                             })};
        m_bus->runSteps(std::move(steps), [this, servo, readBack](bool ok, const QString &message) {
            const bool locked = ok && readBack->has_value() && **readBack != 0;
            QString text = message;
            if (locked)
                text = Tr::tr("Servo %1's EEPROM is locked (read back).").arg(servo.id);
            else if (ok)
                text = Tr::tr("Servo %1 still reads back unlocked after the lock was written.")
                           .arg(servo.id);
            finishOperation({Operation::LockEeprom, locked, text, servo, {}});
        });
    });
}

} // namespace feetech
