// Tests servosim's argument parsing: --hand, --robot and --allow-shared-ids, their bad values,
// and the bus a --robot or shared IDs make.
#include "simulator.h"

#include <QTemporaryDir>
#include <QtTest>

namespace {

std::optional<sim::SimulatorOptions> parse(QStringList extra, QString *error)
{
    QStringList arguments {QStringLiteral("feetech"), QStringLiteral("--link"),
                           QStringLiteral("/tmp/unused")};
    return sim::parseSimulatorArguments(arguments + extra, error);
}

} // namespace

class TestSimOptions : public QObject
{
    Q_OBJECT

private slots:
    void handTakesIdFromToSecondsAndOptionalCyclesAndWay()
    {
        QString error;
        const auto options = parse({QStringLiteral("--servo"), QStringLiteral("5:STS3215"),
                                    QStringLiteral("--hand"), QStringLiteral("5:3900:200:2.5:3:up"),
                                    QStringLiteral("--hand"), QStringLiteral("5:100:200:1")},
                                   &error);
        QVERIFY2(options, qPrintable(error));
        QCOMPARE(options->sweeps.size(), 2);
        const sim::HandSweep first = options->sweeps.at(0);
        QCOMPARE(first.id, quint8(5));
        QCOMPARE(first.from, 3900);
        QCOMPARE(first.to, 200);
        QCOMPARE(first.seconds, 2.5);
        QCOMPARE(first.cycles, 3);
        QCOMPARE(first.way, sim::Hand::Way::Up);
        QCOMPARE(options->sweeps.at(1).cycles, 0); // until released
        QCOMPARE(options->sweeps.at(1).way, sim::Hand::Way::Direct);
    }

    void robotPutsTheArmsJointsFirst()
    {
        QString error;
        const auto options = parse({QStringLiteral("--servo"), QStringLiteral("7:SCS15"),
                                    QStringLiteral("--robot"), QStringLiteral("SO101")},
                                   &error);
        QVERIFY2(options, qPrintable(error));
        QVERIFY(options->robot);
        QCOMPARE(options->robot->name, QStringLiteral("SO-101 follower arm"));
        QCOMPARE(options->servos.size(), 7);
        for (int i = 0; i < 6; ++i) {
            QCOMPARE(options->servos.at(i).id, quint8(i + 1));
            QCOMPARE(options->servos.at(i).model, QStringLiteral("STS3215"));
            QCOMPARE(options->servos.at(i).baud, 1000000);
        }
        QCOMPARE(options->servos.at(6).model, QStringLiteral("SCS15"));
        QVERIFY(parse({QStringLiteral("--robot"), QStringLiteral("so100-leader")}, &error));
    }

    void badValuesAreRefusedWithAClearMessage_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("expected");
        const QString servo = QStringLiteral("--servo");
        const QString one = QStringLiteral("1:STS3215");
        const QString hand = QStringLiteral("--hand");
        QTest::newRow("hand too short") << QStringList {servo, one, hand, QStringLiteral("1:0:100")}
                                        << QStringLiteral("expected ID FROM TO SECONDS");
        QTest::newRow("hand bad id") << QStringList {servo, one, hand, QStringLiteral("x:0:100:1")}
                                     << QStringLiteral("the ID must be 0 to 253");
        QTest::newRow("hand bad position")
            << QStringList {servo, one, hand, QStringLiteral("1:0:4096:1")}
            << QStringLiteral("FROM and TO must be positions from 0 to 4095");
        QTest::newRow("hand zero seconds")
            << QStringList {servo, one, hand, QStringLiteral("1:0:100:0")}
            << QStringLiteral("SECONDS must be a number above 0");
        QTest::newRow("hand bad cycles")
            << QStringList {servo, one, hand, QStringLiteral("1:0:100:1:many")}
            << QStringLiteral("CYCLES must be a whole number");
        QTest::newRow("hand bad way")
            << QStringList {servo, one, hand, QStringLiteral("1:0:100:1:2:left")}
            << QStringLiteral("expected ID FROM TO SECONDS");
        QTest::newRow("unknown robot")
            << QStringList {QStringLiteral("--robot"), QStringLiteral("so102")}
            << QStringLiteral("unknown robot \"so102\": use so101, so100");
        QTest::newRow("two robots")
            << QStringList {QStringLiteral("--robot"), QStringLiteral("so101"),
                            QStringLiteral("--robot"), QStringLiteral("so100")}
            << QStringLiteral("--robot may be given once");
        QTest::newRow("robot needs a value")
            << QStringList {QStringLiteral("--robot")} << QStringLiteral("--robot needs a value");
    }
    void badValuesAreRefusedWithAClearMessage()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, expected);
        QString error;
        QVERIFY(!parse(arguments, &error));
        QVERIFY2(error.contains(expected), qPrintable(error));
    }

    void badOptionValuesSayWhyByCode()
    {
        using Code = sim::OptionError::Code;
        sim::OptionError why;
        const auto faultCode = [&why](const char *text) {
            return sim::FaultSettings::parse(QString::fromLatin1(text), &why) ? Code::None
                                                                              : why.code();
        };
        QCOMPARE(faultCode("drop"), Code::FaultNotNameValue);
        QCOMPARE(faultCode("drop=x"), Code::FaultNotANumber);
        QCOMPARE(faultCode("delay=70000"), Code::FaultDelayOutOfRange);
        QCOMPARE(faultCode("drop=2"), Code::FaultNotAProbability);
        QCOMPARE(faultCode("spill=0.1"), Code::UnknownFault);
        QCOMPARE(why.text(), QStringLiteral("spill"));
        QCOMPARE(faultCode("drop=0.5,delay=3"), Code::None);

        const auto specCode = [&why](const char *text) {
            return sim::parseServoSpec(QString::fromLatin1(text), QStringLiteral("--servo"), &why)
                ? Code::None
                : why.code();
        };
        QCOMPARE(specCode("x"), Code::NotAServoSpec);
        QCOMPARE(specCode("254:STS3215"), Code::ServoIdOverMax);
        QCOMPARE(why.value(), 254);
        QCOMPARE(specCode("1:"), Code::ServoWithoutModel);
        QCOMPARE(specCode("1:STS3215@0"), Code::ServoBadBaud);
        QCOMPARE(why.source(), QStringLiteral("--servo"));
        QCOMPARE(specCode("1:STS3215@500000"), Code::None);

        const auto sweepCode = [&why](const char *fields) {
            return sim::parseHandSweep(QString::fromLatin1(fields).split(u':'),
                                       QStringLiteral("--hand"), &why)
                ? Code::None
                : why.code();
        };
        QCOMPARE(sweepCode("1:0:100"), Code::SweepFields);
        QCOMPARE(sweepCode("x:0:100:1"), Code::SweepBadId);
        QCOMPARE(sweepCode("1:0:4096:1"), Code::SweepBadPositions);
        QCOMPARE(sweepCode("1:0:100:0"), Code::SweepBadSeconds);
        QCOMPARE(sweepCode("1:0:100:1:many"), Code::SweepBadCycles);
        QCOMPARE(sweepCode("1:0:100:1:2:up"), Code::None);

        QVERIFY(!sim::simulatedRobot(QStringLiteral("so102"), &why));
        QCOMPARE(why.code(), Code::UnknownRobot);
        QVERIFY(sim::simulatedRobot(QStringLiteral("SO101"), &why));
    }

    void feetechOnlyOptionsAreRefusedForPtk_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::newRow("allow shared ids") << QStringList {QStringLiteral("--allow-shared-ids")};
        QTest::newRow("robot") << QStringList {QStringLiteral("--robot"), QStringLiteral("so101")};
        QTest::newRow("hand") << QStringList {QStringLiteral("--hand"), QStringLiteral("1:0:1:1")};
    }
    void feetechOnlyOptionsAreRefusedForPtk()
    {
        QFETCH(QStringList, arguments);
        QString error;
        QVERIFY(!sim::parseSimulatorArguments(
            QStringList {QStringLiteral("ptk"), QStringLiteral("--link"), QStringLiteral("/tmp/x")}
                + arguments,
            &error));
        QVERIFY2(error.contains(QLatin1String("is for a Feetech bus")), qPrintable(error));
    }

    void aRepeatedIdNeedsAllowSharedIds()
    {
        const QStringList twins {QStringLiteral("--servo"), QStringLiteral("1:STS3215"),
                                 QStringLiteral("--servo"), QStringLiteral("1:STS3215")};
        QString error;
        auto options = parse(twins, &error);
        QVERIFY2(options, qPrintable(error));
        QVERIFY(!sim::Simulator::create(*options, &error));
        QVERIFY2(error.contains(QLatin1String("two servos have ID 1 at 1000000 bps"))
                     && error.contains(QLatin1String("--allow-shared-ids")),
                 qPrintable(error));

        options = parse(twins + QStringList {QStringLiteral("--allow-shared-ids")}, &error);
        QVERIFY2(options && options->allowSharedIds, qPrintable(error));
        const auto simulator = sim::Simulator::create(*options, &error);
        QVERIFY2(simulator, qPrintable(error));
        QCOMPARE(simulator->feetechBus()->indexesOf(1).size(), 2);
    }

    void anUnknownModelGetsNoSharedIdsHint()
    {
        QString error;
        const auto options = parse({QStringLiteral("--servo"), QStringLiteral("1:XYZ99")}, &error);
        QVERIFY(options);
        QVERIFY(!sim::Simulator::create(*options, &error));
        QVERIFY2(!error.contains(QLatin1String("--allow-shared-ids")), qPrintable(error));
    }

    void robotBusIsSetUpWithTheTemplatesSettingsAndHornsAtRest()
    {
        QString error;
        const auto options = parse({QStringLiteral("--robot"), QStringLiteral("so101")}, &error);
        QVERIFY2(options, qPrintable(error));
        const auto simulator = sim::Simulator::create(*options, &error);
        QVERIFY2(simulator, qPrintable(error));
        sim::VirtualFeetechBus &bus = *simulator->feetechBus();
        QCOMPARE(bus.servoCount(), 6);
        for (int i = 0; i < 6; ++i) {
            const sim::VirtualFeetechServo &joint = bus.servo(i);
            QCOMPARE(joint.value(u"p_gain"), 16);
            QCOMPARE(joint.value(u"return_delay"), 0);
            QCOMPARE(joint.value(u"torque_enable"), 0);
        }
        QCOMPARE(bus.servo(5).value(u"max_torque"), 500); // the gripper's own setting
        QCOMPARE(bus.servo(1).value(u"present_position"), 890); // shoulder lift folded down
        // In EEPROM, as after a set-up: a power cycle keeps them.
        bus.powerCycle();
        QCOMPARE(bus.servo(5).value(u"max_torque"), 500);
        QCOMPARE(bus.servo(0).value(u"p_gain"), 16);
    }

    void handSweepOfAnAbsentIdFailsAtCreate()
    {
        QString error;
        const auto options = parse({QStringLiteral("--robot"), QStringLiteral("so101"),
                                    QStringLiteral("--hand"), QStringLiteral("9:0:100:1")},
                                   &error);
        QVERIFY2(options, qPrintable(error));
        QVERIFY(!sim::Simulator::create(*options, &error));
        QVERIFY2(error.contains(QLatin1String("--hand for ID 9: no servo has ID 9")),
                 qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestSimOptions)
#include "tst_simoptions.moc"
