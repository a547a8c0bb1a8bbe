// Tests of each Feetech guided flow on its own, against the simulated servos' register state.
#include "feetechbus.h"

#include "guidedflows.h"

#include <QtTest>

using feetech::GuidedFlows;
using feetech::Instruction;
using feetech::OperationResult;
using feetech::ServoInfo;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;
constexpr qint32 k500k = 500000;

// STS3215 as 1 and 2 and an SCS15 as 3 at 1 Mbps; an SMS as 4 and an STS3215 as 1 at 115200.
QVector<sim::FeetechServoSpec> testServos()
{
    auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS15"});
    servos.append({4, QStringLiteral("SMS"), k115k});
    servos.append({1, QStringLiteral("STS3215"), k115k});
    return servos;
}

// The parameters of a WRITE of one byte: address, value.
QByteArray oneByteWrite(int address, int value)
{
    return QByteArray(1, char(address)) + char(value);
}

} // namespace

class TestGuidedFlows : public testsupport::FeetechLinkTest
{
    Q_OBJECT

private:
    std::unique_ptr<GuidedFlows> m_flows;

    void startBus()
    {
        QString error;
        QVERIFY2(startLink(busOptions(testServos()), &error), qPrintable(error));
        m_flows = std::make_unique<GuidedFlows>(*m_bus);
    }

    ServoInfo servo(quint8 id, qint32 baud)
    {
        const auto info = identify(id, baud);
        if (!info)
            qWarning("servo %d at %d does not answer", id, baud);
        return info.value_or(ServoInfo {});
    }

    // Starts a flow with `start` and waits up to 20 s for its result; an empty result when
    // none came.
    OperationResult run(const std::function<void(GuidedFlows::Finish)> &start)
    {
        auto result = std::make_shared<std::optional<OperationResult>>();
        start([result](const OperationResult &r) { *result = r; });
        if (!QTest::qWaitFor([&] { return result->has_value(); }, 20000))
            qWarning("the flow did not end within 20 s");
        return result->value_or(OperationResult {});
    }

    // Register `key` of the servo with `id` listening at `baud`; -1 when there is none.
    qint32 valueAt(quint8 id, qint32 baud, QStringView key)
    {
        qint32 value = -1;
        withServo(id, baud, [&](sim::VirtualFeetechServo &servo) { value = servo.value(key); });
        return value;
    }

    void powerCycle()
    {
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
    }

    int writesReceived()
    {
        return int(testsupport::feetechRequestsReceived(logPath(), Instruction::Write).size());
    }

private slots:
    void init()
    {
        m_timing.rebootPollInterval = std::chrono::milliseconds(20);
        startBus();
    }

    void cleanup()
    {
        m_flows.reset();
        stopLink();
    }

    void changeIdMovesTheServoAndLeavesItsEepromLocked()
    {
        const OperationResult result =
            run([&](auto finish) { m_flows->changeId(servo(2, k1M), 7, {}, finish); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.operation, feetech::Operation::ChangeId);
        QCOMPARE(result.servo.id, quint8(7));
        QCOMPARE(result.servo.baud, k1M);
        QCOMPARE(valueAt(2, k1M, u"id"), -1);
        QCOMPARE(valueAt(7, k1M, u"lock"), 1);
        // ID 7 was free, as hoped: its silence is no link error.
        QCOMPARE(m_link->counters().timeouts, 0);
        QCOMPARE(m_link->counters().retries, 0);
        // In EEPROM: the new ID survives a power cycle.
        powerCycle();
        QCOMPARE(valueAt(7, k1M, u"id"), 7);
    }

    void changeIdRefusesAnIdInUseAndWritesNothing()
    {
        const ServoInfo first = servo(1, k1M);
        const OperationResult result =
            run([&](auto finish) { m_flows->changeId(first, 3, {}, finish); });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::IdInUse);
        QCOMPARE(result.servo.id, quint8(1));
        QCOMPARE(writesReceived(), 0);
        QCOMPARE(valueAt(1, k1M, u"id"), 1);
        QCOMPARE(valueAt(3, k1M, u"id"), 3); // the SCS15 there is untouched
        QCOMPARE(valueAt(1, k1M, u"lock"), 1);
    }

    void changeIdRefusesWhatIsWrongBeforeSendingAnything_data()
    {
        QTest::addColumn<int>("newId");
        QTest::addColumn<QVector<int>>("inUse");
        QTest::newRow("out of range") << 254 << QVector<int> {};
        QTest::newRow("negative") << -1 << QVector<int> {};
        QTest::newRow("its own ID") << 1 << QVector<int> {};
        QTest::newRow("known to be in use") << 9 << QVector<int> {1, 9};
    }

    void changeIdRefusesWhatIsWrongBeforeSendingAnything()
    {
        QFETCH(int, newId);
        QFETCH(QVector<int>, inUse);
        const ServoInfo first = servo(1, k1M);
        const int before = testsupport::feetechFramesReceived(logPath()).size();
        bool finished = false;
        m_flows->changeId(first, newId, inUse, [&](const OperationResult &result) {
            finished = true;
            QVERIFY(!result.ok);
            QVERIFY(!result.message.isEmpty());
        });
        QVERIFY(finished); // at once
        QCOMPARE(testsupport::feetechFramesReceived(logPath()).size(), before);
    }

    void changeBaudFollowsTheServoToItsNewRate()
    {
        const OperationResult result =
            run([&](auto finish) { m_flows->changeBaud(servo(2, k1M), k500k, finish); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.servo.id, quint8(2));
        QCOMPARE(result.servo.baud, k500k);
        QCOMPARE(int(result.servo.baudCode), *feetech::baudCode(k500k));
        QCOMPARE(valueAt(2, k500k, u"baud_rate"), *feetech::baudCode(k500k));
        QCOMPARE(valueAt(2, k500k, u"lock"), 1);
        QCOMPARE(valueAt(2, k1M, u"id"), -1);
    }

    void changeBaudIsRefusedWhenTheIdAlreadyAnswersAtTheNewRate()
    {
        // ID 1 answers at 115200 too: two servos would then share an address.
        const OperationResult result =
            run([&](auto finish) { m_flows->changeBaud(servo(1, k1M), k115k, finish); });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::IdInUse);
        QCOMPARE(writesReceived(), 0);
        QCOMPARE(valueAt(1, k1M, u"baud_rate"), *feetech::baudCode(k1M));
        QCOMPARE(valueAt(1, k115k, u"baud_rate"), *feetech::baudCode(k115k));
    }

    void calibrateMiddleMakesThePresentPositionTheMiddle_data()
    {
        QTest::addColumn<quint8>("id");
        QTest::addColumn<qint32>("baud");
        QTest::addColumn<bool>("byInstruction");
        QTest::newRow("STS: instruction 0x0B") << quint8(1) << k1M << true;
        QTest::newRow("SMS: torque enable 128") << quint8(4) << k115k << false;
    }

    void calibrateMiddleMakesThePresentPositionTheMiddle()
    {
        QFETCH(quint8, id);
        QFETCH(qint32, baud);
        QFETCH(bool, byInstruction);
        const ServoInfo target = servo(id, baud);
        QCOMPARE(feetech::middleCalibration(target) == feetech::MiddleCalibration::Instruction,
                 byInstruction);
        QVERIFY(withServo(id, baud, [](auto &servo) { servo.setPhysicalPosition(2548); }));
        const OperationResult result =
            run([&](auto finish) { m_flows->calibrateMiddle(target, finish); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(valueAt(id, baud, u"position_offset"), 500);
        QVERIFY(qAbs(valueAt(id, baud, u"present_position") - 2048) <= 2);
        QCOMPARE(valueAt(id, baud, u"lock"), 1);
        // The way the family asks for it, and only that way.
        const int instructions =
            testsupport::feetechRequestsReceived(logPath(), Instruction::Calibrate, id).size();
        int torque128 = 0;
        const int torqueAddress = target.table().find(u"torque_enable")->address;
        for (const feetech::Packet &write :
             testsupport::feetechRequestsReceived(logPath(), Instruction::Write, id)) {
            if (write.parameters == oneByteWrite(torqueAddress, 128))
                ++torque128;
        }
        QCOMPARE(instructions, byInstruction ? 1 : 0);
        QCOMPARE(torque128, byInstruction ? 0 : 1);
        // The offset went to EEPROM.
        powerCycle();
        QCOMPARE(valueAt(id, baud, u"position_offset"), 500);
    }

    void calibrateMiddleIsRefusedOnScsWithNothingSent()
    {
        const ServoInfo scs = servo(3, k1M);
        const int before = testsupport::feetechFramesReceived(logPath()).size();
        const OperationResult result =
            run([&](auto finish) { m_flows->calibrateMiddle(scs, finish); });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::Unsupported);
        QCOMPARE(testsupport::feetechFramesReceived(logPath()).size(), before);
    }

    void factoryResetFindsTheServoAgainAtItsFactoryRate()
    {
        // Servo 2 was moved to 500 kbps and had a limit changed, both kept in EEPROM.
        const ServoInfo moved =
            run([&](auto finish) { m_flows->changeBaud(servo(2, k1M), k500k, finish); }).servo;
        QCOMPARE(moved.baud, k500k);
        setSimulatorValue(2, u"max_temperature", 60);
        const qint32 factoryTemperature = valueAt(1, k1M, u"max_temperature"); // untouched
        QVERIFY(factoryTemperature != 60);

        const OperationResult result =
            run([&](auto finish) { m_flows->factoryReset(moved, finish); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.servo.baud, k1M);
        QCOMPARE(result.servo.id, quint8(2)); // the ID is not a factory value
        QCOMPARE(valueAt(2, k1M, u"baud_rate"), *feetech::baudCode(k1M));
        QCOMPARE(valueAt(2, k1M, u"max_temperature"), factoryTemperature);
        QCOMPARE(valueAt(2, k1M, u"lock"), 1);
        powerCycle();
        QCOMPARE(valueAt(2, k1M, u"baud_rate"), *feetech::baudCode(k1M));
    }

    void rebootTurnsTorqueOffAndWaitsUntilTheServoAnswersAgain()
    {
        setSimulatorValue(2, u"torque_enable", 1);
        const ServoInfo target = servo(2, k1M);
        const int pingsBefore =
            testsupport::feetechRequestsReceived(logPath(), Instruction::Ping, 2).size();
        const OperationResult result = run([&](auto finish) { m_flows->reboot(target, finish); });
        QVERIFY2(result.ok, qPrintable(result.message));
        QCOMPARE(result.servo.id, quint8(2));
        const QVector<feetech::Packet> frames = testsupport::feetechPacketsReceived(logPath());
        const int torqueAddress = target.table().find(u"torque_enable")->address;
        int torqueOff = -1;
        int reboot = -1;
        for (int i = 0; i < frames.size(); ++i) {
            if (frames.at(i).id != 2)
                continue;
            if (frames.at(i).code == quint8(Instruction::Write)
                && frames.at(i).parameters == oneByteWrite(torqueAddress, 0))
                torqueOff = i;
            if (frames.at(i).code == quint8(Instruction::Reboot))
                reboot = i;
        }
        QVERIFY(torqueOff >= 0 && torqueOff < reboot);
        // The servo is silent for half a second after a reboot; the flow asks every 20 ms
        // until it answers, so more than one PING went out.
        const int pings =
            testsupport::feetechRequestsReceived(logPath(), Instruction::Ping, 2).size();
        QVERIFY2(pings - pingsBefore >= 2, qPrintable(QString::number(pings - pingsBefore)));
        QCOMPARE(valueAt(2, k1M, u"torque_enable"), 0);
    }

    void rebootGivesUpOnAServoThatDoesNotComeBackInTime()
    {
        // It stays silent for 500 ms after the restart; the flow waits only 100 ms.
        cleanup();
        m_timing.rebootPollInterval = std::chrono::milliseconds(20);
        m_timing.rebootGiveUp = std::chrono::milliseconds(100);
        startBus();
        const OperationResult result =
            run([&](auto finish) { m_flows->reboot(servo(1, k1M), finish); });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::NoAnswer);
    }
};

QTEST_GUILESS_MAIN(TestGuidedFlows)
#include "tst_guidedflows.moc"
