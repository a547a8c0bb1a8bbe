// Tests the packet decoder behind `servoctl decode` on spec streams.
#include "decoder.h"
#include "feetechpacket.h"
#include "specvectors.h"

#include <QJsonArray>
#include <QtTest>

using specvectors::bytes;

class TestDecoder : public QObject
{
    Q_OBJECT

private slots:
    void guessesTheProtocolFromTheFirstHeader()
    {
        QCOMPARE(cli::guessProtocol(bytes("00 AF FA 00 09")), cli::Protocol::Ptk);
        QCOMPARE(cli::guessProtocol(bytes("12 FF FF 01 02 01 FB")), cli::Protocol::Feetech);
        QVERIFY(!cli::guessProtocol(bytes("01 02 03")).has_value());
    }

    void ptkRepliesAreAttributedToTheQueryBeforeThem()
    {
        const auto frames =
            cli::decodeStream(cli::Protocol::Ptk, specvectors::ptkConversation(true));
        QCOMPARE(frames.size(), 16);
        for (int i = 0; i < 8; ++i) {
            QCOMPARE(frames[2 * i].kind, QStringLiteral("query"));
            QCOMPARE(frames[2 * i + 1].kind, QStringLiteral("reply"));
            QCOMPARE(frames[2 * i + 1].fields.value(QStringLiteral("answers")).toString(),
                     QLatin1String(specvectors::kPtkExchanges[std::size_t(i)].name));
        }
        const QJsonObject pulses = frames[7].fields.value(QStringLiteral("values")).toObject();
        QCOMPARE(pulses.value(QStringLiteral("min_pulse_us")).toDouble(), 500.0);
        QCOMPARE(pulses.value(QStringLiteral("max_pulse_us")).toDouble(), 2500.0);
        QVERIFY(frames[1].summary.contains(QStringLiteral("overload_power=800")));
    }

    void aPtkReplyWithoutItsQueryIsStillShown()
    {
        const auto frames =
            cli::decodeStream(cli::Protocol::Ptk, bytes(specvectors::kPtkExchanges[0].reply));
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].kind, QStringLiteral("reply"));
        QVERIFY(!frames[0].fields.contains(QStringLiteral("answers")));
    }

    void ptkWritesNameTheirParameters()
    {
        const auto frames =
            cli::decodeStream(cli::Protocol::Ptk, bytes(specvectors::kPtkWrites[2]));
        QCOMPARE(frames.size(), 1);
        QCOMPARE(frames[0].kind, QStringLiteral("write"));
        QCOMPARE(frames[0].fields.value(QStringLiteral("name")).toString(), QStringLiteral("N3"));
        QVERIFY(frames[0].summary.contains(QStringLiteral("overload_time_ms=2000")));
    }

    void badChecksumsAndStrayBytesAreReportedNotHidden()
    {
        QByteArray bad = bytes(specvectors::kPtkExchanges[0].reply);
        bad[8] = char(bad[8] + 1);
        const auto frames =
            cli::decodeStream(cli::Protocol::Ptk, bytes("01 02") + bad + bytes("AF FA"));
        QCOMPARE(frames.size(), 3);
        QCOMPARE(frames[0].kind, QStringLiteral("garbage"));
        QCOMPARE(frames[1].kind, QStringLiteral("reply"));
        QVERIFY(!frames[1].checksumValid);
        QCOMPARE(frames[1].bytes, bad);
        QCOMPARE(frames[2].kind, QStringLiteral("incomplete"));
    }

    void feetechPingAndReadConversationDecodes()
    {
        const QByteArray stream = bytes("FF FF 01 02 01 FB  FF FF 01 02 00 FC"
                                        "FF FF 01 04 02 38 02 BE  FF FF 01 04 00 18 05 DD");
        const auto frames = cli::decodeStream(cli::Protocol::Feetech, stream);
        QCOMPARE(frames.size(), 4);
        QCOMPARE(frames[0].kind, QStringLiteral("instruction"));
        QCOMPARE(frames[0].fields.value(QStringLiteral("instruction")).toString(),
                 QStringLiteral("PING"));
        QCOMPARE(frames[1].kind, QStringLiteral("status"));
        QCOMPARE(frames[2].fields.value(QStringLiteral("instruction")).toString(),
                 QStringLiteral("READ"));
        QVERIFY(frames[2].summary.contains(QStringLiteral("address 56")));
        QCOMPARE(frames[3].kind, QStringLiteral("status"));
        QCOMPARE(frames[3].fields.value(QStringLiteral("data")).toString(),
                 QStringLiteral("18 05"));
    }

    void aStatusAfterAnInstructionIsReadAsStatusEvenWhenItLooksLikeAPing()
    {
        // FF FF 01 02 01 FB is PING ID 1, and also a status from ID 1 with the voltage bit set.
        // After a READ to ID 1 it is the status.
        const auto frames = cli::decodeStream(cli::Protocol::Feetech,
                                              bytes("FF FF 01 04 02 38 02 BE FF FF 01 02 01 FB"));
        QCOMPARE(frames.size(), 2);
        QCOMPARE(frames[1].kind, QStringLiteral("status"));
        const QJsonArray bits = frames[1].fields.value(QStringLiteral("error_bits")).toArray();
        QCOMPARE(bits, QJsonArray {QStringLiteral("voltage")});
        const auto alone = cli::decodeStream(cli::Protocol::Feetech, bytes("FF FF 01 02 01 FB"));
        QCOMPARE(alone[0].kind, QStringLiteral("instruction"));
    }

    void errorBitsAreNamed()
    {
        QByteArray frame = bytes("FF FF 01 02 21");
        frame.append(char(~(0x01 + 0x02 + 0x21) & 0xFF));
        const auto frames = cli::decodeStream(cli::Protocol::Feetech, frame);
        QCOMPARE(frames[0].kind, QStringLiteral("status"));
        QCOMPARE(frames[0].fields.value(QStringLiteral("error_bits")).toArray(),
                 (QJsonArray {QStringLiteral("voltage"), QStringLiteral("overload")}));
    }

    void feetechSyncWriteListsEveryServo()
    {
        const QByteArray frame =
            bytes("FF FF FE 20 83 2A 06 01 00 08 00 00 E8 03 02 00 08 00 00 E8 03"
                  "03 00 08 00 00 E8 03 04 00 08 00 00 E8 03 58");
        const auto frames = cli::decodeStream(cli::Protocol::Feetech, frame);
        QCOMPARE(frames.size(), 1);
        QVERIFY(frames[0].checksumValid);
        QVERIFY(frames[0].summary.contains(QStringLiteral("ID 4: 00 08 00 00 E8 03")));
        QVERIFY(frames[0].summary.contains(QStringLiteral("broadcast")));
    }

    void jsonCarriesHexKindAndChecksum()
    {
        const auto frames = cli::decodeStream(cli::Protocol::Feetech, bytes("FF FF 01 02 01 FB"));
        const QJsonObject json = cli::toJson(frames.first());
        QCOMPARE(json.value(QStringLiteral("hex")).toString(), QStringLiteral("FF FF 01 02 01 FB"));
        QCOMPARE(json.value(QStringLiteral("kind")).toString(), QStringLiteral("instruction"));
        QCOMPARE(json.value(QStringLiteral("checksum_valid")).toBool(), true);
        QCOMPARE(json.value(QStringLiteral("id")).toInt(), 1);
    }
    void summaryOnlyDecodingExplainsEveryFrameAlikeWithoutFields_data()
    {
        QTest::addColumn<int>("protocol");
        QTest::addColumn<QByteArray>("stream");
        QTest::newRow("ptk") << int(cli::Protocol::Ptk)
                             << bytes("00") + specvectors::ptkConversation(true)
                + bytes(specvectors::kPtkWrites[2]) + bytes("AF FA 00");
        QTest::newRow("feetech") << int(cli::Protocol::Feetech)
                                 << feetech::syncRead(0x38, 2, {1, 2})
                + feetech::status(1, 0, bytes("18 05")) + feetech::status(2, 0x24, bytes("00 08"))
                + bytes("12") + feetech::write(1, 0x2A, bytes("00 08")) + feetech::ping(3)
                + feetech::status(3, 0) + bytes("FF FF 01");
    }

    void summaryOnlyDecodingExplainsEveryFrameAlikeWithoutFields()
    {
        QFETCH(int, protocol);
        QFETCH(QByteArray, stream);
        const auto full = cli::decodeStream(cli::Protocol(protocol), stream);
        const auto brief =
            cli::decodeStream(cli::Protocol(protocol), stream, seriallink::Detail::Summary);
        QCOMPARE(brief.size(), full.size());
        bool anyFields = false;
        for (int i = 0; i < full.size(); ++i) {
            QCOMPARE(brief[i].kind, full[i].kind);
            QCOMPARE(brief[i].summary, full[i].summary);
            QCOMPARE(brief[i].offset, full[i].offset);
            QVERIFY(brief[i].fields.isEmpty());
            anyFields = anyFields || !full[i].fields.isEmpty();
        }
        QVERIFY(anyFields);
    }
};

QTEST_APPLESS_MAIN(TestDecoder)
#include "tst_decoder.moc"
