// Tests one simulated Feetech servo: registers, lock semantics, instructions and physics.
#include "feetechpacket.h"
#include "modeltable.h"
#include "registertable.h"
#include "virtualfeetechservo.h"

#include <QtTest>

using feetech::Family;
using feetech::Instruction;
using sim::VirtualFeetechServo;

namespace {

constexpr qint64 kMs = 1000;

VirtualFeetechServo makeServo(const char *model, quint8 id = 1, qint32 baud = 1000000)
{
    const auto info = feetech::ModelTable::builtIn().findByName(QString::fromLatin1(model));
    Q_ASSERT(info && info->family);
    return VirtualFeetechServo(*info, id, baud);
}

VirtualFeetechServo makeHls(quint8 id = 1)
{
    return VirtualFeetechServo(feetech::ModelTable::builtIn().identify(10, 1), id, 1000000);
}

// Sends one instruction frame; the decoded reply, if the servo sent one.
std::optional<feetech::Packet> send(VirtualFeetechServo &servo, const QByteArray &frame)
{
    const auto packet = feetech::decodePacket(frame);
    Q_ASSERT(packet);
    const auto reply = servo.execute(*packet, packet->id == feetech::kBroadcastId);
    if (!reply)
        return std::nullopt;
    const auto decoded = feetech::decodePacket(*reply);
    Q_ASSERT(decoded);
    return decoded;
}

QByteArray readBytes(VirtualFeetechServo &servo, quint8 address, quint8 length)
{
    const auto reply = send(servo, feetech::read(servo.id(), address, length));
    return reply ? reply->parameters : QByteArray();
}

QByteArray byte(int value)
{
    return QByteArray(1, char(value));
}

QByteArray littleEndian(int value)
{
    return QByteArray() + char(value & 0xFF) + char((value >> 8) & 0xFF);
}

void writeByte(VirtualFeetechServo &servo, quint8 address, int value)
{
    send(servo, feetech::write(servo.id(), address, byte(value)));
}

// STS in position mode with torque on, goal speed `speed`, starting from the middle.
void startMove(VirtualFeetechServo &servo, int goal, int speed)
{
    send(servo, feetech::write(servo.id(), 46, littleEndian(speed)));
    send(servo, feetech::write(servo.id(), 42, littleEndian(goal)));
    writeByte(servo, 40, 1);
}

} // namespace

class TestVirtualFeetechServo : public QObject
{
    Q_OBJECT

private slots:
    void factoryRegistersReadBackModelByteOrderIdBaudAndLock()
    {
        VirtualFeetechServo servo = makeServo("STS3215", 7, 500000);
        const QByteArray head = readBytes(servo, 0, 7);
        QCOMPARE(head.toHex(), QByteArray("030a0009030701")); // fw 3.10, END 0, 9/3, ID 7, code 1
        QCOMPARE(feetech::modelNumber(quint8(head[3]), quint8(head[4]), feetech::ByteOrder::Little),
                 quint16(777));
        QCOMPARE(readBytes(servo, 55, 1), byte(1));
        QCOMPARE(servo.baudRate(), 500000);
        QCOMPARE(servo.id(), quint8(7));
        QCOMPARE(servo.value(u"torque_limit"), 1000); // copied from max torque at power-on
        QCOMPARE(servo.value(u"present_voltage"), 74);
        QCOMPARE(servo.value(u"present_temperature"), 25);
    }

    void readReturnsStsValuesLittleEndianAndScsValuesBigEndian()
    {
        VirtualFeetechServo sts = makeServo("STS3215");
        QCOMPARE(readBytes(sts, 11, 2).toHex(), QByteArray("ff0f")); // 4095
        VirtualFeetechServo scs = makeServo("SCS15");
        QCOMPARE(readBytes(scs, 11, 2).toHex(), QByteArray("03eb")); // 1003
        QCOMPARE(readBytes(scs, 2, 3).toHex(), QByteArray("01050f")); // END 1, model 5/15
        QCOMPARE(readBytes(scs, 48, 1), byte(1)); // SCS lock lives at 48
    }

    void readOfNothingOrPastTheLastAddressGetsNoReply()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        QVERIFY(!send(servo, feetech::read(1, 56, 0)));
        QVERIFY(!send(servo, feetech::read(1, 250, 10)));
        QVERIFY(send(servo, feetech::read(1, 250, 6)));
    }

    void eepromWriteWhileLockedIsLostAtPowerCycle()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        const quint64 revision = servo.eepromRevision();
        QVERIFY(send(servo, feetech::write(1, 11, littleEndian(3000))));
        QCOMPARE(servo.value(u"max_angle_limit"), 3000); // live at once
        QCOMPARE(servo.eepromRevision(), revision);
        servo.powerCycle();
        QCOMPARE(servo.value(u"max_angle_limit"), 4095);
    }

    void eepromWriteWhileUnlockedSurvivesPowerCycle()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        const quint64 revision = servo.eepromRevision();
        writeByte(servo, 55, 0);
        QVERIFY(send(servo, feetech::write(1, 11, littleEndian(3000))));
        writeByte(servo, 55, 1);
        QVERIFY(servo.eepromRevision() > revision);
        servo.powerCycle();
        QCOMPARE(servo.value(u"max_angle_limit"), 3000);
        QCOMPARE(servo.value(u"lock"), 1);
        QCOMPARE(servo.eepromImage().mid(11, 2).toHex(), QByteArray("b80b"));
    }

    void readOnlyAndUndefinedRegistersIgnoreWritesButStillReply()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        QVERIFY(send(servo, feetech::write(1, 3, byte(42))));
        QCOMPARE(servo.value(u"model_major"), 9);
        QVERIFY(send(servo, feetech::write(1, 56, littleEndian(100))));
        QCOMPARE(servo.value(u"present_position"), 2048);
        QVERIFY(send(servo, feetech::write(1, 50, byte(7))));
        QCOMPARE(readBytes(servo, 50, 1), byte(0));
    }

    void responseLevelZeroSuppressesWriteRepliesButNotReadOrPing()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        // The level applies as soon as it is written: that write is already silent.
        QVERIFY(!send(servo, feetech::write(1, 8, byte(0))));
        QVERIFY(!send(servo, feetech::write(1, 42, littleEndian(1000))));
        QCOMPARE(servo.value(u"goal_position"), 1000); // executed, just silent
        QVERIFY(!send(servo, feetech::regWrite(1, 42, littleEndian(1200))));
        QVERIFY(send(servo, feetech::read(1, 42, 2)));
        QVERIFY(send(servo, feetech::ping(1)));
    }

    void broadcastGetsNoReplyExceptToPing()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        QVERIFY(!send(servo, feetech::write(feetech::kBroadcastId, 42, littleEndian(1000))));
        QCOMPARE(servo.value(u"goal_position"), 1000);
        QVERIFY(!send(servo, feetech::read(feetech::kBroadcastId, 42, 2)));
        const auto pong = send(servo, feetech::ping(feetech::kBroadcastId));
        QVERIFY(pong);
        QCOMPARE(pong->id, quint8(1));
    }

    void regWriteDoesNothingUntilAction()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        QVERIFY(send(servo, feetech::regWrite(1, 42, littleEndian(1000))));
        QCOMPARE(servo.value(u"goal_position"), 2048); // power-on goal = present
        QCOMPARE(servo.value(u"async_write_flag"), 1);
        QVERIFY(!send(servo, feetech::action()));
        QCOMPARE(servo.value(u"goal_position"), 1000);
        QCOMPARE(servo.value(u"async_write_flag"), 0);
    }

    void recoveryRestoresFactoryValuesExceptTheId()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 55, 0);
        send(servo, feetech::write(1, 11, littleEndian(3000)));
        writeByte(servo, 13, 60);
        writeByte(servo, 5, 9);
        QCOMPARE(servo.id(), quint8(9));
        const auto reply = send(servo, feetech::recovery(9));
        QVERIFY(reply);
        QCOMPARE(reply->id, quint8(9));
        QCOMPARE(servo.value(u"max_angle_limit"), 4095);
        QCOMPARE(servo.value(u"max_temperature"), 70);
        QCOMPARE(servo.id(), quint8(9));
        servo.powerCycle(); // unlocked: persisted
        QCOMPARE(servo.value(u"max_angle_limit"), 4095);
        QCOMPARE(servo.id(), quint8(9));
    }

    void recoveryAfterBackupRestoresTheBackup()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 55, 0);
        writeByte(servo, 13, 60);
        QVERIFY(send(servo, feetech::encodePacket(1, quint8(Instruction::Backup))));
        writeByte(servo, 13, 50);
        QVERIFY(send(servo, feetech::recovery(1)));
        QCOMPARE(servo.value(u"max_temperature"), 60);
    }

    void lockedRecoveryIsLostAtPowerCycle()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 55, 0);
        writeByte(servo, 13, 60);
        writeByte(servo, 55, 1);
        QVERIFY(send(servo, feetech::recovery(1)));
        QCOMPARE(servo.value(u"max_temperature"), 70);
        servo.powerCycle();
        QCOMPARE(servo.value(u"max_temperature"), 60);
    }

    void rebootGetsNoReplyAndPowerCycles()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        send(servo, feetech::write(1, 11, littleEndian(3000)));
        writeByte(servo, 40, 1);
        QVERIFY(!send(servo, feetech::reboot(1)));
        QCOMPARE(servo.value(u"max_angle_limit"), 4095);
        QCOMPARE(servo.value(u"torque_enable"), 0);
        QCOMPARE(servo.value(u"lock"), 1);
    }

    void resetClearsTheStatus()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 35, 10); // 100 ms protection time
        writeByte(servo, 40, 1);
        servo.setExternalLoad(900);
        servo.advanceTo(300 * kMs);
        QCOMPARE(servo.value(u"status"), 0x20);
        const auto reply = send(servo, feetech::reset(1));
        QVERIFY(reply);
        QCOMPARE(reply->code, quint8(0));
        QCOMPARE(servo.value(u"status"), 0);
    }

    void calibrateMakesPresentPosition2048OnSts()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        servo.setPhysicalPosition(1000);
        QCOMPARE(servo.value(u"present_position"), 1000);
        const auto reply = send(servo, feetech::calibrate(1));
        QVERIFY(reply);
        QCOMPARE(servo.value(u"present_position"), 2048);
        QCOMPARE(servo.value(u"position_offset"), -1048);
        // Sign-magnitude with bit 11, little-endian: 0x0800 | 1048 = 0x0C18.
        QCOMPARE(readBytes(servo, 31, 2).toHex(), QByteArray("180c"));
    }

    void calibrateWithAValueMakesThatThePresentPosition()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        servo.setPhysicalPosition(3000);
        QVERIFY(send(servo, QByteArray::fromHex("FFFF01040B0004EB"))); // spec §10 example: 1024
        QCOMPARE(servo.value(u"present_position"), 1024);
        QCOMPARE(servo.value(u"position_offset"), 1976);
    }

    void torqueEnable128MakesPresentPosition2048AndReadsBackZeroOnSts()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        servo.setPhysicalPosition(3000);
        QVERIFY(send(servo, feetech::write(1, 40, byte(128))));
        QCOMPARE(servo.value(u"present_position"), 2048);
        QCOMPARE(servo.value(u"torque_enable"), 0);
        servo.powerCycle(); // locked: the offset was not persisted
        QCOMPARE(servo.value(u"present_position"), 3000);
    }

    void calibrateAndTorqueEnable128DoNothingOnScs()
    {
        VirtualFeetechServo servo = makeServo("SCS15");
        servo.setPhysicalPosition(300);
        QVERIFY(!send(servo, feetech::calibrate(1)));
        QCOMPARE(servo.value(u"present_position"), 300);
        QVERIFY(send(servo, feetech::write(1, 40, byte(128))));
        QCOMPARE(servo.value(u"torque_enable"), 0);
        QCOMPARE(servo.value(u"present_position"), 300);
    }

    void smsCalibratesByTorqueEnable128ButNotByInstruction()
    {
        VirtualFeetechServo servo = makeServo("SM40BLHV", 1, 115200);
        servo.setPhysicalPosition(100);
        QVERIFY(!send(servo, feetech::calibrate(1)));
        QCOMPARE(servo.value(u"present_position"), 100);
        QVERIFY(send(servo, feetech::write(1, 40, byte(128))));
        QCOMPARE(servo.value(u"present_position"), 2048);
        QCOMPARE(servo.returnDelayUs(), qint64(100)); // SMS: register 7 below 50 acts as 50
    }

    void hlsCalibratesByInstructionButIgnoresTorqueEnable128()
    {
        VirtualFeetechServo servo = makeHls();
        QCOMPARE(readBytes(servo, 0, 4).toHex(), QByteArray("032d000a")); // fw 3.45, model 10
        servo.setPhysicalPosition(500);
        QVERIFY(send(servo, feetech::write(1, 40, byte(128))));
        QCOMPARE(servo.value(u"present_position"), 500);
        QVERIFY(send(servo, feetech::calibrate(1, littleEndian(100))));
        QCOMPARE(servo.value(u"present_position"), 100);
        QCOMPARE(servo.returnDelayUs(), qint64(0)); // address 7 is the secondary ID on HLS
    }

    void positionMoveRunsAtTheGoalSpeedAndStopsOnTheGoal()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        startMove(servo, 3048, 1000);
        // Fast acceleration (50000 step/s²) costs 10 steps against an instant start.
        for (const int ms : {100, 300, 500, 800}) {
            servo.advanceTo(ms * kMs);
            const int expected = 2048 + ms - 10;
            QVERIFY2(qAbs(servo.value(u"present_position") - expected) <= 15,
                     qPrintable(QStringLiteral("at %1 ms: %2, expected about %3")
                                    .arg(ms)
                                    .arg(servo.value(u"present_position"))
                                    .arg(expected)));
            QCOMPARE(servo.value(u"moving"), 1);
            QVERIFY(qAbs(servo.value(u"present_speed") - 1000) <= 5);
            QVERIFY(servo.value(u"present_load") > 0);
        }
        servo.advanceTo(1500 * kMs);
        QCOMPARE(servo.value(u"present_position"), 3048);
        QCOMPARE(servo.value(u"present_speed"), 0);
        QCOMPARE(servo.value(u"moving"), 0);
        QCOMPARE(servo.value(u"current_goal_position"), 3048);
    }

    void slowAccelerationGivesATrapezoid()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 41, 20); // 2000 step/s²
        startMove(servo, 3048, 1000);
        servo.advanceTo(250 * kMs); // still ramping: v = 500, s = 62.5
        QVERIFY(qAbs(servo.value(u"present_speed") - 500) <= 5);
        QVERIFY(qAbs(servo.value(u"present_position") - 2110) <= 3);
        servo.advanceTo(2000 * kMs); // 0.5 s up, 0.5 s cruise, 0.5 s down
        QCOMPARE(servo.value(u"present_position"), 3048);
        QCOMPARE(servo.value(u"moving"), 0);
    }

    void goalOutsideTheAngleLimitsStopsAtTheLimit()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        send(servo, feetech::write(1, 11, littleEndian(2500)));
        startMove(servo, 4000, 0); // speed 0: the model's maximum
        servo.advanceTo(1000 * kMs);
        QCOMPARE(servo.value(u"present_position"), 2500);
    }

    void torqueOffMeansNoMotion()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        send(servo, feetech::write(1, 42, littleEndian(3000)));
        servo.advanceTo(1000 * kMs);
        QCOMPARE(servo.value(u"present_position"), 2048);
        QCOMPARE(servo.value(u"present_speed"), 0);
        QCOMPARE(servo.value(u"moving"), 0);
        QCOMPARE(servo.value(u"present_load"), 0);
    }

    void dampingLetsTheSpeedDecay()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        startMove(servo, 4000, 2000);
        servo.advanceTo(200 * kMs);
        writeByte(servo, 40, 2);
        servo.advanceTo(250 * kMs);
        const int slowed = servo.value(u"present_speed");
        QVERIFY(slowed > 0 && slowed < 1000);
        servo.advanceTo(1000 * kMs);
        QCOMPARE(servo.value(u"present_speed"), 0);
    }

    void wheelModeRunsAtTheSignedGoalSpeed()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 33, 1);
        send(servo, feetech::write(1, 46, littleEndian(0x8000 | 500))); // −500 step/s
        writeByte(servo, 40, 1);
        servo.advanceTo(1000 * kMs);
        QCOMPARE(servo.value(u"present_speed"), -500);
        QVERIFY(qAbs(servo.value(u"present_position") - (2048 - 500)) <= 5);
        servo.advanceTo(5000 * kMs); // wraps below 0
        QVERIFY(qAbs(servo.value(u"present_position") - (2048 - 2500 + 4096)) <= 5);
    }

    void scsMotorModeRunsFromThePwmRegister()
    {
        VirtualFeetechServo servo = makeServo("SCS15");
        servo.setValue(u"min_angle_limit", 0);
        servo.setValue(u"max_angle_limit", 0);
        send(servo, feetech::write(1, 44, QByteArray::fromHex("01F4"))); // +500 (big-endian)
        writeByte(servo, 40, 1);
        servo.advanceTo(200 * kMs);
        QVERIFY(qAbs(servo.value(u"present_speed") - 500) <= 5);
    }

    void negativePresentSpeedIsSignMagnitudeOnTheWire()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        startMove(servo, 1048, 1000);
        servo.advanceTo(300 * kMs);
        QCOMPARE(servo.value(u"present_speed"), -1000);
        QCOMPARE(readBytes(servo, 58, 2).toHex(), QByteArray("e883")); // 0x8000 | 1000
        QVERIFY(servo.value(u"present_load") < 0);
    }

    void supplyVoltageAboveMaxSetsTheVoltageBit()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        servo.setSupplyVoltage(9.0); // max_voltage 8.0 V
        servo.advanceTo(10 * kMs);
        QCOMPARE(servo.value(u"present_voltage"), 90);
        QCOMPARE(servo.value(u"status") & 0x01, 0x01);
        const auto pong = send(servo, feetech::ping(1));
        QVERIFY(pong);
        QCOMPARE(pong->code & 0x01, 0x01);
        servo.setSupplyVoltage(7.4);
        QCOMPARE(send(servo, feetech::ping(1))->code, quint8(0));
    }

    void temperatureAboveMaxSetsTheTemperatureBitAndDropsTorque()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 40, 1);
        servo.setTemperature(80);
        servo.advanceTo(10 * kMs);
        QCOMPARE(servo.value(u"status") & 0x04, 0x04);
        QCOMPARE(send(servo, feetech::ping(1))->code & 0x04, 0x04);
        QCOMPARE(servo.value(u"torque_enable"), 0);
    }

    void temperatureRisesSlowlyUnderLoad()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 36, 100); // overload protection out of the way
        writeByte(servo, 40, 1);
        servo.setExternalLoad(800);
        servo.advanceTo(1000 * kMs);
        QCOMPARE(servo.value(u"present_temperature"), 25); // slow
        QVERIFY(servo.value(u"present_current") > 300); // 6.5 mA units
        QVERIFY(servo.value(u"present_voltage") < 74); // sags with current
        servo.advanceTo(300'000 * kMs);
        QVERIFY(servo.value(u"present_temperature") > 45);
    }

    void sustainedExternalLoadSetsTheOverloadBitAfterTheProtectionTime()
    {
        VirtualFeetechServo servo = makeServo("STS3215"); // overload 80 %, 200 × 10 ms
        writeByte(servo, 40, 1);
        servo.setExternalLoad(900);
        servo.advanceTo(1900 * kMs);
        QCOMPARE(servo.value(u"present_load"), 900);
        QCOMPARE(servo.value(u"status") & 0x20, 0);
        servo.advanceTo(2100 * kMs);
        QCOMPARE(servo.value(u"status") & 0x20, 0x20);
        QCOMPARE(send(servo, feetech::ping(1))->code & 0x20, 0x20);
        QCOMPARE(servo.value(u"present_load"), 200); // limited to the holding torque
    }

    void loadBelowTheOverloadTorqueNeverTrips()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        writeByte(servo, 40, 1);
        servo.setExternalLoad(-700);
        servo.advanceTo(5000 * kMs);
        QCOMPARE(servo.value(u"present_load"), -700);
        QCOMPARE(servo.value(u"status"), 0);
    }

    void idChangeRepliesWithTheOldIdThenAnswersOnlyAtTheNewId()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        const auto reply = send(servo, feetech::write(1, 5, byte(12)));
        QVERIFY(reply);
        QCOMPARE(reply->id, quint8(1));
        QCOMPARE(servo.id(), quint8(12));
        const auto pong = send(servo, feetech::ping(12));
        QVERIFY(pong);
        QCOMPARE(pong->id, quint8(12));
        QVERIFY(send(servo, feetech::write(12, 5, byte(254)))); // out of range: ignored
        QCOMPARE(servo.id(), quint8(12));
    }

    void baudChangeTakesEffectAfterTheReply()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        QVERIFY(send(servo, feetech::write(1, 6, byte(4))));
        QCOMPARE(servo.baudRate(), 115200);
        servo.powerCycle(); // locked: back to the stored rate
        QCOMPARE(servo.baudRate(), 1000000);
    }

    void eepromImageRoundTripsThroughSetEepromImage()
    {
        VirtualFeetechServo first = makeServo("STS3215");
        writeByte(first, 55, 0);
        writeByte(first, 5, 33);
        VirtualFeetechServo second = makeServo("STS3215");
        QVERIFY(second.setEepromImage(first.eepromImage()));
        QCOMPARE(second.id(), quint8(1)); // until it powers up
        second.powerCycle();
        QCOMPARE(second.id(), quint8(33));
        QVERIFY(!second.setEepromImage(QByteArray(10, '\0')));
    }

    void advancingIsDeterministic()
    {
        VirtualFeetechServo a = makeServo("STS3215");
        VirtualFeetechServo b = makeServo("STS3215");
        for (VirtualFeetechServo *servo : {&a, &b}) {
            writeByte(*servo, 41, 30);
            startMove(*servo, 100, 3000);
        }
        // Whole-millisecond slices integrate exactly like one long call.
        for (qint64 t = 0; t <= 1000 * kMs; t += 37 * kMs)
            a.advanceTo(t);
        a.advanceTo(1000 * kMs);
        b.advanceTo(1000 * kMs);
        QCOMPARE(a.registerFile().mid(56, 15), b.registerFile().mid(56, 15));
    }

    void unicastActionGetsNoReply()
    {
        VirtualFeetechServo servo = makeServo("STS3215");
        QVERIFY(send(servo, feetech::regWrite(1, 46, littleEndian(300))));
        QVERIFY(!send(servo, feetech::action(1)));
        QCOMPARE(servo.value(u"goal_speed"), 300);
    }
};

QTEST_APPLESS_MAIN(TestVirtualFeetechServo)
#include "tst_virtualfeetechservo.moc"
