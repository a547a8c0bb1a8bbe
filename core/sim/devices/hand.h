// The simulator's hand: turns the horns of simulated Feetech servos whose torque is off, at once
// or in a scripted back-and-forth sweep, as a user moving joints during a calibration would.
// Pure logic: time passes through the bus's advanceTo().
#pragma once

#include "simrefusal.h"

#include <QString>
#include <QStringList>
#include <QtGlobal>

#include <initializer_list>
#include <vector>

namespace sim {

class VirtualFeetechBus;

class Hand
{
public:
    // How a sweep goes from FROM to TO on a full-circle servo: straight between the two numbers,
    // or always upward / downward, crossing the 4095/0 seam when it has to (3900 up to 200).
    enum class Way { Direct, Up, Down };
    static constexpr double kMaxSweepSeconds = 3600.0;
    // Turns of one horn this close together are one gesture (a slider dragged): the encoder
    // sees the speed between them, for as long again after the last one.
    static constexpr qint64 kTurnGestureUs = 250'000;
    static constexpr int kMaxSweepCycles = 1'000'000;

    explicit Hand(VirtualFeetechBus &bus);
    Hand(const Hand &) = delete;
    Hand &operator=(const Hand &) = delete;

    // A turn soon after the last one of the same horn (kTurnGestureUs) carries on a gesture:
    // the servo reports the speed between them, and that it moves, until the gesture pauses.
    // Positions are present positions, what the host reads (the horn less the position offset)
    // when the hand takes hold: 0-4095 on a full-circle servo, 0-1023 on an SCS. The hand then
    // holds the horn: an offset changed later changes the readings, not where the horn is, as on
    // a real servo. A servo with its torque on holds its position: the hand refuses it. By ID
    // the servo must be the only one at that ID.
    // Refused, *why says why: NoSuchId, SharedId, NoSuchPlace, TorqueOn, PositionOutOfRange,
    // and for a sweep SweepTooLong, TooManyCycles, NoSeam.
    bool turn(quint8 id, int position, SimRefusal *why = nullptr);
    bool turnServo(int index, int position, SimRefusal *why = nullptr);
    // From FROM to TO and back in `seconds`, `cycles` times (0: until stop()); the horn starts
    // at FROM now and rests at FROM at the end. A sweep lets go when the servo's torque comes on.
    bool sweep(quint8 id, int from, int to, double seconds, int cycles = 0, Way way = Way::Direct,
               SimRefusal *why = nullptr);
    bool sweepServo(int index, int from, int to, double seconds, int cycles = 0,
                    Way way = Way::Direct, SimRefusal *why = nullptr);
    // The same, as a person's hand does it: the horn is first taken from where it stands to
    // FROM, straight along the numbers at the sweep's speed, never in one jump (which a reader
    // of the encoder takes for a turn across the seam).
    bool sweepServoFromHere(int index, int from, int to, double seconds, int cycles = 0,
                            Way way = Way::Direct, SimRefusal *why = nullptr);
    // Lets go of every servo; the number of sweeps stopped.
    int stop();
    bool isSweeping(int index) const;
    int sweepCount() const { return int(m_sweeps.size()); }

    // Called by the bus after the servos have advanced to `nowUs`.
    void advanceTo(qint64 nowUs);
    // The servo at `index` left the bus: its sweep ends and later servos move up one place.
    void servoUnplugged(int index);
    // What the hand did on its own since the last call (a sweep ended or was resisted).
    QStringList takeNotes();

    // How the hand's sentences name the servo at place `index` (0-based) with `id`.
    static QString describe(int index, int id);

private:
    struct Sweep
    {
        int index = 0;
        // Horn angles (present position plus the offset when the sweep began); `to` may lie
        // beyond 0-4095: the way across the seam.
        double from = 0.0;
        double to = 0.0;
        double periodUs = 0.0;
        int cycles = 0;
        qint64 startUs = 0; // when the horn is at FROM and the first sweep begins
        double approachFrom = 0.0; // the horn's angle when the hand took it
        qint64 approachStartUs = 0;
    };
    // The last turn of a horn by hand, while it may be part of a gesture.
    struct Turn
    {
        int index = 0;
        double horn = 0.0;
        double stepsPerSecond = 0.0;
        qint64 atUs = 0;
    };

    bool startSweep(int index, int from, int to, double seconds, int cycles, Way way, bool fromHere,
                    SimRefusal *why);
    // The servo exists, its torque is off and every position is in its range.
    bool checkServo(int index, std::initializer_list<int> positions, SimRefusal *why) const;
    bool holdsTorque(int index, SimRefusal *why) const;
    // The horn's angle for a present position, with the servo's offset now.
    double hornAngle(int index, double position) const;
    // Puts the horn at `horn`, turning at `stepsPerSecond` (0: held still there).
    void place(int index, double horn, double stepsPerSecond = 0.0);
    void letGo(int index);
    QString describe(int index) const;

    VirtualFeetechBus &m_bus;
    std::vector<Sweep> m_sweeps;
    std::vector<Turn> m_turns;
    QStringList m_notes;
};

} // namespace sim
