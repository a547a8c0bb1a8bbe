// The fault soak: thousands of reads and writes through the GUI's own clients against a
// simulated bus that drops, corrupts, truncates and pads replies and loses requests, every value
// shown and every write's outcome checked against what the simulator holds.
#pragma once

#include "faultsettings.h"

#include <QJsonObject>
#include <QStringList>

namespace soak {

struct SoakOptions
{
    int transactions = 10000;
    quint32 seed = 1;
    // 10 % of each where it applies: replies dropped, corrupted, truncated, preceded by noise,
    // and requests lost on their way.
    sim::FaultSettings faults {0.1, 0.1, 0.1, 0.1, 0, 0.1};
};

struct SoakCounts
{
    int transactions = 0; // operations asked for (reads, applies)
    int readsOk = 0;
    int readsFailed = 0;
    qint64 valuesChecked = 0; // values a finished read showed, each compared with the simulator
    qint64 wrongValues = 0; // shown values the simulator did not hold
    int writesAsked = 0; // registers (Feetech) or parameters (PTK) an apply was to write
    int writesVerified = 0; // reported written and read back
    int writesMismatch = 0; // read back, different: reported as such
    int writesFailed = 0; // reported not written
    int writesUnknown = 0; // the outcome could not be learnt: reported as unknown
    int lostWrites = 0; // reported written, but the simulator does not hold the value
    int falseFailures = 0; // reported not written, but the simulator holds the value
    int hangs = 0; // operations that never finished
    int appliesRefused = 0; // PTK: the servo was not answering, a read went first
    int eepromLeftUnlocked = 0; // servos whose lock is open at the end
    QStringList examples; // the first few wrong values and false reports, for the reader

    bool trustworthy() const
    {
        return wrongValues == 0 && lostWrites == 0 && falseFailures == 0 && hangs == 0
            && eepromLeftUnlocked == 0;
    }
    QJsonObject toJson() const;
};

// Six STS3215 at 1 Mbps through feetech::BusClient: full table reads and applies of RAM and
// EEPROM registers (locked writes), chosen at random.
SoakCounts soakFeetech(const SoakOptions &options);
// The PTK servo through ptk::Client: reads of the eight queries and applies of the twelve
// parameters.
SoakCounts soakPtk(const SoakOptions &options);

} // namespace soak
