// Deterministic fault injection on the simulator's replies and the host's frames (--faults ...
// --seed N).
#pragma once

#include "faultsettings.h"

#include <QByteArray>
#include <QRandomGenerator>
#include <QString>

namespace sim {

// What happened to one reply.
struct FaultOutcome
{
    QByteArray bytes; // empty when dropped
    qint64 extraDelayUs = 0;
    QString note; // "drop", "corrupt", ... for the log; empty when untouched
};

class FaultInjector
{
public:
    FaultInjector(const FaultSettings &settings, quint32 seed);

    // The same seed and the same sequence of replies give the same outcomes, always: every reply
    // draws the same number of random values whatever happens to it.
    FaultOutcome apply(const QByteArray &reply);
    // Whether the next host frame is lost on its way to the servos; from a generator of its
    // own, so requests never shift the replies' outcomes.
    bool loseRequest();

private:
    FaultSettings m_settings;
    QRandomGenerator m_random;
    QRandomGenerator m_requestRandom;
};

} // namespace sim
