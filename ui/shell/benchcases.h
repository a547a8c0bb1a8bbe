// What goes wrong on a real bench (a servo without power, a broken daisy chain, a supply out of
// range, heat, a blocked horn, a latched overload), played on the simulated bus so the Doctor,
// the health check and the guard can be seen at work.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QVector>

namespace sim {
class VirtualFeetechBus;
} // namespace sim

class BenchCases
{
    Q_DECLARE_TR_FUNCTIONS(BenchCases)

public:
    // Played on the selected servo or the whole bus.
    enum class Case {
        CutPower, // the selected servo
        RestorePower,
        BreakChainAfter, // every servo after the selected one loses signal and power
        MendChain,
        BlockHorn, // something holds the selected servo's horn
        FreeHorn,
        Heat, // the selected servo warms by kHeatPerSecond
        StopHeating,
        LatchOverload, // until the next power cycle
        SupplyTooHigh, // the bus: kHighSupplyVolts
        SupplyTooLow, // the bus: kLowSupplyVolts
        SupplyNormal, // each servo its family's usual supply
    };
    static constexpr double kHeatPerSecond = 1.0;
    static constexpr double kHighSupplyVolts = 12.6;
    static constexpr double kLowSupplyVolts = 4.5;

    // Every case, in the order a list offers them.
    static QVector<Case> all();
    // What a list calls it.
    static QString title(Case benchCase);
    // Whether it is played on one servo (the selected one), not on the whole bus.
    static bool needsServo(Case benchCase);
    // Plays it on `bus`, on the servo at `index` where it needs one; false when the bus refused.
    static bool play(Case benchCase, sim::VirtualFeetechBus &bus, int index);
    // What the bus is like after it was played (on the servo at `index`), for the user.
    static QString outcome(Case benchCase, int index);
};
