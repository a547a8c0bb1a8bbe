// The resident memory of this process, as Linux reports it in /proc/self/status.
#pragma once

#include <optional>

namespace util {

struct ProcessMemory
{
    double residentMb = 0; // VmRSS: resident now
    double peakResidentMb = 0; // VmHWM: the most that was ever resident
};

// Nothing where /proc/self/status cannot be read (not Linux).
std::optional<ProcessMemory> processMemory();

} // namespace util
