// Fuzz target: the model table (resources/feetech/models.json) as the loader reads it; a table
// accepted names each model once and identifies every model number.
#include "fuzztarget.h"
#include "modeltable.h"
#include "registertable.h"

#include <QSet>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    QString error;
    const auto table = feetech::ModelTable::fromJson(fuzz::input(data, size), source, &error);
    if (!table) {
        FUZZ_CHECK(error.startsWith(source));
        return 0;
    }
    for (const qint32 rate : table->baudRates())
        FUZZ_CHECK(rate > 0);
    QSet<int> numbers;
    for (const feetech::ModelInfo &model : table->models()) {
        FUZZ_CHECK(model.major >= 0 && model.major <= 255 && model.minor >= 0
                   && model.minor <= 255);
        FUZZ_CHECK(!model.name.isEmpty());
        numbers.insert(model.major * 256 + model.minor);
        const feetech::ModelInfo identified =
            table->identify(quint8(model.major), quint8(model.minor));
        FUZZ_CHECK(identified.major == model.major && identified.minor == model.minor);
        FUZZ_CHECK(identified.name == model.name);
        FUZZ_CHECK(identified.family == model.family);
        // Found by each of its names (a model of that name is: names may repeat).
        for (const QString &alias : model.name.split(u'/'))
            FUZZ_CHECK(table->findByName(alias).has_value());
    }
    FUZZ_CHECK(numbers.size() == table->models().size());
    // Any number is identified, listed or not, with no crash; an unlisted one keeps its numbers.
    for (const int major : {0, 1, 5, 9, 255}) {
        const feetech::ModelInfo identified = table->identify(quint8(major), 42);
        FUZZ_CHECK(identified.major == major && identified.minor == 42);
    }
    return 0;
}
