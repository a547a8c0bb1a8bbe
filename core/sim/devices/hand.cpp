// The simulator's hand: turns and sweeps of horns whose torque is off, asked for in present
// positions, carried out on the horns.
#include "hand.h"

#include "virtualfeetechbus.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace {

struct Tr
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

bool fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return false;
}

} // namespace

Hand::Hand(VirtualFeetechBus &bus)
    : m_bus(bus)
{ }

QString Hand::describe(int index) const
{
    return Tr::tr("servo #%1 (ID %2)").arg(index + 1).arg(m_bus.servo(index).id());
}

bool Hand::checkServo(int index, std::initializer_list<int> positions, QString *error) const
{
    if (index < 0 || index >= m_bus.servoCount())
        return fail(error,
                    Tr::tr("there is no servo #%1 on the bus (it has %2)")
                        .arg(index + 1)
                        .arg(m_bus.servoCount()));
    if (holdsTorque(index, error))
        return false;
    const int maximum = maxPosition(m_bus.servo(index));
    for (const int position : positions) {
        if (position < 0 || position > maximum)
            return fail(error,
                        Tr::tr("position %1 is out of range: %2 turns from 0 to %3")
                            .arg(position)
                            .arg(describe(index))
                            .arg(maximum));
    }
    return true;
}

bool Hand::holdsTorque(int index, QString *error) const
{
    if (m_bus.servo(index).value(u"torque_enable") == 0)
        return false;
    fail(error,
         Tr::tr("%1 has its torque on: it holds its position and the hand cannot turn it")
             .arg(describe(index)));
    return true;
}

double Hand::hornAngle(int index, double position) const
{
    const VirtualFeetechServo &servo = m_bus.servo(index);
    return position + (fullCircle(servo) ? servo.value(u"position_offset") : 0.0);
}

void Hand::place(int index, double horn)
{
    m_bus.servo(index).setPhysicalPosition(horn);
}

bool Hand::turn(quint8 id, int position, QString *error)
{
    SimRefusal why;
    const auto index = m_bus.uniqueIndexOf(id, &why);
    if (!index)
        return fail(error, why.describe());
    return turnServo(*index, position, error);
}

bool Hand::turnServo(int index, int position, QString *error)
{
    if (!checkServo(index, {position}, error))
        return false;
    // A turn by hand ends a sweep of the same joint: one hand, one gesture.
    letGo(index);
    place(index, hornAngle(index, position));
    return true;
}

bool Hand::sweep(quint8 id, int from, int to, double seconds, int cycles, Way way, QString *error)
{
    SimRefusal why;
    const auto index = m_bus.uniqueIndexOf(id, &why);
    if (!index)
        return fail(error, why.describe());
    return sweepServo(*index, from, to, seconds, cycles, way, error);
}

bool Hand::sweepServo(int index, int from, int to, double seconds, int cycles, Way way,
                      QString *error)
{
    if (!checkServo(index, {from, to}, error))
        return false;
    if (!(seconds > 0.0) || seconds > kMaxSweepSeconds)
        return fail(
            error,
            Tr::tr("a sweep takes more than 0 and at most %1 seconds").arg(kMaxSweepSeconds));
    if (cycles < 0 || cycles > kMaxSweepCycles)
        return fail(error,
                    Tr::tr("a sweep runs 0 (until released) to %1 times").arg(kMaxSweepCycles));
    double end = to;
    const bool crosses = (way == Way::Up && to < from) || (way == Way::Down && to > from);
    if (crosses) {
        if (!fullCircle(m_bus.servo(index)))
            return fail(error,
                        Tr::tr("%1 is an SCS servo: it stops at 0 and %2, there is no "
                               "seam to sweep across")
                            .arg(describe(index))
                            .arg(maxPosition(m_bus.servo(index))));
        end += way == Way::Up ? ServoMotion::kFullCircleSteps : -ServoMotion::kFullCircleSteps;
    }
    letGo(index);
    // The hand holds the horn: from now on it moves between these angles, whatever the offset
    // (and so the readings) become.
    m_sweeps.push_back(Sweep {index, hornAngle(index, from), hornAngle(index, end), seconds * 1e6,
                              cycles, m_bus.nowUs()});
    place(index, m_sweeps.back().from);
    return true;
}

void Hand::letGo(int index)
{
    m_sweeps.erase(std::remove_if(m_sweeps.begin(), m_sweeps.end(),
                                  [index](const Sweep &sweep) { return sweep.index == index; }),
                   m_sweeps.end());
}

int Hand::stop()
{
    const int stopped = int(m_sweeps.size());
    m_sweeps.clear();
    return stopped;
}

bool Hand::isSweeping(int index) const
{
    return std::any_of(m_sweeps.cbegin(), m_sweeps.cend(),
                       [index](const Sweep &sweep) { return sweep.index == index; });
}

void Hand::advanceTo(qint64 nowUs)
{
    for (auto it = m_sweeps.begin(); it != m_sweeps.end();) {
        const Sweep &sweep = *it;
        QString resisted;
        if (holdsTorque(sweep.index, &resisted)) {
            m_notes.append(Tr::tr("the hand lets go: %1").arg(resisted));
            it = m_sweeps.erase(it);
            continue;
        }
        const double elapsed = double(std::max<qint64>(0, nowUs - sweep.startUs));
        if (sweep.cycles > 0 && elapsed >= sweep.cycles * sweep.periodUs) {
            place(sweep.index, sweep.from);
            m_notes.append(
                Tr::tr("the hand finished sweeping %1 (%n time(s))", nullptr, sweep.cycles)
                    .arg(describe(sweep.index)));
            it = m_sweeps.erase(it);
            continue;
        }
        // A triangle wave: FROM to TO in the first half of each period, back in the second.
        const double phase = std::fmod(elapsed, sweep.periodUs) / sweep.periodUs;
        const double share = phase < 0.5 ? 2.0 * phase : 2.0 - 2.0 * phase;
        place(sweep.index, sweep.from + (sweep.to - sweep.from) * share);
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
}

QStringList Hand::takeNotes()
{
    QStringList notes;
    notes.swap(m_notes);
    return notes;
}

} // namespace sim
