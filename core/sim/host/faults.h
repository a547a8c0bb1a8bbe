// Deterministic fault injection on the simulator's replies (--faults ... --seed N).
#pragma once

#include "optionerror.h"

#include <QByteArray>
#include <QRandomGenerator>
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
