// servoctl feetech recover against the pty simulator: a tripped servo recovered by torque off
// and on, a latched one given the power-cycle steps and checked after the power cycle.
#include "feetechbus.h"
#include "servoctlrun.h"

#include <QtTest>

using testsupport::runServoctl;

namespace {

constexpr qint32 k1M = 1000000;

} // namespace

class TestServoctlGuard : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    testsupport::ServoctlResult run(const QString &line) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath(),
                                        QStringLiteral("feetech")}
                           + line.split(u' ', Qt::SkipEmptyParts));
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
    }

    void cleanup() { m_simulator.reset(); }

    void aServoThatIsNotTrippedIsRecoveredHoldingWhereItStands()
    {
        const auto result = run(QStringLiteral("recover --id 1"));
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        QVERIFY2(result.out.contains(QLatin1String("recovered")), qPrintable(result.out));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        QCOMPARE(simulatorValue(1, u"goal_position"), simulatorValue(1, u"present_position"));
    }

    void aLatchedOverloadPrintsThePowerCycleStepsAndFails()
    {
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setOverloadLatched(true); }));
        const auto stuck = run(QStringLiteral("recover --id 1"));
        QCOMPARE(stuck.exitCode, 1);
        QVERIFY2(stuck.err.contains(QLatin1String("power supply off")), qPrintable(stuck.err));
        QVERIFY2(stuck.err.contains(QLatin1String("recover --id 1 --check")),
                 qPrintable(stuck.err));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->setPowered(0, false);
            simulator.feetechBus()->setPowered(0, true);
        });
        const auto checked = run(QStringLiteral("recover --id 1 --check"));
        QVERIFY2(checked.exitCode == 0, qPrintable(checked.err));
        QVERIFY2(checked.out.contains(QLatin1String("clear")), qPrintable(checked.out));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0); // a check switches nothing on
    }

    void checkIsRefusedByOtherCommands()
    {
        const auto result = run(QStringLiteral("reboot --id 1 --check"));
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.err.contains(QLatin1String("--check")));
    }
};

QTEST_GUILESS_MAIN(TestServoctlGuard)
#include "tst_servoctlguard.moc"
