// Tests the Feetech packet encoders and decoder against the seed's and the spec's hex frames.
#include "feetechpacket.h"

#include <QtTest>

using feetech::Instruction;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(text);
}

// The WRITE / REG WRITE payload of seed examples 4 and 5: position 2048, time 0, speed 1000,
// low byte first.
QByteArray goal2048At1000()
{
    return hex("00080000E803");
}

} // namespace

class TestFeetechPacket : public QObject
{
    Q_OBJECT

private slots:
    void pingForIdOneMatchesTheSeedExample() { QCOMPARE(feetech::ping(1), hex("FFFF010201FB")); }

    void pingReplyForIdOneMatchesTheSeedExample()
    {
        QCOMPARE(feetech::status(1, 0), hex("FFFF010200FC"));
    }

    void readOfPresentPositionMatchesTheSeedExample()
    {
        QCOMPARE(feetech::read(1, 0x38, 2), hex("FFFF0104023802BE"));
    }

    void readReplyCarryingPosition1304MatchesTheSeedExample()
    {
        QCOMPARE(feetech::status(1, 0, hex("1805")), hex("FFFF0104001805DD"));
    }

    void broadcastWriteOfIdOneMatchesTheSeedExample()
    {
        QCOMPARE(feetech::write(feetech::kBroadcastId, 0x05, hex("01")), hex("FFFFFE04030501F4"));
    }

    void writeOfGoalPositionAndSpeedMatchesTheSeedExample()
    {
        QCOMPARE(feetech::write(1, 0x2A, goal2048At1000()), hex("FFFF0109032A00080000E803D5"));
    }

    void regWriteMatchesTheCorrectedSeedFrames_data()
    {
        QTest::addColumn<int>("id");
        QTest::addColumn<QByteArray>("expected");
        // IDs 1-6 are the seed's frames as printed. The seed's lines for 7 to 10 are wrong: 7, 9
        // and 10 carry the ID bytes 08, 0A, 0A, and the "ID 8" line ends in CE, which is the
        // checksum for ID 7. The frames below are recomputed as ~sum.
        QTest::newRow("id 1") << 1 << hex("FFFF0109042A00080000E803D4");
        QTest::newRow("id 2") << 2 << hex("FFFF0209042A00080000E803D3");
        QTest::newRow("id 3") << 3 << hex("FFFF0309042A00080000E803D2");
        QTest::newRow("id 4") << 4 << hex("FFFF0409042A00080000E803D1");
        QTest::newRow("id 5") << 5 << hex("FFFF0509042A00080000E803D0");
        QTest::newRow("id 6") << 6 << hex("FFFF0609042A00080000E803CF");
        QTest::newRow("id 7") << 7 << hex("FFFF0709042A00080000E803CE");
        QTest::newRow("id 8") << 8 << hex("FFFF0809042A00080000E803CD");
        QTest::newRow("id 9") << 9 << hex("FFFF0909042A00080000E803CC");
        QTest::newRow("id 10") << 10 << hex("FFFF0A09042A00080000E803CB");
    }

    void regWriteMatchesTheCorrectedSeedFrames()
    {
        QFETCH(int, id);
        QFETCH(QByteArray, expected);
        QCOMPARE(feetech::regWrite(quint8(id), 0x2A, goal2048At1000()), expected);
    }

    void actionGoesToTheBroadcastIdByDefault() { QCOMPARE(feetech::action(), hex("FFFFFE0205FA")); }

    void syncWriteOfFourServosMatchesTheSeedExample()
    {
        QVector<feetech::SyncWriteEntry> entries;
        for (quint8 id = 1; id <= 4; ++id)
            entries.append({id, goal2048At1000()});
        const auto frame = feetech::syncWrite(0x2A, 6, entries);
        QVERIFY(frame.has_value());
        QCOMPARE(frame->size(), 36);
        QCOMPARE(*frame,
                 hex("FFFFFE20832A06"
                     "0100080000E803"
                     "0200080000E803"
                     "0300080000E803"
                     "0400080000E803"
                     "58"));
    }

    void syncWriteRejectsAnEntryOfTheWrongLength()
    {
        const QVector<feetech::SyncWriteEntry> shortEntry {{1, goal2048At1000()}, {2, hex("0008")}};
        QVERIFY(!feetech::syncWrite(0x2A, 6, shortEntry).has_value());
        const QVector<feetech::SyncWriteEntry> longEntry {{1, goal2048At1000() + hex("00")}};
        QVERIFY(!feetech::syncWrite(0x2A, 6, longEntry).has_value());
    }

    void syncWriteRefusesAFrameLongerThanTheSdkLimit()
    {
        // 2 + 34 * 7 parameters make a 246-byte frame; one more entry makes 253 > 250.
        QVector<feetech::SyncWriteEntry> entries;
        for (quint8 id = 1; id <= 34; ++id)
            entries.append({id, goal2048At1000()});
        const auto fits = feetech::syncWrite(0x2A, 6, entries);
        QVERIFY(fits.has_value());
        QCOMPARE(fits->size(), 246);
        entries.append({35, goal2048At1000()});
        QVERIFY(!feetech::syncWrite(0x2A, 6, entries).has_value());
    }

    void recoveryForIdZeroIsTheCorrectedSeedFrame()
    {
        // The seed's table for ID 0 says F7; its frame line is the ID 1 frame.
        QCOMPARE(feetech::recovery(0), hex("FFFF000206F7"));
    }

    void recoveryForIdOneMatchesTheSeedFrameLine()
    {
        QCOMPARE(feetech::recovery(1), hex("FFFF010206F6"));
    }

    void calibrateIdOneTo1024MatchesTheSpecExample()
    {
        QCOMPARE(feetech::calibrate(1, hex("0004")), hex("FFFF01040B0004EB"));
    }

    void calibrateWithoutParameterIsABareInstruction()
    {
        QCOMPARE(feetech::calibrate(1), hex("FFFF01020BF1"));
    }

    void rebootUsesInstructionEight()
    {
        QCOMPARE(feetech::reboot(1), hex("FFFF010208F4"));
        QCOMPARE(feetech::reboot(feetech::kBroadcastId), hex("FFFFFE0208F7"));
    }

    void resetUsesInstructionTenNotSix() { QCOMPARE(feetech::reset(1), hex("FFFF01020AF2")); }

    void syncReadListsTheIdsAfterAddressAndLength_data()
    {
        QTest::addColumn<QByteArray>("ids");
        QTest::addColumn<quint8>("length");
        QTest::addColumn<QByteArray>("expected");
        QTest::newRow("one servo") << hex("01") << quint8(2) << hex("FFFFFE05823802013F");
        QTest::newRow("three servos")
            << hex("010203") << quint8(2) << hex("FFFFFE0782380201020338");
        QTest::newRow("ten servos, feedback block") << hex("0102030405060708090A") << quint8(15)
                                                    << hex("FFFFFE0E82380F0102030405060708090AF3");
    }

    void syncReadListsTheIdsAfterAddressAndLength()
    {
        QFETCH(QByteArray, ids);
        QFETCH(quint8, length);
        QFETCH(QByteArray, expected);
        QVector<quint8> idList;
        for (const char id : ids)
            idList.append(quint8(id));
        const QByteArray frame = feetech::syncRead(0x38, length, idList);
        QCOMPARE(frame, expected);
        QCOMPARE(int(quint8(frame.at(3))), ids.size() + 4); // LEN = n + 4
        QCOMPARE(quint8(frame.at(2)), feetech::kBroadcastId);
    }

    void decodePacketRoundTripsEveryReferenceFrame_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::addColumn<quint8>("id");
        QTest::addColumn<quint8>("code");
        QTest::addColumn<QByteArray>("parameters");
        QTest::newRow("ping") << hex("FFFF010201FB") << quint8(1) << quint8(0x01) << QByteArray();
        QTest::newRow("ping reply")
            << hex("FFFF010200FC") << quint8(1) << quint8(0x00) << QByteArray();
        QTest::newRow("read") << hex("FFFF0104023802BE") << quint8(1) << quint8(0x02)
                              << hex("3802");
        QTest::newRow("read reply")
            << hex("FFFF0104001805DD") << quint8(1) << quint8(0x00) << hex("1805");
        QTest::newRow("broadcast write")
            << hex("FFFFFE04030501F4") << quint8(0xFE) << quint8(0x03) << hex("0501");
        QTest::newRow("write") << hex("FFFF0109032A00080000E803D5") << quint8(1) << quint8(0x03)
                               << hex("2A00080000E803");
        QTest::newRow("reg write id 10") << hex("FFFF0A09042A00080000E803CB") << quint8(10)
                                         << quint8(0x04) << hex("2A00080000E803");
        QTest::newRow("action") << hex("FFFFFE0205FA") << quint8(0xFE) << quint8(0x05)
                                << QByteArray();
        QTest::newRow("sync write")
            << hex("FFFFFE20832A060100080000E8030200080000E803"
                   "0300080000E8030400080000E80358")
            << quint8(0xFE) << quint8(0x83)
            << hex("2A060100080000E8030200080000E8030300080000E8030400080000E803");
        QTest::newRow("recovery id 0")
            << hex("FFFF000206F7") << quint8(0) << quint8(0x06) << QByteArray();
        QTest::newRow("calibrate 1024")
            << hex("FFFF01040B0004EB") << quint8(1) << quint8(0x0B) << hex("0004");
        QTest::newRow("sync read")
            << hex("FFFFFE0782380201020338") << quint8(0xFE) << quint8(0x82) << hex("3802010203");
        QTest::newRow("status with alarm bits")
            << feetech::status(3, 0x25) << quint8(3) << quint8(0x25) << QByteArray();
    }

    void decodePacketRoundTripsEveryReferenceFrame()
    {
        QFETCH(QByteArray, frame);
        QFETCH(quint8, id);
        QFETCH(quint8, code);
        QFETCH(QByteArray, parameters);
        const auto packet = feetech::decodePacket(frame);
        QVERIFY(packet.has_value());
        QCOMPARE(packet->id, id);
        QCOMPARE(packet->code, code);
        QCOMPARE(packet->parameters, parameters);
        QCOMPARE(feetech::encodePacket(packet->id, packet->code, packet->parameters), frame);
    }

    void decodePacketRejectsMalformedFrames_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::newRow("checksum off by one") << hex("FFFF010201FC");
        QTest::newRow("checksum of the reply on the request") << hex("FFFF0104023802DD");
        // LEN says 7 bytes; the checksum is right for the bytes present.
        QTest::newRow("len too large") << hex("FFFF010301FA");
        // LEN says 6 bytes of an 8-byte frame; the checksum is right for all eight.
        QTest::newRow("len too small") << hex("FFFF0102023802C0");
        QTest::newRow("len below two") << hex("FFFF0101FD");
        QTest::newRow("checksum missing") << hex("FFFF010201");
        QTest::newRow("header only") << hex("FFFF");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("single header byte") << hex("FF010201FB");
        QTest::newRow("trailing byte") << hex("FFFF010201FB00");
    }

    void decodePacketRejectsMalformedFrames()
    {
        QFETCH(QByteArray, frame);
        QVERIFY(!feetech::decodePacket(frame).has_value());
    }

    void checksumIgnoresTheHeader()
    {
        QCOMPARE(feetech::checksum(hex("FFFF010201")), quint8(0xFB));
        QCOMPARE(feetech::checksum(hex("FFFF0104001805")), quint8(0xDD));
    }

    void instructionNameNamesKnownCodes_data()
    {
        QTest::addColumn<quint8>("code");
        QTest::addColumn<QString>("name");
        QTest::newRow("0x01") << quint8(0x01) << QStringLiteral("PING");
        QTest::newRow("0x02") << quint8(0x02) << QStringLiteral("READ");
        QTest::newRow("0x03") << quint8(0x03) << QStringLiteral("WRITE");
        QTest::newRow("0x04") << quint8(0x04) << QStringLiteral("REG WRITE");
        QTest::newRow("0x05") << quint8(0x05) << QStringLiteral("ACTION");
        QTest::newRow("0x06") << quint8(0x06) << QStringLiteral("RECOVERY");
        QTest::newRow("0x08") << quint8(0x08) << QStringLiteral("REBOOT");
        QTest::newRow("0x09") << quint8(0x09) << QStringLiteral("BACKUP");
        QTest::newRow("0x0A") << quint8(0x0A) << QStringLiteral("RESET");
        QTest::newRow("0x0B") << quint8(0x0B) << QStringLiteral("CALIBRATE");
        QTest::newRow("0x82") << quint8(0x82) << QStringLiteral("SYNC READ");
        QTest::newRow("0x83") << quint8(0x83) << QStringLiteral("SYNC WRITE");
    }

    void instructionNameNamesKnownCodes()
    {
        QFETCH(quint8, code);
        QFETCH(QString, name);
        const auto actual = feetech::instructionName(code);
        QVERIFY(actual.has_value());
        QCOMPARE(*actual, name);
    }

    void instructionNameHasNothingForUnknownCodes_data()
    {
        QTest::addColumn<quint8>("code");
        for (const quint8 code : {0x00, 0x07, 0x0C, 0x10, 0x81, 0x84, 0x92, 0xFF})
            QTest::newRow(qPrintable(QStringLiteral("0x%1").arg(code, 2, 16, QLatin1Char('0'))))
                << code;
    }

    void instructionNameHasNothingForUnknownCodes()
    {
        QFETCH(quint8, code);
        QVERIFY(!feetech::instructionName(code).has_value());
    }

    void statusBitNamesListsVoltageTemperatureOverloadFor0x25()
    {
        QCOMPARE(feetech::statusBitNames(0x25),
                 QStringList({QStringLiteral("voltage"), QStringLiteral("temperature"),
                              QStringLiteral("overload")}));
    }

    void statusBitNamesIsEmptyWithoutAlarm()
    {
        QVERIFY(feetech::statusBitNames(0).isEmpty());
        QCOMPARE(feetech::statusBitNames(0x0A),
                 QStringList({QStringLiteral("encoder"), QStringLiteral("current")}));
    }
};

QTEST_APPLESS_MAIN(TestFeetechPacket)
#include "tst_feetechpacket.moc"
