// Tests the simulated Feetech bus: routing by ID and baud, broadcast, SYNC READ / SYNC WRITE,
// collisions, baud changes, reboot silence, the EEPROM state file and spec validation.
#include "feetechpacket.h"
#include "virtualfeetechbus.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

using feetech::Instruction;
using sim::Response;
using sim::SimRefusal;
using sim::VirtualFeetechBus;

Q_DECLARE_METATYPE(sim::SimRefusal::Code)
Q_DECLARE_METATYPE(sim::VirtualFeetechBus::ServoSpec)

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;
constexpr qint64 kMs = 1000;

using Specs = QVector<VirtualFeetechBus::ServoSpec>;

// STS3215 id 1, SCS15 id 2, HLS id 3 at 1 Mbps; an SMS at its default 115200, id 4.
Specs mixedSpecs()
{
    return {{1, QStringLiteral("STS3215"), 0},
            {2, QStringLiteral("SCS15"), 0},
            {3, QStringLiteral("HLS"), 0},
            {4, QStringLiteral("SM40BLHV"), 0}};
}

QByteArray byte(int value)
{
    return QByteArray(1, char(value));
}

QByteArray littleEndian(int value)
{
    return QByteArray() + char(value & 0xFF) + char((value >> 8) & 0xFF);
}

QVector<quint8> replyIds(const QVector<Response> &responses)
{
    QVector<quint8> ids;
    for (const Response &response : responses) {
        const auto packet = feetech::decodePacket(response.bytes);
        ids.append(packet ? packet->id : 0xFF);
    }
    return ids;
}

} // namespace

class TestVirtualFeetechBus : public QObject
{
    Q_OBJECT

private slots:
    void mixedBusAnswersPingPerIdOnlyAtItsOwnBaud()
    {
        VirtualFeetechBus bus(mixedSpecs());
        QCOMPARE(bus.servoCount(), 4);
        QCOMPARE(bus.servo(2).family(), feetech::Family::Hls);
        for (quint8 id : {1, 2, 3}) {
            QCOMPARE(replyIds(bus.handleFrame(feetech::ping(id), k1M, 0)), QVector<quint8> {id});
            QVERIFY(bus.handleFrame(feetech::ping(id), k115k, 0).isEmpty());
        }
        QVERIFY(bus.handleFrame(feetech::ping(4), k1M, 0).isEmpty());
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(4), k115k, 0)), QVector<quint8> {4});
        QVERIFY(bus.handleFrame(feetech::ping(5), k1M, 0).isEmpty());
    }

    void scsRepliesBigEndianOnAMixedBus()
    {
        VirtualFeetechBus bus(mixedSpecs());
        const auto replies = bus.handleFrame(feetech::read(2, 11, 2), k1M, 0);
        QCOMPARE(replies.size(), 1);
        QCOMPARE(feetech::decodePacket(replies[0].bytes)->parameters.toHex(), QByteArray("03eb"));
    }

    void syncReadAnswersInListOrderWithGapsAndScsNeverAnswers()
    {
        VirtualFeetechBus bus(mixedSpecs());
        const auto replies = bus.handleFrame(feetech::syncRead(56, 2, {3, 2, 9, 1, 4}), k1M, 0);
        QCOMPARE(replyIds(replies), (QVector<quint8> {3, 1}));
        const auto first = feetech::decodePacket(replies[0].bytes);
        QCOMPARE(first->parameters, littleEndian(2048));
        QCOMPARE(replies[1].bytes.size(), 8); // an ordinary READ status frame of 2 bytes
    }

    void syncWriteMovesGoalsOfSeveralServosWithoutReply()
    {
        VirtualFeetechBus bus(mixedSpecs());
        const auto frame = feetech::syncWrite(
            42, 2, {{1, littleEndian(1000)}, {3, littleEndian(3000)}, {7, littleEndian(5)}});
        QVERIFY(frame);
        QVERIFY(bus.handleFrame(*frame, k1M, 0).isEmpty());
        QCOMPARE(bus.findServo(1)->value(u"goal_position"), 1000);
        QCOMPARE(bus.findServo(3)->value(u"goal_position"), 3000);

        for (quint8 id : {1, 3})
            bus.handleFrame(feetech::write(id, 40, byte(1)), k1M, 0);
        bus.advanceTo(2000 * kMs);
        QCOMPARE(bus.findServo(1)->value(u"present_position"), 1000);
        QCOMPARE(bus.findServo(3)->value(u"present_position"), 3000);
    }

    void broadcastWriteExecutesOnAllListeningServosWithoutReply()
    {
        VirtualFeetechBus bus(mixedSpecs());
        QVERIFY(
            bus.handleFrame(feetech::write(feetech::kBroadcastId, 40, byte(1)), k1M, 0).isEmpty());
        for (quint8 id : {1, 2, 3})
            QCOMPARE(bus.findServo(id)->value(u"torque_enable"), 1);
        QCOMPARE(bus.findServo(4)->value(u"torque_enable"), 0); // at 115200: heard only noise
    }

    void anUnpoweredServoHearsNothingAndBootsFreshWhenPoweredAgain()
    {
        VirtualFeetechBus bus(mixedSpecs());
        bus.servo(0).setValue(u"torque_enable", 1);
        QVERIFY(bus.setPowered(0, false));
        QVERIFY(!bus.isPowered(0));
        QVERIFY(bus.handleFrame(feetech::ping(1), k1M, 0).isEmpty());
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(2), k1M, 0)), QVector<quint8> {2});
        QVERIFY(bus.setPowered(0, true));
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(1), k1M, 0)), QVector<quint8> {1});
        QCOMPARE(bus.servo(0).value(u"torque_enable"), 0);
        QVERIFY(!bus.setPowered(9, false));
    }

    void aBrokenChainSilencesEveryServoAfterTheBreakUntilMended()
    {
        VirtualFeetechBus bus(mixedSpecs());
        QVERIFY(bus.setChainBreakAfter(0));
        QCOMPARE(bus.chainBreakAfter(), 0);
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(1), k1M, 0)), QVector<quint8> {1});
        QVERIFY(bus.handleFrame(feetech::ping(2), k1M, 0).isEmpty());
        QVERIFY(bus.handleFrame(feetech::ping(3), k1M, 0).isEmpty());
        QVERIFY(bus.handleFrame(feetech::ping(4), k115k, 0).isEmpty());
        QVERIFY(!bus.setChainBreakAfter(4));
        QVERIFY(bus.setChainBreakAfter(-1));
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(4), k115k, 0)), QVector<quint8> {4});
    }

    void unpluggingAServoBeforeTheBreakKeepsTheBreakAfterTheSameServo()
    {
        VirtualFeetechBus bus(mixedSpecs());
        QVERIFY(bus.setChainBreakAfter(1)); // after ID 2
        QVERIFY(bus.unplug(0));
        QCOMPARE(bus.chainBreakAfter(), 0); // still after ID 2, now first
        QVERIFY(bus.isPowered(0));
        QVERIFY(!bus.isPowered(1));
    }

    void aLatchedOverloadStaysSetWhenTorqueIsSwitchedOnAgainUntilAPowerCycle()
    {
        VirtualFeetechBus bus({{1, QStringLiteral("STS3215"), 0}});
        bus.servo(0).setOverloadLatched(true);
        const auto write = [&](int value) {
            bus.handleFrame(feetech::write(1, 40, byte(value)), k1M, 0);
        };
        write(0);
        write(1);
        bus.advanceTo(10 * kMs);
        QCOMPARE(bus.servo(0).value(u"status") & 0x20, 0x20);
        const double before = bus.servo(0).physicalPosition();
        bus.servo(0).setValue(u"goal_position", int(before) + 500);
        bus.advanceTo(500 * kMs);
        QCOMPARE(bus.servo(0).physicalPosition(), before); // limp: it does not move
        bus.powerCycle();
        bus.advanceTo(510 * kMs);
        QCOMPARE(bus.servo(0).value(u"status") & 0x20, 0);
        QVERIFY(!bus.servo(0).overloadLatched());
    }

    void heatRaisesTheTemperatureUntilTheServoTripsAtItsMaximum()
    {
        VirtualFeetechBus bus({{1, QStringLiteral("STS3215"), 0}});
        bus.servo(0).setValue(u"torque_enable", 1);
        bus.servo(0).setTemperatureRise(5.0);
        const int maximum = bus.servo(0).value(u"max_temperature");
        bus.advanceTo(qint64(maximum) * 1000 * kMs / 5);
        QVERIFY(bus.servo(0).value(u"present_temperature") >= maximum);
        QCOMPARE(bus.servo(0).value(u"torque_enable"), 0);
        QCOMPARE(bus.servo(0).value(u"status") & 0x04, 0x04);
    }

    void theSupplyReachesEveryServo()
    {
        VirtualFeetechBus bus(mixedSpecs());
        bus.setSupplyVoltage(12.6);
        for (int index = 0; index < bus.servoCount(); ++index)
            QCOMPARE(bus.servo(index).supplyVoltage(), 12.6);
    }

    void broadcastPingWithOneServoListeningGetsOneCleanReply()
    {
        VirtualFeetechBus bus(mixedSpecs());
        const auto replies = bus.handleFrame(feetech::ping(feetech::kBroadcastId), k115k, 0);
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].bytes, feetech::status(4, 0));
    }

    void broadcastPingWithTwoServosListeningGetsACollidedReply()
    {
        VirtualFeetechBus bus(
            Specs {{1, QStringLiteral("STS3215"), 0}, {3, QStringLiteral("STS3215"), 0}});
        const auto replies = bus.handleFrame(feetech::ping(feetech::kBroadcastId), k1M, 0);
        QCOMPARE(replies.size(), 1);
        // FF FF 01 02 00 FC and FF FF 03 02 00 FA overlap as FF FF 01 02 00 F8.
        QCOMPARE(replies[0].bytes.toHex(), QByteArray("ffff010200f8"));
        QVERIFY(!feetech::decodePacket(replies[0].bytes));
    }

    void twoServosAtOneIdPingCleanlyButTheirPositionReadIsGarbled()
    {
        const Specs twins {{1, QStringLiteral("STS3215"), 0}, {1, QStringLiteral("STS3215"), 0}};
        SimRefusal why;
        QVERIFY(!VirtualFeetechBus::validate(twins, &why));
        QCOMPARE(why.code(), SimRefusal::Code::IdTaken);
        QCOMPARE(why.servo(), 1);
        auto bus = VirtualFeetechBus::create(twins, &why, VirtualFeetechBus::SharedIds::Allow);
        QVERIFY2(bus, qPrintable(why.describe()));

        QCOMPARE(bus->handleFrame(feetech::ping(1), k1M, 0).first().bytes, feetech::status(1, 0));
        const auto identity = bus->handleFrame(feetech::read(1, 3, 2), k1M, 0);
        QVERIFY(feetech::decodePacket(identity.first().bytes)); // same model: same bytes
        QVERIFY(bus->servo(0).physicalPosition() != bus->servo(1).physicalPosition());
        const auto position = bus->handleFrame(feetech::read(1, 56, 2), k1M, kMs);
        QCOMPARE(position.size(), 1);
        QVERIFY(!feetech::decodePacket(position.first().bytes));
    }

    void servosPluggedInAndOutWhileRunningAnswerOnlyWhilePresent()
    {
        VirtualFeetechBus bus(Specs {{1, QStringLiteral("STS3215"), 0}});
        SimRefusal why;
        QVERIFY(!bus.plug({7, QStringLiteral("NoSuchServo"), 0}, &why));
        QCOMPARE(why.code(), SimRefusal::Code::UnknownModel);
        QCOMPARE(why.name(), QStringLiteral("NoSuchServo"));
        QVERIFY2(bus.plug({7, QStringLiteral("STS3215"), 0}, &why), qPrintable(why.describe()));
        QCOMPARE(bus.servoCount(), 2);
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(7), k1M, 0)), QVector<quint8> {7});
        QVERIFY(bus.plug({1, QStringLiteral("STS3215"), 0}, &why)); // a second ID 1
        QVERIFY(!feetech::decodePacket(
            bus.handleFrame(feetech::read(1, 56, 2), k1M, kMs).first().bytes));

        QVERIFY(!bus.unplug(3));
        QVERIFY(bus.unplug(0));
        QCOMPARE(bus.servoCount(), 2);
        QCOMPARE(bus.servo(0).id(), 7);
        QVERIFY(feetech::decodePacket(
            bus.handleFrame(feetech::read(1, 56, 2), k1M, 2 * kMs).first().bytes));
        QVERIFY(bus.unplug(0));
        QVERIFY(bus.handleFrame(feetech::ping(7), k1M, 3 * kMs).isEmpty());
    }

    void collisionPadsToTheLongestFrame()
    {
        const QByteArray wire = VirtualFeetechBus::collide(
            {QByteArray::fromHex("F0F0"), QByteArray::fromHex("3C3C3C")});
        QCOMPARE(wire.toHex(), QByteArray("30303c"));
    }

    void baudChangeRepliesAtTheOldBaudThenAnswersOnlyAtTheNewOne()
    {
        VirtualFeetechBus bus(mixedSpecs());
        const auto replies = bus.handleFrame(feetech::write(1, 6, byte(4)), k1M, 0);
        QCOMPARE(replyIds(replies), QVector<quint8> {1}); // the 1 Mbps host heard it
        QVERIFY(bus.handleFrame(feetech::ping(1), k1M, 10).isEmpty());
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(1), k115k, 20)), QVector<quint8> {1});
    }

    void rebootIsSilentDuringTheRebootTimeThenAnswersAgain()
    {
        VirtualFeetechBus bus(mixedSpecs());
        QVERIFY(bus.handleFrame(feetech::reboot(1), k1M, 1000 * kMs).isEmpty());
        QVERIFY(bus.handleFrame(feetech::ping(1), k1M, 1100 * kMs).isEmpty());
        QVERIFY(bus.handleFrame(feetech::ping(1), k1M, 1499 * kMs).isEmpty());
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(3), k1M, 1499 * kMs)), QVector<quint8> {3});
        const qint64 after = 1000 * kMs + VirtualFeetechBus::kRebootTimeUs;
        QCOMPARE(replyIds(bus.handleFrame(feetech::ping(1), k1M, after)), QVector<quint8> {1});
    }

    void turnaroundIsTheServosReturnDelay()
    {
        VirtualFeetechBus bus(mixedSpecs());
        bus.handleFrame(feetech::write(1, 7, byte(250)), k1M, 0);
        QCOMPARE(bus.handleFrame(feetech::ping(1), k1M, 0).value(0).turnaroundUs, qint64(500));
        QCOMPARE(bus.handleFrame(feetech::ping(4), k115k, 0).value(0).turnaroundUs, qint64(100));
        QCOMPARE(bus.handleFrame(feetech::ping(3), k1M, 0).value(0).turnaroundUs, qint64(0));
    }

    void unlockedIdChangeSurvivesSaveNewBusAndLoad()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("state.json"));
        {
            VirtualFeetechBus bus(mixedSpecs());
            bus.handleFrame(feetech::write(1, 55, byte(0)), k1M, 0);
            const auto replies = bus.handleFrame(feetech::write(1, 5, byte(10)), k1M, 0);
            QCOMPARE(replyIds(replies), QVector<quint8> {1});
            bus.handleFrame(feetech::write(2, 5, byte(20)), k1M, 0); // locked: lost
            SimRefusal why;
            QVERIFY2(bus.saveState(path, &why), qPrintable(why.describe()));
        }
        VirtualFeetechBus restarted(mixedSpecs());
        SimRefusal why;
        QVERIFY2(restarted.loadState(path, &why), qPrintable(why.describe()));
        QVERIFY(restarted.handleFrame(feetech::ping(1), k1M, 0).isEmpty());
        QCOMPARE(replyIds(restarted.handleFrame(feetech::ping(10), k1M, 0)), QVector<quint8> {10});
        QCOMPARE(replyIds(restarted.handleFrame(feetech::ping(2), k1M, 0)), QVector<quint8> {2});
        QCOMPARE(restarted.servo(0).value(u"lock"), 1);
    }

    void statePathSavesAutomaticallyWhenAnImageChanges()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("auto.json"));
        VirtualFeetechBus bus(mixedSpecs());
        bus.setStatePath(path);
        bus.handleFrame(feetech::write(1, 13, byte(60)), k1M, 0); // locked: no change
        QVERIFY(!QFile::exists(path));
        bus.handleFrame(feetech::write(1, 55, byte(0)), k1M, 0);
        bus.handleFrame(feetech::write(1, 13, byte(60)), k1M, 0);
        QVERIFY(QFile::exists(path));

        VirtualFeetechBus restarted(mixedSpecs());
        SimRefusal why;
        QVERIFY2(restarted.loadState(path, &why), qPrintable(why.describe()));
        QCOMPARE(restarted.servo(0).value(u"max_temperature"), 60);
    }

    void loadRejectsAFileWhoseModelsDiffer()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("state.json"));
        VirtualFeetechBus saved(mixedSpecs());
        QVERIFY(saved.saveState(path, nullptr));

        Specs other = mixedSpecs();
        other[1].model = QStringLiteral("SCS40");
        VirtualFeetechBus bus(other);
        SimRefusal why;
        QVERIFY(!bus.loadState(path, &why));
        QCOMPARE(why.code(), SimRefusal::Code::StateModelDiffers);
        QCOMPARE(why.name(), QStringLiteral("SCS15"));

        VirtualFeetechBus shorter(Specs {{1, QStringLiteral("STS3215"), 0}});
        QVERIFY(!shorter.loadState(path, &why));
        QCOMPARE(why.code(), SimRefusal::Code::StateServoCount);
    }

    void loadRejectsAFileThatIsNoState()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("broken.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QJsonDocument(QJsonObject {{QStringLiteral("format"), 2}}).toJson());
        file.close();
        VirtualFeetechBus bus(mixedSpecs());
        SimRefusal why;
        QVERIFY(!bus.loadState(path, &why));
        QCOMPARE(why.code(), SimRefusal::Code::StateNotThisFormat);
        QVERIFY(!why.describe().isEmpty());
        QVERIFY(!bus.loadState(dir.filePath(QStringLiteral("missing.json")), &why));
        QCOMPARE(why.code(), SimRefusal::Code::CannotReadState);
    }

    void aStateIsReadFromTextAsFromItsFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("state.json"));
        VirtualFeetechBus saved(mixedSpecs());
        saved.handleFrame(feetech::write(1, 55, byte(0)), k1M, 0);
        saved.handleFrame(feetech::write(1, 13, byte(60)), k1M, 0);
        QVERIFY(saved.saveState(path, nullptr));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll(), saved.stateJson()); // the file holds exactly the text

        VirtualFeetechBus fromText(mixedSpecs());
        SimRefusal why;
        QVERIFY2(fromText.loadStateJson(saved.stateJson(), path, &why), qPrintable(why.describe()));
        QCOMPARE(fromText.servo(0).value(u"max_temperature"), 60);
        QCOMPARE(fromText.stateJson(), saved.stateJson());
    }

    void aRefusedStateTextChangesNothingAndNamesTheFile()
    {
        VirtualFeetechBus bus(mixedSpecs());
        const QByteArray before = bus.stateJson();
        QByteArray wrongImage = before;
        wrongImage.replace("\"eeprom\": \"", "\"eeprom\": \"zz");
        for (const QByteArray &text : {QByteArray("{\"format\": 1, \"servos\": ["), wrongImage}) {
            SimRefusal why;
            QVERIFY(!bus.loadStateJson(text, QStringLiteral("bench.json"), &why));
            QCOMPARE(why.file(), QStringLiteral("bench.json"));
            QVERIFY2(why.describe().startsWith(QStringLiteral("state file bench.json: ")),
                     qPrintable(why.describe()));
            QCOMPARE(bus.stateJson(), before);
        }
    }

    void validationRejectsBadSpecs_data()
    {
        QTest::addColumn<Specs>("specs");
        QTest::addColumn<SimRefusal::Code>("code");
        QTest::addColumn<QString>("mention");
        QTest::newRow("unknown model")
            << Specs {{1, QStringLiteral("XYZ123"), 0}} << SimRefusal::Code::UnknownModel
            << QStringLiteral("XYZ123");
        QTest::newRow("model without a table")
            << Specs {{1, QStringLiteral("SCS15-2"), 0}} << SimRefusal::Code::NoRegisterTable
            << QStringLiteral("SCS15-2");
        QTest::newRow("duplicate id at one baud")
            << Specs {{5, QStringLiteral("STS3215"), 0}, {5, QStringLiteral("SCS15"), 1000000}}
            << SimRefusal::Code::IdTaken << QStringLiteral("5");
        QTest::newRow("id 254") << Specs {{254, QStringLiteral("STS3215"), 0}}
                                << SimRefusal::Code::IdOutOfRange << QStringLiteral("254");
        QTest::newRow("bad baud") << Specs {{1, QStringLiteral("STS3215"), 9600}}
                                  << SimRefusal::Code::NotAFeetechRate << QStringLiteral("9600");
        QTest::newRow("no servos") << Specs {} << SimRefusal::Code::NoServos << QString();
    }

    void validationRejectsBadSpecs()
    {
        QFETCH(Specs, specs);
        QFETCH(SimRefusal::Code, code);
        QFETCH(QString, mention);
        SimRefusal why;
        QVERIFY(!VirtualFeetechBus::validate(specs, &why));
        QCOMPARE(why.code(), code);
        QVERIFY(why.describe().contains(mention)); // the sentence names what is wrong
        QVERIFY(!why.describe().isEmpty());
        QVERIFY(!VirtualFeetechBus::create(specs, nullptr));
    }

    void validationAcceptsOneIdAtTwoBauds()
    {
        const Specs specs {{5, QStringLiteral("STS3215"), 0},
                           {5, QStringLiteral("STS3215"), 500000}};
        SimRefusal why;
        QVERIFY2(VirtualFeetechBus::validate(specs, &why), qPrintable(why.describe()));
        QVERIFY(VirtualFeetechBus::validate(mixedSpecs(), &why));
        QVERIFY(VirtualFeetechBus::create(specs, &why));
    }

    void modelsResolveByNameNumberOrFamily()
    {
        QCOMPARE(VirtualFeetechBus::resolveModel(u"sts3215")->name, QStringLiteral("STS3215"));
        QCOMPARE(VirtualFeetechBus::resolveModel(u"9/3")->name, QStringLiteral("STS3215"));
        QCOMPARE(*VirtualFeetechBus::resolveModel(u"10/2")->family, feetech::Family::Hls);
        QCOMPARE(*VirtualFeetechBus::resolveModel(u"hls")->family, feetech::Family::Hls);
        QVERIFY(!VirtualFeetechBus::resolveModel(u"6/3")); // SM-CL: no table
    }

    void hlsSecondaryIdExecutesWritesSilently()
    {
        VirtualFeetechBus bus(mixedSpecs());
        bus.handleFrame(feetech::write(3, 7, byte(40)), k1M, 0);
        QVERIFY(bus.handleFrame(feetech::write(40, 42, littleEndian(1234)), k1M, 0).isEmpty());
        QCOMPARE(bus.findServo(3)->value(u"goal_position"), 1234);
        QVERIFY(bus.handleFrame(feetech::ping(40), k1M, 0).isEmpty());
    }

    void powerCycleReloadsEveryServo()
    {
        VirtualFeetechBus bus(mixedSpecs());
        bus.handleFrame(feetech::write(1, 5, byte(9)), k1M, 0);
        QVERIFY(bus.findServo(9));
        bus.powerCycle();
        QVERIFY(!bus.findServo(9));
        QVERIFY(bus.findServo(1));
    }
};

QTEST_APPLESS_MAIN(TestVirtualFeetechBus)
#include "tst_virtualfeetechbus.moc"
