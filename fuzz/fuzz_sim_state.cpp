// Fuzz target: the simulator's state file (servosim --state) as VirtualFeetechBus reads it; a
// refused file changes nothing, an accepted one leaves each servo with the file's EEPROM values.
#include "fuzztarget.h"
#include "virtualfeetechbus.h"
#include "virtualfeetechservo.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    // One bus for every input, put back to its first state after an input that changed it.
    static sim::VirtualFeetechBus bus({{1, QStringLiteral("STS3215"), 0},
                                       {2, QStringLiteral("SCS009"), 0},
                                       {3, QStringLiteral("HLS"), 0}});
    static const QByteArray pristine = bus.stateJson();

    const QString path = QStringLiteral("fuzz.json");
    const QByteArray json = fuzz::input(data, size);
    sim::SimRefusal why;
    if (!bus.loadStateJson(json, path, &why)) {
        FUZZ_CHECK(why.file() == path);
        FUZZ_CHECK(why.describe().contains(path));
        FUZZ_CHECK(bus.stateJson() == pristine);
        return 0;
    }
    const QJsonArray servos = QJsonDocument::fromJson(json).object().value(u"servos").toArray();
    FUZZ_CHECK(servos.size() == bus.servoCount());
    for (int i = 0; i < bus.servoCount(); ++i) {
        const QByteArray image =
            QByteArray::fromHex(servos.at(i).toObject().value(u"eeprom").toString().toLatin1());
        // The servo takes the file's writable EEPROM registers (its model the file must match,
        // its firmware is its own).
        const QByteArray held = bus.servo(i).eepromImage();
        for (const feetech::Register &reg : bus.servo(i).table().registers()) {
            if (reg.storage == feetech::Storage::Eeprom && reg.writable())
                FUZZ_CHECK(held.mid(reg.address, reg.size) == image.mid(reg.address, reg.size));
        }
    }
    // What it saves now reads back as the same state.
    const QByteArray saved = bus.stateJson();
    FUZZ_CHECK(bus.loadStateJson(saved, path, &why));
    FUZZ_CHECK(bus.stateJson() == saved);
    FUZZ_CHECK(bus.loadStateJson(pristine, path, &why));
    return 0;
}
