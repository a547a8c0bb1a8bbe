// The faults servosim injects (--faults): how often each happens, read from its option.
#pragma once

#include "optionerror.h"

#include <QString>

#include <optional>

namespace sim {

struct FaultSettings
{
    double drop = 0; // probability a reply is not sent
    double corrupt = 0; // probability one bit of a reply is flipped
    double truncate = 0; // probability a reply is cut short
    double noise = 0; // probability stray bytes precede a reply
    int delayMs = 0; // each reply is late by a random 0..delayMs milliseconds
    double lost = 0; // probability a host frame never reaches the servos (noise on the way there)

    bool any() const
    {
        return drop > 0 || corrupt > 0 || truncate > 0 || noise > 0 || delayMs > 0 || lost > 0;
    }

    // "drop=0.2,corrupt=0.1,delay=30,lost=0.1"; nothing (and *error) on a bad spec.
    static std::optional<FaultSettings> parse(const QString &text, OptionError *error);
};

} // namespace sim
