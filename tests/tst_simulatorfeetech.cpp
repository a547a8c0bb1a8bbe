// End to end over a real pty: the simulated Feetech bus as a QSerialPort client sees it.
#include "simclient.h"

#include "feetechpacket.h"
#include "feetechvalue.h"
#include "hex.h"
#include "registertable.h"
#include "simulatorthread.h"
#include "virtualfeetechbus.h"
#include "virtualfeetechservo.h"

#include <QtTest>

using testsupport::PortClient;
namespace ft = feetech;

namespace {

constexpr qint32 k1M = 1000000;

// Reads one status packet from what came back; nothing when it is not exactly one packet.
std::optional<ft::Packet> onePacket(const QByteArray &bytes)
{
    return ft::decodePacket(bytes);
}

} // namespace

class TestSimulatorFeetech : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    int m_runs = 0;

    // STS3215 #1, SCS15 #2 (big-endian), HLS #3 at 1 Mbps; an SMS (SM-BL) #4 at 115200.
    sim::SimulatorOptions mixedBus()
    {
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Feetech;
        options.linkPath = m_dir.filePath(QStringLiteral("bus%1").arg(++m_runs));
        options.logPath = options.linkPath + QStringLiteral(".log");
        options.servos = {{1, QStringLiteral("STS3215"), k1M},
                          {2, QStringLiteral("SCS15"), k1M},
                          {3, QStringLiteral("HLSxx"), k1M},
                          {4, QStringLiteral("SM40BLHV"), 115200}};
        return options;
    }

    // A request that expects one status packet of `dataLength` bytes back.
    static std::optional<ft::Packet> ask(PortClient &client, const QByteArray &request,
                                         int dataLength = 0)
    {
        const QByteArray reply = client.exchange(request, dataLength + ft::kMinimumPacketSize);
        return onePacket(reply);
    }

    static qint32 readValue(PortClient &client, quint8 id, ft::Family family, QStringView key)
    {
        const ft::RegisterTable &table = ft::RegisterTable::forFamily(family);
        const ft::Register *reg = table.find(key);
        if (!reg)
            return INT_MIN;
        const auto reply =
            ask(client, ft::read(id, quint8(reg->address), quint8(reg->size)), reg->size);
        if (!reply || reply->id != id || reply->parameters.size() != reg->size)
            return INT_MIN;
        return ft::decodeValue(reply->parameters, table.format(*reg));
    }

    static QByteArray writeBytes(ft::Family family, QStringView key, qint32 value, quint8 *address)
    {
        const ft::RegisterTable &table = ft::RegisterTable::forFamily(family);
        const ft::Register *reg = table.find(key);
        *address = quint8(reg->address);
        return ft::encodeValue(value, table.format(*reg)).value_or(QByteArray());
    }

    static bool writeValue(PortClient &client, quint8 id, ft::Family family, QStringView key,
                           qint32 value)
    {
        quint8 address = 0;
        const QByteArray data = writeBytes(family, key, value, &address);
        const auto reply = ask(client, ft::write(id, address, data));
        return reply && reply->id == id && reply->parameters.isEmpty();
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void everyServoAnswersPingOnlyAtItsOwnBaud()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        for (quint8 id : {1, 2, 3}) {
            const auto reply = ask(client, ft::ping(id));
            QVERIFY2(reply.has_value(), qPrintable(QString::number(id)));
            QCOMPARE(reply->id, id);
            QCOMPARE(reply->code, quint8(0));
        }
        // #4 is at 115200: silence at 1 Mbps, proven by the next reply arriving alone.
        client.received().clear();
        client.send(ft::ping(4) + ft::ping(1));
        QVERIFY(client.waitFor(6));
        QCOMPARE(client.received(), ft::status(1, 0));
        QVERIFY(client.setBaud(115200));
        const auto sms = ask(client, ft::ping(4));
        QVERIFY(sms.has_value());
        QCOMPARE(sms->id, quint8(4));
    }

    void readsComeInEachFamilysByteOrder()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        // Model at 3-4 and the END flag at 2, as a scan reads them.
        const auto sts = ask(client, ft::read(1, 2, 3), 3);
        QVERIFY(sts.has_value());
        QCOMPARE(sts->parameters, QByteArray::fromHex("000903"));
        const auto scs = ask(client, ft::read(2, 2, 3), 3);
        QVERIFY(scs.has_value());
        QCOMPARE(scs->parameters, QByteArray::fromHex("01050f"));
        // Max angle limit: 4095 little-endian on STS, 1003 big-endian on SCS.
        const auto stsLimit = ask(client, ft::read(1, 11, 2), 2);
        QVERIFY(stsLimit.has_value());
        QCOMPARE(stsLimit->parameters, QByteArray::fromHex("ff0f"));
        const auto scsLimit = ask(client, ft::read(2, 11, 2), 2);
        QVERIFY(scsLimit.has_value());
        QCOMPARE(scsLimit->parameters, QByteArray::fromHex("03eb"));
        QCOMPARE(readValue(client, 3, ft::Family::Hls, u"max_angle_limit"), 4095);
    }

    void writeThenReadOnEveryFamily()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"goal_speed", -1200));
        QCOMPARE(readValue(client, 1, ft::Family::Sts, u"goal_speed"), -1200);
        QVERIFY(writeValue(client, 2, ft::Family::Scs, u"goal_position", 700));
        QCOMPARE(readValue(client, 2, ft::Family::Scs, u"goal_position"), 700);
        QVERIFY(writeValue(client, 3, ft::Family::Hls, u"goal_position", 1234));
        QCOMPARE(readValue(client, 3, ft::Family::Hls, u"goal_position"), 1234);
        QVERIFY(client.setBaud(115200));
        QVERIFY(writeValue(client, 4, ft::Family::Sms, u"acceleration", 20));
        QCOMPARE(readValue(client, 4, ft::Family::Sms, u"acceleration"), 20);
    }

    void regWriteWaitsForActionAndSyncWriteNeedsNoReply()
    {
        sim::SimulatorThread simulator;
        QString error;
        const auto options = mixedBus();
        QVERIFY2(simulator.start(options, &error), qPrintable(error));
        PortClient client;
        QVERIFY(client.open(simulator.linkPath(), k1M));
        quint8 address = 0;
        const QByteArray speed = writeBytes(ft::Family::Sts, u"goal_speed", 900, &address);
        QVERIFY(ask(client, ft::regWrite(1, address, speed)).has_value());
        QCOMPARE(readValue(client, 1, ft::Family::Sts, u"goal_speed"), 0);
        client.send(ft::action());
        QCOMPARE(readValue(client, 1, ft::Family::Sts, u"goal_speed"), 900);

        // SYNC WRITE of goal speed to #1 and #3 (both little-endian): no reply, both changed.
        const auto sync = ft::syncWrite(address, 2,
                                        {{1, ft::encodeRaw(300, 2, ft::ByteOrder::Little)},
                                         {3, ft::encodeRaw(400, 2, ft::ByteOrder::Little)}});
        QVERIFY(sync.has_value());
        client.send(*sync);
        QCOMPARE(readValue(client, 1, ft::Family::Sts, u"goal_speed"), 300);
        QCOMPARE(readValue(client, 3, ft::Family::Hls, u"goal_speed"), 400);
        // The log shows no reply between the SYNC WRITE and the next READ.
        const QStringList lines = testsupport::logLines(options.logPath);
        const int syncAt = lines.indexOf(QStringLiteral("in ") + util::toHex(*sync));
        QVERIFY(syncAt >= 0);
        QVERIFY(lines.at(syncAt + 1).startsWith(QStringLiteral("in ")));
    }

    void everyInstructionWorksOnEveryFamily_data()
    {
        QTest::addColumn<int>("id");
        QTest::addColumn<int>("family");
        QTest::addColumn<int>("baud");
        QTest::addColumn<bool>("calibrates"); // 0x0B: STS fw >= 3.10 and HLS fw >= 3.43 only
        QTest::newRow("STS3215") << 1 << int(ft::Family::Sts) << k1M << true;
        QTest::newRow("SCS15") << 2 << int(ft::Family::Scs) << k1M << false;
        QTest::newRow("HLS") << 3 << int(ft::Family::Hls) << k1M << true;
        QTest::newRow("SMS") << 4 << int(ft::Family::Sms) << 115200 << false;
    }
    void everyInstructionWorksOnEveryFamily()
    {
        QFETCH(int, id);
        QFETCH(int, family);
        QFETCH(int, baud);
        QFETCH(bool, calibrates);
        const auto servoFamily = ft::Family(family);
        const quint8 servo = quint8(id);
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), baud), qPrintable(simulator.error));
        PortClient &client = simulator.client;

        QCOMPARE(ask(client, ft::ping(servo))->id, servo);
        QVERIFY(writeValue(client, servo, servoFamily, u"goal_position", 600));
        QCOMPARE(readValue(client, servo, servoFamily, u"goal_position"), 600);
        quint8 address = 0;
        const QByteArray data = writeBytes(servoFamily, u"goal_position", 650, &address);
        QVERIFY(ask(client, ft::regWrite(servo, address, data)).has_value());
        QCOMPARE(readValue(client, servo, servoFamily, u"goal_position"), 600);
        client.send(ft::action());
        QCOMPARE(readValue(client, servo, servoFamily, u"goal_position"), 650);
        QVERIFY(ask(client, ft::reset(servo)).has_value());
        QVERIFY(writeValue(client, servo, servoFamily, u"max_temperature", 50));
        QVERIFY(ask(client, ft::recovery(servo)).has_value());
        QVERIFY(readValue(client, servo, servoFamily, u"max_temperature") != 50);
        client.received().clear();
        client.send(ft::calibrate(servo) + ft::ping(servo));
        QVERIFY(client.waitFor(calibrates ? 12 : 6));
        QCOMPARE(client.received().size(), calibrates ? 12 : 6);
        client.received().clear();
        client.send(ft::reboot(servo));
        QVERIFY(QTest::qWaitFor(
            [&] { return client.exchange(ft::ping(servo), 6, 50) == ft::status(servo, 0); }, 5000));
    }

    void syncReadAnswersInListOrderSkippingMissingAndScsServos()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        // Present voltage (62) and temperature (63) of #3, a missing #9, SCS #2 and #1.
        client.received().clear();
        client.send(ft::syncRead(62, 2, {3, 9, 2, 1}) + ft::ping(1));
        QVERIFY(client.waitFor(8 + 8 + 6));
        const ft::FrameFormat format;
        seriallink::StreamFramer reader(format);
        reader.append(client.received());
        QList<quint8> ids;
        while (auto item = reader.next()) {
            QCOMPARE(item->kind, seriallink::StreamItem::Kind::Frame);
            ids.append(quint8(item->bytes[2]));
        }
        QCOMPARE(ids, (QList<quint8> {3, 1, 1})); // #3, #1, then the PING's reply
    }

    void eepromWritesPersistOnlyWhenUnlockedAcrossAPowerCycle()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        for (const auto &[id, family] :
             {std::pair {quint8(1), ft::Family::Sts}, std::pair {quint8(2), ft::Family::Scs}}) {
            const qint32 original = readValue(client, id, family, u"max_temperature");
            QVERIFY(writeValue(client, id, family, u"max_temperature", 60)); // locked
            QCOMPARE(readValue(client, id, family, u"max_temperature"), 60);
            simulator.simulator.call([](sim::Simulator &s) { s.powerCycle(); });
            QCOMPARE(readValue(client, id, family, u"max_temperature"), original);

            QVERIFY(writeValue(client, id, family, u"lock", 0));
            QVERIFY(writeValue(client, id, family, u"max_temperature", 61));
            QVERIFY(writeValue(client, id, family, u"lock", 1));
            simulator.simulator.call([](sim::Simulator &s) { s.powerCycle(); });
            QCOMPARE(readValue(client, id, family, u"max_temperature"), 61);
        }
    }

    void anIdChangeIsAnsweredFromTheOldIdThenTheServoAnswersAtTheNewOne()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"lock", 0));
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"id", 7)); // reply from ID 1
        QVERIFY(writeValue(client, 7, ft::Family::Sts, u"lock", 1));
        QCOMPARE(ask(client, ft::ping(7))->id, quint8(7));
        client.received().clear();
        client.send(ft::ping(1) + ft::ping(2));
        QVERIFY(client.waitFor(6));
        QCOMPARE(client.received(), ft::status(2, 0)); // #1 is gone
    }

    void aBaudChangeIsFollowedAndTheOldRateGetsSilence()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"baud_rate", 1)); // code 1 = 500000
        client.received().clear();
        client.send(ft::ping(1) + ft::ping(2));
        QVERIFY(client.waitFor(6));
        QCOMPARE(client.received(), ft::status(2, 0));
        QVERIFY(client.setBaud(500000));
        const auto moved = ask(client, ft::ping(1));
        QVERIFY(moved.has_value());
        QCOMPARE(moved->id, quint8(1));
    }

    void aHostAtTheWrongBaudGetsSilence()
    {
        sim::SimulatorThread simulator;
        QString error;
        auto options = mixedBus();
        QVERIFY2(simulator.start(options, &error), qPrintable(error));
        PortClient client;
        QVERIFY(client.open(simulator.linkPath(), 250000));
        client.send(ft::ping(1));
        QTRY_COMPARE(
            testsupport::logLinesStartingWith(options.logPath, QStringLiteral("in")).size(), 1);
        QVERIFY(client.setBaud(k1M));
        QCOMPARE(client.exchange(ft::ping(2), 6), ft::status(2, 0));
    }

    void echoModeReturnsTheInstructionBeforeTheStatus()
    {
        sim::SimulatorThread simulator;
        QString error;
        auto options = mixedBus();
        options.echo = true;
        QVERIFY2(simulator.start(options, &error), qPrintable(error));
        PortClient client;
        QVERIFY(client.open(simulator.linkPath(), k1M));
        QCOMPARE(client.exchange(ft::ping(1), 12), ft::ping(1) + ft::status(1, 0));
    }

    void rebootIsSilentThenTheServoAnswersAgain()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        client.received().clear();
        client.send(ft::reboot(1) + ft::ping(2));
        QVERIFY(client.waitFor(6));
        QCOMPARE(client.received(), ft::status(2, 0));
        QVERIFY(QTest::qWaitFor(
            [&] { return client.exchange(ft::ping(1), 6, 50) == ft::status(1, 0); }, 5000));
    }

    void recoveryResetAndCalibrateAnswerWithAStatus()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"max_temperature", 55));
        QVERIFY(ask(client, ft::recovery(1)).has_value());
        QCOMPARE(readValue(client, 1, ft::Family::Sts, u"max_temperature"), 70);
        QCOMPARE(ask(client, ft::ping(1))->id, quint8(1)); // the ID survives recovery
        QVERIFY(ask(client, ft::reset(1)).has_value());
        QVERIFY(ask(client, ft::calibrate(1)).has_value());
        QCOMPARE(readValue(client, 1, ft::Family::Sts, u"present_position"), 2048);
    }

    void withTorqueOnTheHornMovesToTheGoal()
    {
        testsupport::ConnectedSimulator simulator;
        QVERIFY2(simulator.start(mixedBus(), k1M), qPrintable(simulator.error));
        PortClient &client = simulator.client;
        const qint32 start = readValue(client, 1, ft::Family::Sts, u"present_position");
        const qint32 goal = start > 2048 ? start - 1000 : start + 1000;
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"goal_speed", 3000));
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"torque_enable", 1));
        QVERIFY(writeValue(client, 1, ft::Family::Sts, u"goal_position", goal));
        QVERIFY(QTest::qWaitFor(
            [&] { return readValue(client, 1, ft::Family::Sts, u"moving") == 1; }, 2000));
        QVERIFY(QTest::qWaitFor(
            [&] {
                return std::abs(readValue(client, 1, ft::Family::Sts, u"present_position") - goal)
                    <= 1;
            },
            5000));
        QTRY_COMPARE(readValue(client, 1, ft::Family::Sts, u"moving"), 0);
    }

    void theStateFileKeepsAnUnlockedIdChangeAcrossRuns()
    {
        auto options = mixedBus();
        options.statePath = m_dir.filePath(QStringLiteral("state.json"));
        QString error;
        {
            sim::SimulatorThread simulator;
            QVERIFY2(simulator.start(options, &error), qPrintable(error));
            PortClient client;
            QVERIFY(client.open(simulator.linkPath(), k1M));
            QVERIFY(writeValue(client, 2, ft::Family::Scs, u"lock", 0));
            QVERIFY(writeValue(client, 2, ft::Family::Scs, u"id", 12));
            QVERIFY(writeValue(client, 12, ft::Family::Scs, u"lock", 1));
        }
        sim::SimulatorThread again;
        QVERIFY2(again.start(options, &error), qPrintable(error));
        PortClient client;
        QVERIFY(client.open(again.linkPath(), k1M));
        QCOMPARE(ask(client, ft::ping(12))->id, quint8(12));
    }
};

QTEST_GUILESS_MAIN(TestSimulatorFeetech)
#include "tst_simulatorfeetech.moc"
