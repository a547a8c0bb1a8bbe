// Looks up the Feetech register tables in tests: a family's table, and a register by key.
#pragma once

#include "registertable.h"

#include <QtGlobal>

namespace registerlookup {

inline const feetech::RegisterTable &sts()
{
    return feetech::RegisterTable::forFamily(feetech::Family::Sts);
}

inline const feetech::RegisterTable &scs()
{
    return feetech::RegisterTable::forFamily(feetech::Family::Scs);
}

// The register `key` of `table`; a test whose table lacks it stops at once.
inline const feetech::Register &reg(const feetech::RegisterTable &table, const char *key)
{
    const feetech::Register *found = table.find(QString::fromLatin1(key));
    if (!found)
        qFatal("register %s missing from the %s table", key,
               qPrintable(feetech::familyKey(table.family())));
    return *found;
}

} // namespace registerlookup
