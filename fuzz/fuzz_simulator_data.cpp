// Fuzz target: the simulator's facts file (resources/feetech/simulator.json) as SimulatorData
// reads it; every family of data accepted answers for its firmware and defaults.
#include "fuzztarget.h"
#include "registertable.h"
#include "simulatordata.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    QString error;
    const auto parsed = sim::SimulatorData::parse(fuzz::input(data, size), source, &error);
    if (!parsed) {
        FUZZ_CHECK(error.contains(source));
        return 0;
    }
    for (const feetech::Family family : feetech::kAllFamilies) {
        const sim::SimulatedFirmware firmware = parsed->firmware(family);
        FUZZ_CHECK(firmware.major >= 0 && firmware.major <= 255);
        FUZZ_CHECK(firmware.minor >= 0 && firmware.minor <= 255);
        for (const feetech::Register &reg : feetech::RegisterTable::forFamily(family).registers())
            parsed->fallbackDefault(family, reg.key);
    }
    return 0;
}
