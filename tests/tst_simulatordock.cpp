// Tests the Simulator dock offscreen: its servo table, turning a horn by hand (refused with
// torque on), sweeping, plugging and unplugging, putting a servo at an ID, power-cycling and
// the bench cases, each verified through the SimulatorThread.
#include "feetechbus.h"
#include "feetechworkspace.h"
#include "mainwindow.h"
#include "packetlogdock.h"
#include "simulatordock.h"

#include <QPushButton>
#include <QSet>
#include <QSettings>
#include <QSlider>
#include <QTableWidget>
#include <QtTest>

class TestSimulatorDock : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    std::unique_ptr<sim::SimulatorThread> m_simulator;
    std::unique_ptr<SimulatorDock> m_dock;

    template<typename Work>
    auto onBus(Work work)
    {
        return testsupport::onSimulatedBus(*m_simulator, work);
    }
    int positionOf(int index) { return testsupport::simulatedPosition(*m_simulator, index); }
    int servoCount()
    {
        return onBus([](sim::VirtualFeetechBus &bus) { return bus.servoCount(); });
    }

private slots:
    void init()
    {
        QSettings().clear(); // nothing remembered from an earlier case
        QVERIFY(m_dir.isValid());
        m_simulator = std::make_unique<sim::SimulatorThread>();
        QString error;
        QVERIFY2(m_simulator->start(testsupport::feetechBusOptions(
                                        m_dir, QStringLiteral("dock"),
                                        testsupport::servosAt(1000000, {u"STS3215", u"STS3215"})),
                                    &error),
                 qPrintable(error));
        m_dock = std::make_unique<SimulatorDock>();
        m_dock->setSimulator(m_simulator.get());
        m_dock->show();
    }
    void cleanup()
    {
        m_dock.reset();
        m_simulator.reset();
    }

    void theTableShowsEveryServoAndFollowsTheSimulator()
    {
        QTableWidget *table = m_dock->table();
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(1, 1)->text(), QStringLiteral("2"));
        QCOMPARE(table->item(1, 2)->text(), QStringLiteral("1000000"));
        QCOMPARE(table->item(1, 3)->text(), QStringLiteral("STS3215"));
        QCOMPARE(table->item(1, 5)->text(), QStringLiteral("off"));
        // Changed behind the dock's back: its timer shows it.
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.hand().turnServo(1, 1234);
            bus.servo(0).setValue(u"torque_enable", 1);
            return 0;
        });
        QTRY_COMPARE_WITH_TIMEOUT(table->item(1, 4)->text(), QStringLiteral("1234"), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(table->item(0, 5)->text(), QStringLiteral("on"), 5000);
    }

    void theSliderTurnsTheSelectedHorn()
    {
        m_dock->selectServo(1);
        m_dock->hornSlider()->setValue(3000); // as a drag would
        QCOMPARE(positionOf(1), 3000);
        QVERIFY(m_dock->turnSelected(500));
        QCOMPARE(positionOf(1), 500);
        QCOMPARE(m_dock->note(), QStringLiteral("Turned servo #2 to 500."));
        QCOMPARE(m_dock->hornSlider()->value(), 500);
    }

    void aServoWithTorqueOnCannotBeTurnedAndSaysWhy()
    {
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.servo(0).setValue(u"torque_enable", 1);
            return 0;
        });
        m_dock->refresh();
        m_dock->selectServo(0);
        QVERIFY(!m_dock->hornSlider()->isEnabled());
        QVERIFY2(m_dock->hornSlider()->toolTip().contains(QLatin1String("torque on")),
                 qPrintable(m_dock->hornSlider()->toolTip()));
        const int before = positionOf(0);
        QVERIFY(!m_dock->turnSelected(before + 700));
        QVERIFY2(m_dock->note().contains(QLatin1String("torque on")), qPrintable(m_dock->note()));
        QCOMPARE(positionOf(0), before);
    }

    void sweepMovesTheJointUntilLetGo()
    {
        m_dock->selectServo(0);
        QVERIFY(m_dock->sweepSelected(1000, 3000, 1.0, 0));
        QVERIFY(onBus([](sim::VirtualFeetechBus &bus) { return bus.hand().isSweeping(0); }));
        QTRY_VERIFY_WITH_TIMEOUT(positionOf(0) > 2000, 5000);
        auto *letGo = m_dock->findChild<QPushButton *>(QStringLiteral("letGoButton"));
        QVERIFY(letGo && letGo->isEnabled());
        letGo->click();
        QVERIFY(!onBus([](sim::VirtualFeetechBus &bus) { return bus.hand().isSweeping(0); }));
    }

    void everyModelIsOfferedOnce()
    {
        const QStringList models = SimulatorDock::simulatedModels();
        QCOMPARE(models.count(QStringLiteral("SM30BL")), 1);
        QCOMPARE(QSet<QString>(models.cbegin(), models.cend()).size(), models.size());
        QVERIFY(models.contains(QStringLiteral("SM30BL(FT)")));
    }

    void plugAndUnplugChangeTheBus()
    {
        QVERIFY(SimulatorDock::simulatedModels().contains(QStringLiteral("STS3215")));
        QVERIFY(SimulatorDock::simulatedModels().contains(QStringLiteral("SCS15")));
        QVERIFY(m_dock->plugFactoryNew(QStringLiteral("SCS15")));
        QCOMPARE(servoCount(), 3);
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return int(bus.servo(2).id()); }), 1);
        QCOMPARE(m_dock->table()->rowCount(), 3);
        QCOMPARE(m_dock->table()->item(2, 3)->text(), QStringLiteral("SCS15"));
        m_dock->selectServo(0);
        QVERIFY(m_dock->unplugSelected());
        QCOMPARE(servoCount(), 2);
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return int(bus.servo(0).id()); }), 2);
        QCOMPARE(m_dock->table()->rowCount(), 2);
    }

    void anUnpluggedServoIsPluggedBackInAsItWas()
    {
        auto *plugBack = m_dock->findChild<QPushButton *>(QStringLiteral("plugBackButton"));
        QVERIFY(plugBack);
        QVERIFY(!plugBack->isEnabled()); // nothing is off the bus
        // Servo 1, set up with settings of its own, taken off the bus.
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) {
                     bus.servo(0).storeValue(u"max_temperature", 66);
                     return int(bus.servo(0).id());
                 }),
                 1);
        m_dock->selectServo(0);
        QVERIFY(m_dock->unplugSelected());
        QTRY_VERIFY(plugBack->isEnabled());
        QVERIFY2(plugBack->toolTip().contains(QLatin1String("ID 1")),
                 qPrintable(plugBack->toolTip()));
        QVERIFY(m_dock->plugBackIn());
        QCOMPARE(servoCount(), 2);
        // Back last in the chain, at its ID with its settings: not a factory-new servo.
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return int(bus.servo(1).id()); }), 1);
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) {
                     return int(bus.servo(1).value(u"max_temperature"));
                 }),
                 66);
        QTRY_VERIFY(!plugBack->isEnabled());
    }

    void putAtIdLetsTwoServosShareOne()
    {
        m_dock->selectServo(1);
        QVERIFY(m_dock->putSelectedAtId(1));
        QCOMPARE(m_dock->note(), QStringLiteral("Servo #2 is now at ID 1."));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.indexesOf(1).size(); }), 2);
        QVERIFY(m_dock->powerCycle());
        // In the EEPROM: still there after the power cycle.
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return int(bus.servo(1).id()); }), 1);
        QCOMPARE(m_dock->table()->item(1, 1)->text(), QStringLiteral("1"));
        QVERIFY(!m_dock->putSelectedAtId(254));
        QVERIFY2(m_dock->note().contains(QLatin1String("out of range")),
                 qPrintable(m_dock->note()));
    }

    void everyBenchCaseChangesTheBusAndTheTableSaysSo()
    {
        using Case = BenchCases::Case;
        m_dock->selectServo(1);
        QVERIFY(m_dock->playBenchCase(Case::CutPower));
        QVERIFY(!onBus([](sim::VirtualFeetechBus &bus) { return bus.isPowered(1); }));
        QVERIFY2(m_dock->table()->item(1, 6)->text().contains(QLatin1String("no power")),
                 qPrintable(m_dock->table()->item(1, 6)->text()));
        QVERIFY(m_dock->playBenchCase(Case::RestorePower));
        QVERIFY(onBus([](sim::VirtualFeetechBus &bus) { return bus.isPowered(1); }));

        m_dock->selectServo(0);
        QVERIFY(m_dock->playBenchCase(Case::BreakChainAfter));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.chainBreakAfter(); }), 0);
        QVERIFY(m_dock->playBenchCase(Case::MendChain));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.chainBreakAfter(); }), -1);

        m_dock->selectServo(0);
        QVERIFY(m_dock->playBenchCase(Case::BlockHorn));
        QVERIFY(m_dock->playBenchCase(Case::Heat));
        QVERIFY(m_dock->playBenchCase(Case::LatchOverload));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) {
                     const sim::VirtualFeetechServo &servo = bus.servo(0);
                     return std::make_tuple(servo.externalLoad(), servo.temperatureRise(),
                                            servo.overloadLatched());
                 }),
                 std::make_tuple(1000, BenchCases::kHeatPerSecond, true));
        const QString bench = m_dock->table()->item(0, 6)->text();
        QVERIFY2(bench.contains(QLatin1String("horn blocked"))
                     && bench.contains(QLatin1String("overload latched"))
                     && bench.contains(QLatin1String("heating")),
                 qPrintable(bench));
        QVERIFY(m_dock->playBenchCase(Case::FreeHorn));
        QVERIFY(m_dock->playBenchCase(Case::StopHeating));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) {
                     return std::make_pair(bus.servo(0).externalLoad(),
                                           bus.servo(0).temperatureRise());
                 }),
                 std::make_pair(0, 0.0));

        QVERIFY(m_dock->playBenchCase(Case::SupplyTooHigh));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.servo(1).supplyVoltage(); }),
                 BenchCases::kHighSupplyVolts);
        QVERIFY(m_dock->playBenchCase(Case::SupplyTooLow));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.servo(1).supplyVoltage(); }),
                 BenchCases::kLowSupplyVolts);
        QVERIFY(m_dock->playBenchCase(Case::SupplyNormal));
        QCOMPARE(onBus([](sim::VirtualFeetechBus &bus) { return bus.servo(1).supplyVoltage(); }),
                 sim::VirtualFeetechServo::kDefaultSupplyVolts);
    }

    void aServoCaseNeedsASelectedServo()
    {
        m_dock->table()->clearSelection();
        QVERIFY(!m_dock->playBenchCase(BenchCases::Case::CutPower));
        QVERIFY2(m_dock->note().contains(QLatin1String("Select a servo")),
                 qPrintable(m_dock->note()));
    }

    void withoutASimulatorTheDockIsEmptyAndSaysSo()
    {
        m_dock->setSimulator(nullptr);
        QCOMPARE(m_dock->table()->rowCount(), 0);
        QVERIFY(!m_dock->hornSlider()->isEnabled());
        QVERIFY(!m_dock->powerCycle());
        QVERIFY2(m_dock->note().contains(QLatin1String("No simulated Feetech bus")),
                 qPrintable(m_dock->note()));
    }

    void theArmDemoScansSixJointsAndShowsTheDockBesideThePacketLog()
    {
        MainWindow window;
        window.resize(1366, 768);
        window.show();
        QVERIFY(!window.simulatorDock());
        window.startArmDemo();
        QVERIFY(window.simulatorDock());
        QVERIFY(window.tabifiedDockWidgets(window.packetLog()).contains(window.simulatorDock()));
        QCOMPARE(window.simulatorDock()->table()->rowCount(), 6);
        QTRY_COMPARE_WITH_TIMEOUT(window.feetechClient()->servos()->idsInUse(),
                                  (QVector<int> {1, 2, 3, 4, 5, 6}), 20000);
        // The dock scrolls its controls rather than make the window taller than what a 1366x768
        // screen leaves under a desktop's panel and a title bar (some 70 pixels).
        QVERIFY2(window.minimumSizeHint().height() <= 700,
                 qPrintable(QString::number(window.minimumSizeHint().height())));
        // The hand turns the arm's shoulder lift; the dock shows it.
        window.simulatorDock()->selectServo(1);
        QVERIFY(window.simulatorDock()->turnSelected(2100));
        QCOMPARE(window.simulatorDock()->table()->item(1, 4)->text(), QStringLiteral("2100"));
    }

    void thePtkDemoHidesTheSimulatorDock()
    {
        MainWindow window;
        window.show();
        window.startArmDemo();
        QTRY_VERIFY_WITH_TIMEOUT(window.feetechClient()->link()->isConnected(), 10000);
        QVERIFY(window.simulatorDock()->isVisible());
        window.feetechClient()->disconnectFrom();
        QTRY_COMPARE_WITH_TIMEOUT(window.feetechClient()->link()->status().state,
                                  seriallink::ConnectionState::Disconnected, 10000);
        window.startDemo();
        QVERIFY(!window.simulatorDock()->isVisible());
        QVERIFY(!window.simulatorDock()->toggleViewAction()->isEnabled());
        QVERIFY(!window.simulatorDock()->simulator());
    }
};

QTEST_MAIN(TestSimulatorDock)
#include "tst_simulatordock.moc"
