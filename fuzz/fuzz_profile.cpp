// Fuzz target: a parameter profile as every family reads it (PTK and the Feetech families); a
// profile read is written and read back to the same values.
#include "fuzztarget.h"
#include "profile.h"
#include "ptkparameters.h"
#include "registertable.h"
#include "servoparameters.h"

namespace {

struct FamilyDefinitions
{
    QString family;
    QVector<model::Definition> definitions;
};

QVector<FamilyDefinitions> allFamilies()
{
    QVector<FamilyDefinitions> families {{QStringLiteral("ptk"), ptk::modelDefinitions()}};
    for (const feetech::Family family : feetech::kAllFamilies)
        families.append({feetech::familyKey(family),
                         feetech::profileDefinitions(feetech::RegisterTable::forFamily(family))});
    return families;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    static const QVector<FamilyDefinitions> families = allFamilies();
    const QByteArray json = fuzz::input(data, size);
    for (const FamilyDefinitions &family : families) {
        util::FileError error;
        const auto profile = profile::parse(json, family.family, family.definitions, &error);
        if (!profile) {
            FUZZ_CHECK(error && !error.describe().isEmpty());
            continue;
        }
        FUZZ_CHECK(profile->family == family.family);
        const QByteArray written = profile::toJson(*profile, family.definitions);
        const auto reread = profile::parse(written, family.family, family.definitions, &error);
        FUZZ_CHECK(reread.has_value());
        FUZZ_CHECK(reread->values == profile->values);
        FUZZ_CHECK(reread->model == profile->model);
        FUZZ_CHECK(reread->note == profile->note);
        FUZZ_CHECK(profile::toJson(*reread, family.definitions) == written);
    }
    return 0;
}
