// Tests PTK frame encoding and decoding against every frame of spec/ptk-protocol.md.
#include "ptkframe.h"
#include "specvectors.h"

#include <QtTest>

using specvectors::bytes;

class TestPtkFrame : public QObject
{
    Q_OBJECT

private:
    static void addExchanges()
    {
        QTest::addColumn<int>("command");
        QTest::addColumn<QByteArray>("query");
        QTest::addColumn<QByteArray>("reply");
        for (const auto &exchange : specvectors::kPtkExchanges)
            QTest::newRow(exchange.name)
                << exchange.command << bytes(exchange.query) << bytes(exchange.reply);
    }

private slots:
    void queriesEncodeToTheSeedBytes_data() { addExchanges(); }
    void queriesEncodeToTheSeedBytes()
    {
        QFETCH(int, command);
        QFETCH(QByteArray, query);
        QCOMPARE(ptk::encodeQuery(quint8(command)), query);
    }

    void queriesDecodeBackToTheirCommand_data() { addExchanges(); }
    void queriesDecodeBackToTheirCommand()
    {
        QFETCH(int, command);
        QFETCH(QByteArray, query);
        const auto request = ptk::decodeRequest(query);
        QVERIFY(request.has_value());
        QCOMPARE(request->command, quint8(command));
        QCOMPARE(request->word0, quint16(0));
        QCOMPARE(request->word1, quint16(0));
    }

    void repliesDecodeAndReencodeByteForByte_data() { addExchanges(); }
    void repliesDecodeAndReencodeByteForByte()
    {
        QFETCH(QByteArray, reply);
        const auto decoded = ptk::decodeReply(reply);
        QVERIFY(decoded.has_value());
        QCOMPARE(ptk::encodeReply(*decoded), reply);
    }

    void replyWordsAreBigEndian()
    {
        const auto reply = ptk::decodeReply(bytes(specvectors::kPtkExchanges[0].reply));
        QVERIFY(reply.has_value());
        QCOMPARE(reply->word0, quint16(800));
        QCOMPARE(reply->word1, quint16(2000));
    }

    void checksumIsTheSumAfterTheHeaderModulo256()
    {
        QCOMPARE(ptk::checksum(bytes("AFFA000A3800000000")), quint8(0x42));
        QCOMPARE(ptk::checksum(bytes("AFFA000A4807D02710")), quint8(0x60));
    }

    void rejectsBadChecksumWrongLengthAndWrongHeader_data()
    {
        QTest::addColumn<QByteArray>("frame");
        QTest::newRow("bad checksum") << bytes("AFFA0009032007D004");
        QTest::newRow("request as reply") << bytes("AFFA000A3800000000 42");
        QTest::newRow("short") << bytes("AFFA0009032007D0");
        QTest::newRow("header") << bytes("AFFB0009032007D003");
    }
    void rejectsBadChecksumWrongLengthAndWrongHeader()
    {
        QFETCH(QByteArray, frame);
        QVERIFY(!ptk::decodeReply(frame).has_value());
    }

    void requestDecodingRejectsAReply()
    {
        QVERIFY(!ptk::decodeRequest(bytes(specvectors::kPtkExchanges[0].reply)).has_value());
        QVERIFY(!ptk::decodeRequest(bytes("AFFA000A3800000000 43")).has_value());
    }
};

QTEST_APPLESS_MAIN(TestPtkFrame)
#include "tst_ptkframe.moc"
