// Tests the simulator's hand: turns and sweeps of horns whose torque is off, seam crossing,
// joints with torque on, and servos put at a shared ID.
#include "virtualfeetechbus.h"

#include <QtTest>

using sim::Hand;
using sim::SimRefusal;
using sim::VirtualFeetechBus;

namespace {

constexpr qint64 kMs = 1000;

std::unique_ptr<VirtualFeetechBus> armBus()
{
    SimRefusal why;
    auto bus = VirtualFeetechBus::create({{1, QStringLiteral("STS3215"), 0},
                                          {2, QStringLiteral("STS3215"), 0},
                                          {3, QStringLiteral("SCS15"), 0}},
                                         &why);
    if (!bus)
        qFatal("%s", qPrintable(why.describe()));
    return bus;
}

int present(VirtualFeetechBus &bus, quint8 id)
{
    return bus.findServo(id)->value(u"present_position");
}

} // namespace

class TestHand : public QObject
{
    Q_OBJECT

private slots:
    void turnPutsTheHornAtThePresentPositionAtOnce()
    {
        auto bus = armBus();
        SimRefusal why;
        QVERIFY2(bus->hand().turn(1, 1000, &why), qPrintable(why.describe()));
        QCOMPARE(present(*bus, 1), 1000);
        QVERIFY(bus->hand().turn(3, 1023));
        QCOMPARE(present(*bus, 3), 1023);
    }

    void turnCountsFromThePositionOffsetLikeTheHostReads()
    {
        auto bus = armBus();
        bus->findServo(1)->setValue(u"position_offset", 100);
        QVERIFY(bus->hand().turn(1, 50));
        QCOMPARE(present(*bus, 1), 50);
        QCOMPARE(qRound(bus->findServo(1)->physicalPosition()), 150);
    }

    void turnRefusesPositionsOutsideTheServosRange()
    {
        auto bus = armBus();
        SimRefusal why;
        QVERIFY(!bus->hand().turn(1, 4096, &why));
        QCOMPARE(why.code(), SimRefusal::Code::PositionOutOfRange);
        QCOMPARE(why.other(), 4095);
        QVERIFY(!bus->hand().turn(3, 1024, &why));
        QCOMPARE(why.code(), SimRefusal::Code::PositionOutOfRange);
        QCOMPARE(why.other(), 1023);
        QVERIFY(!bus->hand().turn(9, 100, &why));
        QCOMPARE(why.code(), SimRefusal::Code::NoSuchId);
        QCOMPARE(why.servo(), 9);
    }

    void aJointWithTorqueOnResistsTheHand()
    {
        auto bus = armBus();
        bus->findServo(2)->setValue(u"torque_enable", 1);
        const int before = present(*bus, 2);
        SimRefusal why;
        QVERIFY(!bus->hand().turn(2, before + 500, &why));
        QCOMPARE(why.code(), SimRefusal::Code::TorqueOn);
        QVERIFY(!bus->hand().sweep(2, 100, 200, 1.0, 1, Hand::Way::Direct, &why));
        QCOMPARE(why.code(), SimRefusal::Code::TorqueOn);
        QCOMPARE(present(*bus, 2), before);
    }

    void sweepGoesFromAToBAndBackOverItsPeriod()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 1000, 3000, 2.0, 2));
        QCOMPARE(present(*bus, 1), 1000);
        bus->advanceTo(500 * kMs);
        QCOMPARE(present(*bus, 1), 2000);
        bus->advanceTo(1000 * kMs);
        QCOMPARE(present(*bus, 1), 3000);
        bus->advanceTo(1500 * kMs);
        QCOMPARE(present(*bus, 1), 2000);
        bus->advanceTo(2500 * kMs); // the second cycle
        QCOMPARE(present(*bus, 1), 2000);
        QVERIFY(bus->hand().isSweeping(0));
        bus->advanceTo(4200 * kMs); // both cycles done: it rests at A and lets go
        QCOMPARE(present(*bus, 1), 1000);
        QVERIFY(!bus->hand().isSweeping(0));
        const QStringList notes = bus->hand().takeNotes();
        QCOMPARE(notes.size(), 1);
        QVERIFY2(notes.first().contains(QLatin1String("finished")), qPrintable(notes.first()));
        bus->advanceTo(5000 * kMs);
        QCOMPARE(present(*bus, 1), 1000);
    }

    void aSweptJointReportsItsSpeedAndThatItMoves()
    {
        // 2000 steps out in 1 s and back in 1 s: 2000 step/s each way, as the encoder sees it.
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 1000, 3000, 2.0, 1));
        bus->advanceTo(500 * kMs);
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 2000);
        QCOMPARE(bus->findServo(1)->value(u"moving"), 1);
        bus->advanceTo(1500 * kMs);
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), -2000);
        QCOMPARE(bus->findServo(1)->value(u"moving"), 1);
        QCOMPARE(bus->findServo(2)->value(u"present_speed"), 0); // nobody turns it
        QCOMPARE(bus->findServo(2)->value(u"moving"), 0);
        bus->advanceTo(2500 * kMs); // the sweep is over: the horn rests
        QVERIFY(!bus->hand().isSweeping(0));
        bus->advanceTo(2600 * kMs);
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 0);
        QCOMPARE(bus->findServo(1)->value(u"moving"), 0);
    }

    void aSweepFromHereTakesTheHornToItsStartGradually()
    {
        // The horn stands at 1500; the sweep 1000-2000 in 1 s turns 2000 step/s: a quarter of a
        // second on the way down to 1000, every reading on the way, then the sweep as asked.
        auto bus = armBus();
        QVERIFY(bus->hand().turnServo(0, 1500));
        bus->advanceTo(1000 * kMs);
        QVERIFY(bus->hand().sweepServoFromHere(0, 1000, 2000, 1.0, 1));
        int last = present(*bus, 1);
        QCOMPARE(last, 1500);
        for (qint64 ms = 1010; ms <= 1250; ms += 10) {
            bus->advanceTo(ms * kMs);
            const int now = present(*bus, 1);
            QVERIFY2(now <= last && last - now <= 25,
                     qPrintable(QStringLiteral("%1 to %2 at %3 ms").arg(last).arg(now).arg(ms)));
            last = now;
        }
        QCOMPARE(present(*bus, 1), 1000);
        bus->advanceTo(1500 * kMs);
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 2000); // sweeping out now
        bus->advanceTo(1750 * kMs);
        QCOMPARE(present(*bus, 1), 2000);
        bus->advanceTo(2600 * kMs);
        QCOMPARE(present(*bus, 1), 1000); // once, then rests at FROM
        QVERIFY(!bus->hand().isSweeping(0));
    }

    void turnsInQuickSuccessionReportTheGesturesSpeed()
    {
        // A slider dragged: each turn soon after the last, the encoder sees the speed between.
        auto bus = armBus();
        bus->advanceTo(1000 * kMs);
        QVERIFY(bus->hand().turn(1, 1000));
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 0); // no gesture yet
        bus->advanceTo(1100 * kMs);
        QVERIFY(bus->hand().turn(1, 1100)); // 100 steps in 0.1 s
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 1000);
        bus->advanceTo(1200 * kMs); // read while the gesture goes on
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 1000);
        QCOMPARE(bus->findServo(1)->value(u"moving"), 1);
        QCOMPARE(present(*bus, 1), 1100);
        bus->advanceTo(1500 * kMs); // the hand paused
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 0);
        QCOMPARE(bus->findServo(1)->value(u"moving"), 0);
        // Across the seam the short way: 4050 to 50 is 96 steps up.
        QVERIFY(bus->hand().turn(1, 4050));
        bus->advanceTo(1600 * kMs);
        QVERIFY(bus->hand().turn(1, 50));
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 960);
        // Torque on where it stands: the servo holds, the gesture is over.
        bus->findServo(1)->setValue(u"goal_position", 50);
        bus->findServo(1)->setValue(u"torque_enable", 1);
        bus->advanceTo(1700 * kMs);
        QCOMPARE(bus->findServo(1)->value(u"present_speed"), 0);
    }

    void anScsJointSweptByHandReportsItsSpeedToo()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(3, 100, 900, 4.0));
        bus->advanceTo(1000 * kMs);
        QCOMPARE(bus->findServo(3)->value(u"present_speed"), 400);
        QCOMPARE(bus->findServo(3)->value(u"moving"), 1);
    }

    void anOffsetChangedMidSweepMovesTheReadingsNotTheHorn()
    {
        // As on a real servo: the hand moves the horn; the reading is the horn less the offset.
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 1000, 3000, 2.0));
        bus->advanceTo(500 * kMs);
        QCOMPARE(present(*bus, 1), 2000);
        bus->findServo(1)->setValue(u"position_offset", 1500);
        bus->advanceTo(1000 * kMs); // the horn at 3000
        QCOMPARE(qRound(bus->findServo(1)->physicalPosition()), 3000);
        QCOMPARE(present(*bus, 1), 1500);
        bus->advanceTo(2000 * kMs); // back at 1000: across the seam in the new coordinates
        QCOMPARE(present(*bus, 1), 4096 - 500);
        bus->findServo(1)->setValue(u"position_offset", 0);
        QCOMPARE(present(*bus, 1), 1000);
    }

    void sweepStartsAtTheBusesCurrentTime()
    {
        auto bus = armBus();
        bus->advanceTo(10'000 * kMs);
        QVERIFY(bus->hand().sweep(1, 0, 400, 4.0));
        bus->advanceTo(11'000 * kMs);
        QCOMPARE(present(*bus, 1), 200);
    }

    void sweepUpFrom3900To200CrossesTheSeam()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 3900, 200, 4.0, 1, Hand::Way::Up));
        QList<int> seen;
        for (qint64 ms = 0; ms <= 2000; ms += 250) {
            bus->advanceTo(ms * kMs);
            seen.append(present(*bus, 1));
        }
        // 396 steps up in 2 s: 49.5 steps every 250 ms, over 4095 to 0.
        QCOMPARE(seen.first(), 3900);
        QCOMPARE(seen.last(), 200);
        QVERIFY(seen.contains(4048) || seen.contains(4049));
        QVERIFY(std::any_of(seen.cbegin(), seen.cend(), [](int p) { return p < 200 && p > 0; }));
        QVERIFY(
            std::none_of(seen.cbegin(), seen.cend(), [](int p) { return p > 200 && p < 3900; }));
    }

    void sweepDownCrossesTheSeamTheOtherWay()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 100, 3996, 2.0, 1, Hand::Way::Down));
        bus->advanceTo(500 * kMs); // 200 steps down in 1 s: halfway at the seam
        QCOMPARE(present(*bus, 1), 0);
        bus->advanceTo(1000 * kMs);
        QCOMPARE(present(*bus, 1), 3996);
    }

    void anScsServoHasNoSeamToCross()
    {
        auto bus = armBus();
        SimRefusal why;
        QVERIFY(!bus->hand().sweep(3, 900, 100, 1.0, 1, Hand::Way::Up, &why));
        QCOMPARE(why.code(), SimRefusal::Code::NoSeam);
    }

    void sweepRefusesBadTimesAndCycles()
    {
        auto bus = armBus();
        SimRefusal why;
        QVERIFY(!bus->hand().sweep(1, 0, 100, 0.0, 1, Hand::Way::Direct, &why));
        QCOMPARE(why.code(), SimRefusal::Code::SweepTooLong);
        QVERIFY(!bus->hand().sweep(1, 0, 100, 1.0, -1, Hand::Way::Direct, &why));
        QCOMPARE(why.code(), SimRefusal::Code::TooManyCycles);
    }

    void torqueComingOnMidSweepMakesTheHandLetGo()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(2, 1000, 2000, 1.0));
        bus->advanceTo(250 * kMs);
        QCOMPARE(present(*bus, 2), 1500);
        // The host holds the joint where it is, as a wizard does at its end.
        bus->findServo(2)->setValue(u"goal_position", 1500);
        bus->findServo(2)->setValue(u"torque_enable", 1);
        bus->advanceTo(300 * kMs);
        QVERIFY(!bus->hand().isSweeping(1));
        const QStringList notes = bus->hand().takeNotes();
        QCOMPARE(notes.size(), 1);
        QVERIFY2(notes.first().contains(QLatin1String("torque on")), qPrintable(notes.first()));
        QVERIFY(qAbs(present(*bus, 2) - 1500) <= 2); // the motor holds, the hand moves it no more
    }

    void stopLetsGoOfEverySweep()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 1000, 2000, 1.0));
        QVERIFY(bus->hand().sweep(2, 1000, 2000, 1.0));
        bus->advanceTo(250 * kMs);
        QCOMPARE(bus->hand().stop(), 2);
        bus->advanceTo(400 * kMs);
        QCOMPARE(present(*bus, 1), 1500);
        QCOMPARE(bus->hand().sweepCount(), 0);
    }

    void unplugEndsTheServosSweepAndKeepsTheOthers()
    {
        auto bus = armBus();
        QVERIFY(bus->hand().sweep(1, 1000, 2000, 1.0));
        QVERIFY(bus->hand().sweep(2, 1000, 2000, 1.0));
        QVERIFY(bus->unplug(0));
        QCOMPARE(bus->hand().sweepCount(), 1);
        QVERIFY(bus->hand().isSweeping(0)); // ID 2, now first
        bus->advanceTo(250 * kMs);
        QCOMPARE(present(*bus, 2), 1500);
    }

    void servosSharingAnIdAreTurnedByPlaceNotById()
    {
        auto bus = armBus();
        SimRefusal why;
        QVERIFY2(bus->setServoId(1, 1, &why), qPrintable(why.describe()));
        QCOMPARE(bus->servo(1).id(), quint8(1));
        QVERIFY(!bus->hand().turn(1, 100, &why));
        QCOMPARE(why.code(), SimRefusal::Code::SharedId);
        QCOMPARE(why.name(), QStringLiteral("#1, #2"));
        QVERIFY(bus->hand().turnServo(1, 100, &why));
        QCOMPARE(bus->servo(1).value(u"present_position"), 100);
    }

    void putAtIdSurvivesAPowerCycle()
    {
        auto bus = armBus();
        SimRefusal why;
        QVERIFY(bus->setServoId(2, 7, &why));
        bus->powerCycle();
        QCOMPARE(bus->servo(2).id(), quint8(7));
        QVERIFY(!bus->setServoId(2, 254, &why));
        QCOMPARE(why.code(), SimRefusal::Code::IdOutOfRange);
        QCOMPARE(why.servo(), 254);
        QVERIFY(!bus->setServoId(5, 1, &why));
        QCOMPARE(why.code(), SimRefusal::Code::NoSuchPlace);
        QCOMPARE(why.servo(), 6);
    }
};

QTEST_GUILESS_MAIN(TestHand)
#include "tst_hand.moc"
