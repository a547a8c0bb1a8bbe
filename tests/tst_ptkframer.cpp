// Tests the PTK stream framer: split reads, concatenation, garbage, bad checksums and echo.
#include "ptkframe.h"
#include "specvectors.h"
#include "streamframer.h"

#include <QtTest>

using specvectors::bytes;
using Kind = seriallink::StreamItem::Kind;

namespace {

QList<QByteArray> framesOf(seriallink::StreamFramer &framer)
{
    QList<QByteArray> frames;
    while (auto item = framer.next()) {
        if (item->kind == Kind::Frame)
            frames.append(item->bytes);
    }
    return frames;
}

QList<QByteArray> expectedConversation(bool withEcho)
{
    QList<QByteArray> frames;
    for (const auto &exchange : specvectors::kPtkExchanges) {
        if (withEcho)
            frames.append(bytes(exchange.query));
        frames.append(bytes(exchange.reply));
    }
    return frames;
}

} // namespace

class TestPtkFramer : public QObject
{
    Q_OBJECT

private slots:
    void splitAtEveryByteBoundaryGivesTheSameFrames()
    {
        const QByteArray stream = specvectors::ptkConversation(true);
        const QList<QByteArray> expected = expectedConversation(true);
        const ptk::FrameFormat format;
        for (int split = 0; split <= stream.size(); ++split) {
            seriallink::StreamFramer framer(format);
            framer.append(stream.left(split));
            QList<QByteArray> frames = framesOf(framer);
            framer.append(stream.mid(split));
            frames += framesOf(framer);
            QCOMPARE(frames, expected);
            QCOMPARE(framer.bytesDiscarded(), 0);
        }
    }

    void byteByByteGivesTheSameFrames()
    {
        const QByteArray stream = specvectors::ptkConversation(false);
        const ptk::FrameFormat format;
        seriallink::StreamFramer framer(format);
        QList<QByteArray> frames;
        for (const char byte : stream) {
            framer.append(QByteArray(1, byte));
            frames += framesOf(framer);
        }
        QCOMPARE(frames, expectedConversation(false));
    }

    void severalFramesInOneReadAllComeOut()
    {
        const ptk::FrameFormat format;
        seriallink::StreamFramer framer(format);
        framer.append(specvectors::ptkConversation(false));
        QCOMPARE(framesOf(framer).size(), 8);
        QCOMPARE(framer.framesAccepted(), 8);
    }

    void leadingGarbageIsDroppedAndCounted()
    {
        const ptk::FrameFormat format;
        seriallink::StreamFramer framer(format);
        // Includes a lone header byte and a header with a wrong length byte.
        const QByteArray garbage = bytes("00 13 AF AF FA 00 07 FA");
        framer.append(garbage + bytes(specvectors::kPtkExchanges[1].reply));
        QCOMPARE(framesOf(framer), QList<QByteArray> {bytes(specvectors::kPtkExchanges[1].reply)});
        QCOMPARE(framer.bytesDiscarded(), garbage.size());
    }

    void aCorruptedChecksumIsSkippedAndTheNextGoodFrameFound()
    {
        const ptk::FrameFormat format;
        seriallink::StreamFramer framer(format);
        QByteArray bad = bytes(specvectors::kPtkExchanges[0].reply);
        bad[5] = char(bad[5] ^ 0x01);
        const QByteArray good = bytes(specvectors::kPtkExchanges[1].reply);
        framer.append(bad + good);
        QCOMPARE(framesOf(framer), QList<QByteArray> {good});
        QCOMPARE(framer.checksumErrors(), 1);
        QCOMPARE(framer.bytesDiscarded(), bad.size());
    }

    void theHostsEchoedQueryComesOutBeforeTheReply()
    {
        const ptk::FrameFormat format;
        seriallink::StreamFramer framer(format);
        const auto &exchange = specvectors::kPtkExchanges[3];
        framer.append(bytes(exchange.query) + bytes(exchange.reply));
        const QList<QByteArray> frames = framesOf(framer);
        QCOMPARE(frames.size(), 2);
        QCOMPARE(frames[0].size(), ptk::kRequestSize);
        QVERIFY(ptk::decodeRequest(frames[0]).has_value());
        QCOMPARE(frames[1].size(), ptk::kReplySize);
        QVERIFY(ptk::decodeReply(frames[1]).has_value());
    }
};

QTEST_APPLESS_MAIN(TestPtkFramer)
#include "tst_ptkframer.moc"
