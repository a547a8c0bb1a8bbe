// Tests servosim's standard-input commands in-process: every command, its replies and errors,
// run in the simulator's thread through SimulatorThread::call.
#include "feetechbus.h"
#include "simcommands.h"

#include <QtTest>

namespace {

bool isOk(const QString &reply)
{
    return reply.startsWith(QLatin1String("ok "));
}

} // namespace

class TestSimCommands : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::unique_ptr<sim::SimulatorThread> m_simulator;

    QString run(const QString &line)
    {
        QString reply;
        m_simulator->call(
            [&](sim::Simulator &simulator) { reply = sim::runSimulatorCommand(line, simulator); });
        return reply;
    }
    template<typename Work>
    auto onBus(Work work)
    {
        return testsupport::onSimulatedBus(*m_simulator, work);
    }
    int positionOf(int index) { return testsupport::simulatedPosition(*m_simulator, index); }

private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        // ID 1 and 2 STS3215, ID 3 an SCS15, all at 1 Mbps.
        m_simulator = std::make_unique<sim::SimulatorThread>();
        QString error;
        QVERIFY2(m_simulator->start(
                     testsupport::feetechBusOptions(
                         m_dir, QStringLiteral("bus"),
                         testsupport::servosAt(1000000, {u"STS3215", u"STS3215", u"SCS15"})),
                     &error),
                 qPrintable(error));
    }
    void cleanup() { m_simulator.reset(); }

    void listShowsEveryServosPlaceIdRateModelPositionAndTorque()
    {
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.servo(1).setValue(u"torque_enable", 1);
            return 0;
        });
        const QString reply = run(QStringLiteral("list"));
        QVERIFY2(isOk(reply), qPrintable(reply));
        QVERIFY2(reply.contains(QLatin1String("#1 id=1 baud=1000000 model=STS3215 position=")),
                 qPrintable(reply));
        QVERIFY2(reply.contains(QLatin1String("#3 id=3 baud=1000000 model=SCS15")),
                 qPrintable(reply));
        QCOMPARE(reply.count(QLatin1String("torque=on")), 1);
        QCOMPARE(reply.count(QLatin1String("torque=off")), 2);
    }

    void turnByIdOrPlaceMovesTheHorn()
    {
        QCOMPARE(run(QStringLiteral("turn 1 1000")), QStringLiteral("ok turned #1 (ID 1) to 1000"));
        QCOMPARE(positionOf(0), 1000);
        QVERIFY(isOk(run(QStringLiteral("turn #3 700"))));
        QCOMPARE(positionOf(2), 700);
        QVERIFY(run(QStringLiteral("list")).contains(QLatin1String("position=1000")));
    }

    void turnOfAJointWithTorqueOnIsRefused()
    {
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.servo(0).setValue(u"torque_enable", 1);
            return 0;
        });
        const QString reply = run(QStringLiteral("turn 1 1000"));
        QVERIFY2(reply.startsWith(QLatin1String("error "))
                     && reply.contains(QLatin1String("torque on")),
                 qPrintable(reply));
    }

    void sweepRunsUntilReleased()
    {
        const QString reply = run(QStringLiteral("sweep 2 3900 200 2 0 up"));
        QVERIFY2(isOk(reply) && reply.contains(QLatin1String("until released")), qPrintable(reply));
        QVERIFY(run(QStringLiteral("list")).contains(QLatin1String("hand=sweeping")));
        // The horn moves with the simulator's clock, over the seam and never through the middle.
        QTRY_VERIFY_WITH_TIMEOUT(positionOf(1) < 200, 5000);
        QCOMPARE(run(QStringLiteral("release")),
                 QStringLiteral("ok the hand let go of 1 sweep(s)"));
        QVERIFY(!run(QStringLiteral("list")).contains(QLatin1String("hand=sweeping")));
    }

    void sweepOfAnScsServoCannotCrossASeam()
    {
        const QString reply = run(QStringLiteral("sweep 3 900 100 1 1 up"));
        QVERIFY2(reply.startsWith(QLatin1String("error ")) && reply.contains(QLatin1String("SCS")),
                 qPrintable(reply));
    }

    void plugAddsAFactoryNewServoAtTheEnd()
    {
        QCOMPARE(run(QStringLiteral("plug 1:STS3215")),
                 QStringLiteral("ok plugged #4 (ID 1): STS3215 at 1000000 bps"));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.servoCount(); }), 4);
        // Two at ID 1 now: by ID is ambiguous, by place is not.
        const QString ambiguous = run(QStringLiteral("turn 1 100"));
        QVERIFY2(ambiguous.contains(QLatin1String("#1, #4 share ID 1")), qPrintable(ambiguous));
        QVERIFY(isOk(run(QStringLiteral("turn #4 100"))));
        QCOMPARE(run(QStringLiteral("unplug #4")), QStringLiteral("ok unplugged #4 (ID 1)"));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.servoCount(); }), 3);
    }

    void unplugByIdRemovesThatServo()
    {
        QCOMPARE(run(QStringLiteral("unplug 2")), QStringLiteral("ok unplugged #2 (ID 2)"));
        QVERIFY(!run(QStringLiteral("list")).contains(QLatin1String("id=2 ")));
    }

    void setIdPutsAServoAtAnotherIdThatSurvivesAPowerCycle()
    {
        QCOMPARE(run(QStringLiteral("set-id #3 1")), QStringLiteral("ok servo #3 is now at ID 1"));
        QCOMPARE(run(QStringLiteral("power-cycle")), QStringLiteral("ok power-cycled"));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return int(bus.servo(2).id()); }), 1);
    }

    void powerCycleTurnsTheTorqueOff()
    {
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.servo(0).setValue(u"torque_enable", 1);
            return 0;
        });
        QVERIFY(isOk(run(QStringLiteral("power-cycle"))));
        QCOMPARE(run(QStringLiteral("list")).count(QLatin1String("torque=off")), 3);
    }

    void benchCasesChangeTheBusAndShowInList()
    {
        QVERIFY(isOk(run(QStringLiteral("power 2 off"))));
        QVERIFY(isOk(run(QStringLiteral("block #1"))));
        QVERIFY(isOk(run(QStringLiteral("latch 3"))));
        QVERIFY(isOk(run(QStringLiteral("heat 1 0.5"))));
        QVERIFY(isOk(run(QStringLiteral("supply 12.5"))));
        const QString list = run(QStringLiteral("list"));
        QCOMPARE(list.count(QLatin1String("power=off")), 1);
        QCOMPARE(list.count(QLatin1String("horn=blocked")), 1);
        QCOMPARE(list.count(QLatin1String("overload=latched")), 1);
        QCOMPARE(list.count(QLatin1String("heat=0.5")), 1);
        QCOMPARE(list.count(QLatin1String("supply=12.5")), 3);
        const auto state = onBus([](sim::VirtualFeetechBus &bus) {
            return std::make_tuple(bus.isPowered(1), bus.servo(0).externalLoad(),
                                   bus.servo(2).overloadLatched(), bus.servo(0).temperatureRise());
        });
        QCOMPARE(state, std::make_tuple(false, 1000, true, 0.5));
        QVERIFY(isOk(run(QStringLiteral("power 2 on"))));
        QVERIFY(isOk(run(QStringLiteral("unblock 1"))));
        QVERIFY(isOk(run(QStringLiteral("temperature 1 70"))));
        const QString after = run(QStringLiteral("list"));
        QVERIFY2(!after.contains(QLatin1String("power=off")), qPrintable(after));
        QVERIFY2(!after.contains(QLatin1String("horn=blocked")), qPrintable(after));
        QVERIFY2(after.contains(QLatin1String("temperature=70")), qPrintable(after));
    }

    void breakChainSilencesTheServosAfterItUntilNone()
    {
        QVERIFY(isOk(run(QStringLiteral("break-chain 1"))));
        QCOMPARE(run(QStringLiteral("list")).count(QLatin1String("power=off")), 2);
        QVERIFY(isOk(run(QStringLiteral("break-chain none"))));
        QCOMPARE(run(QStringLiteral("list")).count(QLatin1String("power=off")), 0);
    }

    void helpNamesEveryCommand()
    {
        const QString reply = run(QStringLiteral("help"));
        QVERIFY(isOk(reply));
        for (const char *command :
             {"turn", "sweep", "release", "plug", "unplug", "set-id", "list", "power-cycle",
              "power", "break-chain", "supply", "heat", "temperature", "block", "unblock", "latch"})
            QVERIFY2(reply.contains(QLatin1String(command)), command);
    }

    void aBlankLineGetsNoReply() { QCOMPARE(run(QStringLiteral("   ")), QString()); }

    void badCommandsGetAClearError_data()
    {
        QTest::addColumn<QString>("line");
        QTest::addColumn<QString>("expected");
        const auto row = [](const char *line, const char *expected) {
            QTest::newRow(line) << QString::fromLatin1(line) << QString::fromUtf8(expected);
        };
        row("bogus", "unknown command \"bogus\": try help");
        row("turn", "turn takes: turn SERVO POS");
        row("turn 1", "turn takes: turn SERVO POS");
        row("turn x 5", "\"x\" names no servo");
        row("turn 1 5000", "\"5000\" is not a position from 0 to 4095");
        row("turn 3 1500", "turns from 0 to 1023");
        row("turn #9 5", "there is no servo #9: the bus has #1 to #3");
        row("turn 9 5", "no servo has ID 9");
        row("sweep 1 0 100", "sweep takes: sweep SERVO FROM TO SECONDS");
        row("sweep 1 0 100 0", "SECONDS must be a number above 0");
        row("sweep 1 0 100 1 -2", "CYCLES must be a whole number");
        row("sweep 1 0 100 1 2 sideways", "expected ID FROM TO SECONDS [CYCLES] [up|down]");
        row("sweep 1 0 5000 1", "FROM and TO must be positions from 0 to 4095");
        row("plug", "plug takes: plug ID:MODEL[@BAUD]");
        row("plug 1", "plug \"1\" is not ID:MODEL[@BAUD]");
        row("plug 1:XYZ99", "unknown model \"XYZ99\"");
        row("plug 1:STS3215@12345", "is not a Feetech baud rate");
        row("unplug", "unplug takes: unplug SERVO");
        row("unplug 99", "no servo has ID 99");
        row("set-id 1", "set-id takes: set-id SERVO ID");
        row("set-id 1 254", "\"254\" is not an ID from 0 to 253");
        row("list all", "list takes: list");
        row("release now", "release takes: release");
        row("power-cycle twice", "power-cycle takes: power-cycle");
        row("power 1", "power takes: power SERVO on|off");
        row("power 1 maybe", "power takes: power SERVO on|off");
        row("power 9 off", "no servo has ID 9");
        row("break-chain", "break-chain takes: break-chain SERVO|none");
        row("supply", "supply takes: supply VOLTS");
        row("supply 99", "\"99\" is not a supply from 0 to 30 V");
        row("supply nan", "\"nan\" is not a supply from 0 to 30 V");
        row("heat 1", "heat takes: heat SERVO C_PER_S");
        row("heat 1 50", "\"50\" is not a rate from -10 to 10 °C/s");
        row("temperature 1 500", "\"500\" is not a temperature from -20 to 120 °C");
        row("block 1 0.5", "\"0.5\" is not a load from -1000 to 1000 ‰");
        row("block 1 2 3", "block takes: block SERVO [PERMILLE]");
        row("unblock", "unblock takes: unblock SERVO");
        row("latch 1 2", "latch takes: latch SERVO");
    }
    void badCommandsGetAClearError()
    {
        QFETCH(QString, line);
        QFETCH(QString, expected);
        const QString reply = run(line);
        QVERIFY2(reply.startsWith(QLatin1String("error ")), qPrintable(reply));
        QVERIFY2(reply.contains(expected), qPrintable(reply));
    }

    void aPtkSimulatorAnswersOnlyPowerCycleAndHelp()
    {
        m_simulator = std::make_unique<sim::SimulatorThread>();
        sim::SimulatorOptions options;
        options.linkPath = m_dir.filePath(QStringLiteral("ptk"));
        QString error;
        QVERIFY2(m_simulator->start(options, &error), qPrintable(error));
        QVERIFY(isOk(run(QStringLiteral("help"))));
        QVERIFY(isOk(run(QStringLiteral("power-cycle"))));
        const QString reply = run(QStringLiteral("turn 1 100"));
        QVERIFY2(reply.contains(QLatin1String("is for a Feetech bus")), qPrintable(reply));
    }
};

QTEST_GUILESS_MAIN(TestSimCommands)
#include "tst_simcommands.moc"
