// The simulator's hand: turns and sweeps of horns whose torque is off, asked for in present
// positions, carried out on the horns.
#include "hand.h"

#include "virtualfeetechbus.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace {

struct HandTr
{
    Q_DECLARE_TR_FUNCTIONS(Hand)
};

} // namespace

namespace sim {

namespace {

bool fullCircle(const VirtualFeetechServo &servo)
{
    return servo.family() != feetech::Family::Scs;
}

int maxPosition(const VirtualFeetechServo &servo)
{
    return fullCircle(servo) ? ServoMotion::kFullCircleSteps - 1 : ServoMotion::kScsMaxPosition;
}

// A sweep from and to the same place still gets there at a hand's pace.
constexpr double kLeastApproachSpeed = 500.0; // steps a second

// How fast the sweep's horn turns: there and back in one period.
double approachSpeed(double from, double to, double periodUs)
{
    return 2.0 * std::abs(to - from) / (periodUs / 1e6);
}

bool fail(const SimRefusal &refusal, SimRefusal *why)
{
    refused(refusal, why);
    return false;
}

} // namespace

Hand::Hand(VirtualFeetechBus &bus)
    : m_bus(bus)
{ }

QString Hand::describe(int index, int id)
{
    return HandTr::tr("servo #%1 (ID %2)").arg(index + 1).arg(id);
}

QString Hand::describe(int index) const
{
    return describe(index, m_bus.servo(index).id());
}

bool Hand::checkServo(int index, std::initializer_list<int> positions, SimRefusal *why) const
{
    if (index < 0 || index >= m_bus.servoCount())
        return fail(SimRefusal(SimRefusal::Code::NoSuchPlace, index + 1, m_bus.servoCount()), why);
    if (holdsTorque(index, why))
        return false;
    const int maximum = maxPosition(m_bus.servo(index));
    for (const int position : positions) {
        if (position < 0 || position > maximum)
            return fail(SimRefusal::ofServo(SimRefusal::Code::PositionOutOfRange, index + 1,
                                            m_bus.servo(index).id(), position, maximum),
                        why);
    }
    return true;
}

bool Hand::holdsTorque(int index, SimRefusal *why) const
{
    if (m_bus.servo(index).value(u"torque_enable") == 0)
        return false;
    refused(SimRefusal::ofServo(SimRefusal::Code::TorqueOn, index + 1, m_bus.servo(index).id()),
            why);
    return true;
}

double Hand::hornAngle(int index, double position) const
{
    const VirtualFeetechServo &servo = m_bus.servo(index);
    return position + (fullCircle(servo) ? servo.value(u"position_offset") : 0.0);
}

void Hand::place(int index, double horn, double stepsPerSecond)
{
    m_bus.servo(index).turnByHand(horn, stepsPerSecond);
}

bool Hand::turn(quint8 id, int position, SimRefusal *why)
{
    const auto index = m_bus.uniqueIndexOf(id, why);
    return index && turnServo(*index, position, why);
}

bool Hand::turnServo(int index, int position, SimRefusal *why)
{
    if (!checkServo(index, {position}, why))
        return false;
    // A turn by hand ends a sweep of the same joint: one hand, one gesture.
    const auto previous = std::find_if(m_turns.cbegin(), m_turns.cend(),
                                       [index](const Turn &turn) { return turn.index == index; });
    const Turn last = previous != m_turns.cend() ? *previous : Turn {index, 0.0, 0.0, -1};
    letGo(index);
    const double horn = hornAngle(index, position);
    const qint64 nowUs = m_bus.nowUs();
    double speed = 0.0;
    if (last.atUs >= 0 && nowUs > last.atUs && nowUs - last.atUs <= kTurnGestureUs) {
        double steps = horn - last.horn;
        if (fullCircle(m_bus.servo(index))) // the short way, across the seam if need be
            steps = std::remainder(steps, double(ServoMotion::kFullCircleSteps));
        speed = steps / (double(nowUs - last.atUs) / 1e6);
    }
    m_turns.push_back(Turn {index, horn, speed, nowUs});
    place(index, horn, speed);
    return true;
}

bool Hand::sweep(quint8 id, int from, int to, double seconds, int cycles, Way way, SimRefusal *why)
{
    const auto index = m_bus.uniqueIndexOf(id, why);
    return index && sweepServo(*index, from, to, seconds, cycles, way, why);
}

bool Hand::sweepServo(int index, int from, int to, double seconds, int cycles, Way way,
                      SimRefusal *why)
{
    return startSweep(index, from, to, seconds, cycles, way, false, why);
}

bool Hand::sweepServoFromHere(int index, int from, int to, double seconds, int cycles, Way way,
                              SimRefusal *why)
{
    return startSweep(index, from, to, seconds, cycles, way, true, why);
}

bool Hand::startSweep(int index, int from, int to, double seconds, int cycles, Way way,
                      bool fromHere, SimRefusal *why)
{
    if (!checkServo(index, {from, to}, why))
        return false;
    if (!(seconds > 0.0) || seconds > kMaxSweepSeconds)
        return fail(SimRefusal(SimRefusal::Code::SweepTooLong), why);
    if (cycles < 0 || cycles > kMaxSweepCycles)
        return fail(SimRefusal(SimRefusal::Code::TooManyCycles), why);
    double end = to;
    const bool crosses = (way == Way::Up && to < from) || (way == Way::Down && to > from);
    if (crosses) {
        if (!fullCircle(m_bus.servo(index)))
            return fail(SimRefusal::ofServo(SimRefusal::Code::NoSeam, index + 1,
                                            m_bus.servo(index).id(), 0,
                                            maxPosition(m_bus.servo(index))),
                        why);
        end += way == Way::Up ? ServoMotion::kFullCircleSteps : -ServoMotion::kFullCircleSteps;
    }
    letGo(index);
    // The hand holds the horn: from now on it moves between these angles, whatever the offset
    // (and so the readings) become. From here, it gets to FROM first, straight along the
    // numbers (never across the seam), as fast as it then sweeps.
    Sweep sweep {index, hornAngle(index, from), hornAngle(index, end), seconds * 1e6, cycles};
    sweep.approachFrom = fromHere ? m_bus.servo(index).physicalPosition() : sweep.from;
    sweep.approachStartUs = m_bus.nowUs();
    const double speed =
        std::max(kLeastApproachSpeed, approachSpeed(sweep.from, sweep.to, sweep.periodUs));
    sweep.startUs =
        sweep.approachStartUs + qint64(std::abs(sweep.from - sweep.approachFrom) / speed * 1e6);
    m_sweeps.push_back(sweep);
    if (!fromHere)
        place(index, sweep.from);
    return true;
}

void Hand::letGo(int index)
{
    m_sweeps.erase(std::remove_if(m_sweeps.begin(), m_sweeps.end(),
                                  [index](const Sweep &sweep) { return sweep.index == index; }),
                   m_sweeps.end());
    m_turns.erase(std::remove_if(m_turns.begin(), m_turns.end(),
                                 [index](const Turn &turn) { return turn.index == index; }),
                  m_turns.end());
}

int Hand::stop()
{
    const int stopped = int(m_sweeps.size());
    m_sweeps.clear();
    m_turns.clear();
    return stopped;
}

bool Hand::isSweeping(int index) const
{
    return std::any_of(m_sweeps.cbegin(), m_sweeps.cend(),
                       [index](const Sweep &sweep) { return sweep.index == index; });
}

void Hand::advanceTo(qint64 nowUs)
{
    // A gesture goes on turning the horn until it pauses; the motor, free, stopped it meanwhile.
    for (auto it = m_turns.begin(); it != m_turns.end();) {
        if (nowUs - it->atUs > kTurnGestureUs || holdsTorque(it->index, nullptr)) {
            it = m_turns.erase(it);
            continue;
        }
        if (it->stepsPerSecond != 0.0)
            place(it->index, it->horn, it->stepsPerSecond);
        ++it;
    }
    for (auto it = m_sweeps.begin(); it != m_sweeps.end();) {
        const Sweep &sweep = *it;
        SimRefusal resisted;
        if (holdsTorque(sweep.index, &resisted)) {
            m_notes.append(HandTr::tr("the hand lets go: %1").arg(resisted.describe()));
            it = m_sweeps.erase(it);
            continue;
        }
        if (nowUs < sweep.startUs) {
            // On its way to FROM.
            const double share = std::clamp(double(nowUs - sweep.approachStartUs)
                                                / double(sweep.startUs - sweep.approachStartUs),
                                            0.0, 1.0);
            const double speed = (sweep.from - sweep.approachFrom)
                / (double(sweep.startUs - sweep.approachStartUs) / 1e6);
            place(sweep.index, sweep.approachFrom + (sweep.from - sweep.approachFrom) * share,
                  speed);
            ++it;
            continue;
        }
        const double elapsed = double(std::max<qint64>(0, nowUs - sweep.startUs));
        if (sweep.cycles > 0 && elapsed >= sweep.cycles * sweep.periodUs) {
            place(sweep.index, sweep.from);
            m_notes.append(
                HandTr::tr("the hand finished sweeping %1 (%n time(s))", nullptr, sweep.cycles)
                    .arg(describe(sweep.index)));
            it = m_sweeps.erase(it);
            continue;
        }
        // A triangle wave: FROM to TO in the first half of each period, back in the second.
        // The encoder sees the horn turn at the wave's slope, as a real servo turned by hand
        // reports its speed and that it moves.
        const double phase = std::fmod(elapsed, sweep.periodUs) / sweep.periodUs;
        const double share = phase < 0.5 ? 2.0 * phase : 2.0 - 2.0 * phase;
        const double speed = 2.0 * (sweep.to - sweep.from) / (sweep.periodUs / 1e6);
        place(sweep.index, sweep.from + (sweep.to - sweep.from) * share,
              phase < 0.5 ? speed : -speed);
        ++it;
    }
}

void Hand::servoUnplugged(int index)
{
    letGo(index);
    for (Sweep &sweep : m_sweeps) {
        if (sweep.index > index)
            --sweep.index;
    }
    for (Turn &turn : m_turns) {
        if (turn.index > index)
            --turn.index;
    }
}

QStringList Hand::takeNotes()
{
    QStringList notes;
    notes.swap(m_notes);
    return notes;
}

} // namespace sim
