// Power cut bench case: recognises the unlock and the first EEPROM write of a write sequence.
#include "powercut.h"

#include "virtualfeetechservo.h"

namespace sim {

std::optional<PowerCut> powerCutFromName(const QString &name)
{
    if (name == QLatin1String("after-unlock"))
        return PowerCut::AfterUnlock;
    if (name == QLatin1String("after-write"))
        return PowerCut::AfterWrite;
    return std::nullopt;
}

bool cutsPower(PowerCut cut, const VirtualFeetechServo &servo, const feetech::Packet &packet)
{
    if (cut == PowerCut::None || packet.code != quint8(feetech::Instruction::Write)
        || packet.parameters.size() < 2)
        return false;
    const feetech::Register *lock = servo.table().find(u"lock");
    if (!lock)
        return false;
    const int address = quint8(packet.parameters.at(0));
    if (cut == PowerCut::AfterUnlock)
        return address == lock->address && packet.parameters.at(1) == 0;
    const feetech::Register *written = servo.table().at(address);
    return written && address != lock->address && written->storage == feetech::Storage::Eeprom;
}

} // namespace sim
