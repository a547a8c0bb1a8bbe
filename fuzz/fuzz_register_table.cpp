// Fuzz target: a register table (resources/feetech/registers-*.json) as the loader reads it; a
// table accepted keeps the promises the code relies on.
#include "feetechvalue.h"
#include "fuzztarget.h"
#include "registertable.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    QString error;
    const auto table = feetech::RegisterTable::fromJson(fuzz::input(data, size), source, &error);
    if (!table) {
        FUZZ_CHECK(error.startsWith(source));
        return 0;
    }
    const QVector<feetech::Register> &registers = table->registers();
    FUZZ_CHECK(!registers.isEmpty());
    int previousEnd = 0;
    for (const feetech::Register &reg : registers) {
        // Ascending addresses, no overlaps, inside the 256-byte register file.
        FUZZ_CHECK(reg.address >= previousEnd);
        FUZZ_CHECK(reg.size == 1 || reg.size == 2);
        FUZZ_CHECK(reg.end() <= 256);
        previousEnd = reg.end();
        FUZZ_CHECK(table->find(reg.key) == &reg);
        FUZZ_CHECK(table->at(reg.address) == &reg);
        FUZZ_CHECK(reg.minimum <= reg.maximum);
        FUZZ_CHECK(reg.scale > 0);
        if (reg.defaultValue)
            FUZZ_CHECK(*reg.defaultValue >= reg.minimum && *reg.defaultValue <= reg.maximum);
        // Every value of the range goes to the wire and comes back as itself.
        const feetech::ValueFormat format = table->format(reg);
        for (const qint32 value : {reg.minimum, reg.maximum}) {
            const auto bytes = feetech::encodeValue(value, format);
            FUZZ_CHECK(bytes.has_value());
            FUZZ_CHECK(bytes->size() == reg.size);
            FUZZ_CHECK(feetech::decodeValue(*bytes, format) == value);
        }
    }
    // Every register lies in one block of registers without gaps.
    for (const feetech::Register &reg : registers) {
        int holders = 0;
        for (const feetech::Block &block : table->blocks())
            holders += reg.address >= block.address && reg.end() <= block.address + block.size;
        FUZZ_CHECK(holders == 1);
    }
    for (const feetech::Block &block : table->ramBlocks())
        FUZZ_CHECK(block.size > 0 && block.address + block.size <= 256);
    const feetech::Block feedback = table->feedbackBlock();
    // A partial table may have no feedback block; a block there is inside the register file.
    FUZZ_CHECK(feedback.size >= 0);
    if (feedback.size > 0)
        FUZZ_CHECK(feedback.address >= 0 && feedback.address + feedback.size <= 256);
    return 0;
}
