// The scan options last chosen in the scan dialog, kept across runs (QSettings).
#pragma once

#include "bustypes.h"

namespace scanmemory {

// What was chosen last, each part checked (IDs in range, known rates); the defaults otherwise.
feetech::ScanOptions rememberedScanOptions();
void rememberScanOptions(const feetech::ScanOptions &options);

} // namespace scanmemory
