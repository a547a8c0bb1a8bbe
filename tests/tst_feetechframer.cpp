// Tests seriallink::StreamFramer driven by feetech::FrameFormat on streams of spec frames.
#include "feetechpacket.h"
#include "streamframer.h"

#include <QtTest>

using seriallink::StreamFramer;
using seriallink::StreamItem;

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(text);
}

// Frames from the seed and the spec, instructions and replies mixed as on a half-duplex bus.
QList<QByteArray> specFrames()
{
    return {
        hex("FFFF010201FB"), // PING ID 1
        hex("FFFF010200FC"), // its reply
        hex("FFFF0104023802BE"), // READ ID 1, 0x38, 2 bytes
        hex("FFFF0104001805DD"), // its reply: position 1304
        hex("FFFFFE04030501F4"), // broadcast WRITE ID <- 1
        hex("FFFF0109032A00080000E803D5"), // WRITE example 4
        hex("FFFF0A09042A00080000E803CB"), // REG WRITE ID 10
        hex("FFFFFE0205FA"), // ACTION
        hex("FFFFFE20832A060100080000E8030200080000E803"
            "0300080000E8030400080000E80358"), // SYNC WRITE example 7
        hex("FFFF000206F7"), // recovery ID 0
        hex("FFFF01040B0004EB"), // calibrate ID 1 to 1024
    };
}

QList<StreamItem> drain(StreamFramer &framer)
{
    QList<StreamItem> items;
    while (const auto item = framer.next())
        items.append(*item);
    return items;
}

// Appends the stream in pieces of `pieceSize` bytes, draining after each piece.
QList<StreamItem> feedInPieces(StreamFramer &framer, const QByteArray &stream, int pieceSize)
{
    QList<StreamItem> items;
    for (int at = 0; at < stream.size(); at += pieceSize) {
        framer.append(stream.mid(at, pieceSize));
        items += drain(framer);
    }
    return items;
}

QList<QByteArray> bytesOfKind(const QList<StreamItem> &items, StreamItem::Kind kind)
{
    QList<QByteArray> result;
    for (const StreamItem &item : items) {
        if (item.kind == kind)
            result.append(item.bytes);
    }
    return result;
}

QList<QByteArray> framesOf(const QList<StreamItem> &items)
{
    return bytesOfKind(items, StreamItem::Kind::Frame);
}

QByteArray garbageOf(const QList<StreamItem> &items)
{
    return bytesOfKind(items, StreamItem::Kind::Garbage).join();
}

} // namespace

class TestFeetechFramer : public QObject
{
    Q_OBJECT

private slots:
    void streamSplitInTwoAtEveryByteYieldsTheFramesInOrder()
    {
        const QList<QByteArray> frames = specFrames();
        const QByteArray stream = frames.join();
        const feetech::FrameFormat format;
        for (int split = 0; split <= stream.size(); ++split) {
            StreamFramer framer(format);
            framer.append(stream.left(split));
            QList<StreamItem> items = drain(framer);
            framer.append(stream.mid(split));
            items += drain(framer);

            QCOMPARE(items.size(), frames.size());
            qint64 offset = 0;
            for (int i = 0; i < items.size(); ++i) {
                QCOMPARE(items.at(i).kind, StreamItem::Kind::Frame);
                QCOMPARE(items.at(i).bytes, frames.at(i));
                QCOMPARE(items.at(i).offset, offset);
                offset += frames.at(i).size();
            }
            QCOMPARE(framer.pendingBytes(), 0);
            QCOMPARE(framer.framesAccepted(), frames.size());
            QCOMPARE(framer.checksumErrors(), 0);
            QCOMPARE(framer.bytesDiscarded(), 0);
        }
    }

    void streamFedByteByByteYieldsTheFramesInOrder()
    {
        const QList<QByteArray> frames = specFrames();
        const feetech::FrameFormat format;
        StreamFramer framer(format);
        const QList<StreamItem> items = feedInPieces(framer, frames.join(), 1);
        QCOMPARE(items.size(), frames.size());
        QCOMPARE(framesOf(items), frames);
        QCOMPARE(framer.pendingBytes(), 0);
        QCOMPARE(framer.bytesDiscarded(), 0);
    }

    void partialFrameWaitsForTheRest()
    {
        const QByteArray frame = hex("FFFF0104001805DD");
        const feetech::FrameFormat format;
        StreamFramer framer(format);
        framer.append(frame.left(7));
        QVERIFY(!framer.next().has_value());
        QCOMPARE(framer.pendingBytes(), 7);
        framer.append(frame.right(1));
        const auto item = framer.next();
        QVERIFY(item.has_value());
        QCOMPARE(item->bytes, frame);
    }

    void severalFramesInOneAppendAllComeOut()
    {
        const QList<QByteArray> frames = specFrames();
        const feetech::FrameFormat format;
        StreamFramer framer(format);
        framer.append(frames.join());
        const QList<StreamItem> items = drain(framer);
        QCOMPARE(items.size(), frames.size());
        QCOMPARE(framesOf(items), frames);
        QCOMPARE(framer.framesAccepted(), frames.size());
    }

    void leadingGarbageIsDroppedAndCountedBeforeTheFrame_data()
    {
        QTest::addColumn<QByteArray>("garbage");
        QTest::addColumn<QByteArray>("frame");
        const QByteArray ping = hex("FFFF010201FB");
        QTest::newRow("noise") << hex("00123456") << ping;
        QTest::newRow("stray FF between noise") << hex("01FF02FF7F") << ping;
        QTest::newRow("FF then a byte") << hex("FF00") << ping;
        QTest::newRow("triple header") << hex("FF") << ping; // FF FF FF 01 ...
        QTest::newRow("four FF before the ID") << hex("FFFF") << ping;
        QTest::newRow("five FF before the ID") << hex("FFFFFF") << ping;
        QTest::newRow("triple header before a reply") << hex("FF") << hex("FFFF0104001805DD");
        QTest::newRow("line idle and noise")
            << hex("FEFEFF00FFFE") << hex("FFFF0109032A00080000E803D5");
    }

    void leadingGarbageIsDroppedAndCountedBeforeTheFrame()
    {
        QFETCH(QByteArray, garbage);
        QFETCH(QByteArray, frame);
        const feetech::FrameFormat format;
        for (const int pieceSize : {int(garbage.size() + frame.size()), 1}) {
            StreamFramer framer(format);
            const QList<StreamItem> items = feedInPieces(framer, garbage + frame, pieceSize);
            QCOMPARE(framesOf(items), QList<QByteArray> {frame});
            QCOMPARE(items.last().kind, StreamItem::Kind::Frame);
            QCOMPARE(items.last().offset, garbage.size());
            QCOMPARE(garbageOf(items), garbage);
            QCOMPARE(framer.bytesDiscarded(), garbage.size());
            QCOMPARE(framer.checksumErrors(), 0);
            QCOMPARE(framer.pendingBytes(), 0);
        }
    }

    void corruptedFrameIsSkippedAndTheNextGoodFrameComesOut_data()
    {
        QTest::addColumn<QByteArray>("bad");
        QTest::addColumn<QByteArray>("good");
        QTest::newRow("ping with a wrong checksum") << hex("FFFF010201FA") << hex("FFFF010200FC");
        QTest::newRow("read reply with a flipped data bit")
            << hex("FFFF0104001804DD") << hex("FFFF0104023802BE");
        QTest::newRow("write with a wrong checksum")
            << hex("FFFF0109032A00080000E803D6") << hex("FFFF010200FC");
        QTest::newRow("checksum byte FF before the next header")
            << hex("FFFF010201FF") << hex("FFFF010200FC");
    }

    void corruptedFrameIsSkippedAndTheNextGoodFrameComesOut()
    {
        QFETCH(QByteArray, bad);
        QFETCH(QByteArray, good);
        const feetech::FrameFormat format;
        for (const int pieceSize : {int(bad.size() + good.size()), 1}) {
            StreamFramer framer(format); // Resync is the default
            const QList<StreamItem> items = feedInPieces(framer, bad + good, pieceSize);
            QVERIFY(!items.isEmpty());
            QCOMPARE(items.first().kind, StreamItem::Kind::BadChecksum);
            QCOMPARE(items.first().bytes, bad);
            QCOMPARE(framesOf(items), QList<QByteArray> {good});
            QCOMPARE(items.last().kind, StreamItem::Kind::Frame);
            QCOMPARE(items.last().offset, bad.size());
            QCOMPARE(framer.checksumErrors(), 1);
            QCOMPARE(framer.bytesDiscarded(), bad.size());
            QCOMPARE(framer.framesAccepted(), 1);
            QCOMPARE(framer.pendingBytes(), 0);
        }
    }

    void echoedInstructionAndTheReplyBothComeOutInstructionFirst()
    {
        const QByteArray echo = hex("FFFF0104023802BE");
        const QByteArray reply = hex("FFFF0104001805DD");
        const feetech::FrameFormat format;
        StreamFramer framer(format);
        framer.append(echo + reply);
        const QList<StreamItem> items = drain(framer);
        QCOMPARE(framesOf(items), (QList<QByteArray> {echo, reply}));
        QCOMPARE(items.size(), 2);
        const auto instruction = feetech::decodePacket(items.at(0).bytes);
        const auto status = feetech::decodePacket(items.at(1).bytes);
        QVERIFY(instruction && status);
        QCOMPARE(instruction->code, quint8(feetech::Instruction::Read));
        QCOMPARE(status->code, quint8(0));
        QCOMPARE(status->parameters, hex("1805"));
    }

    void impossibleLengthIsTreatedAsGarbage_data()
    {
        QTest::addColumn<QByteArray>("header");
        QTest::newRow("LEN 0") << hex("FFFF0100");
        QTest::newRow("LEN 1") << hex("FFFF0101");
        QTest::newRow("LEN 247, frame of 251 bytes") << hex("FFFF01F7");
        QTest::newRow("LEN 255") << hex("FFFF01FF");
    }

    void impossibleLengthIsTreatedAsGarbage()
    {
        QFETCH(QByteArray, header);
        const QByteArray good = hex("FFFF010201FB");
        const feetech::FrameFormat format;
        QCOMPARE(format.frameLength(header), -1);
        StreamFramer framer(format);
        framer.append(header + good);
        const QList<StreamItem> items = drain(framer);
        QCOMPARE(framesOf(items), QList<QByteArray> {good});
        QCOMPARE(garbageOf(items), header);
        QCOMPARE(framer.checksumErrors(), 0);
        QCOMPARE(framer.bytesDiscarded(), header.size());
    }

    void largestAllowedFrameIsAccepted()
    {
        // LEN 246 makes a 250-byte frame, the SDKs' maximum.
        const QByteArray frame = feetech::encodePacket(1, 0x03, QByteArray(244, '\x11'));
        QCOMPARE(frame.size(), feetech::kMaxPacketSize);
        const feetech::FrameFormat format;
        StreamFramer framer(format);
        const QList<StreamItem> items = feedInPieces(framer, frame, 7);
        QCOMPARE(framesOf(items), QList<QByteArray> {frame});
        QCOMPARE(framer.bytesDiscarded(), 0);
    }

    void consumeFramePolicyReturnsTheBadFrameWhole()
    {
        const QByteArray bad = hex("FFFF0109032A00080000E803D6");
        const QByteArray good = hex("FFFF010200FC");
        const feetech::FrameFormat format;
        StreamFramer framer(format, StreamFramer::BadChecksumPolicy::ConsumeFrame);
        framer.append(bad + good);
        const QList<StreamItem> items = drain(framer);
        QCOMPARE(items.size(), 2);
        QCOMPARE(items.at(0).kind, StreamItem::Kind::BadChecksum);
        QCOMPARE(items.at(0).bytes, bad);
        QCOMPARE(items.at(0).offset, 0);
        QCOMPARE(items.at(1).kind, StreamItem::Kind::Frame);
        QCOMPARE(items.at(1).bytes, good);
        QCOMPARE(items.at(1).offset, bad.size());
        QCOMPARE(framer.checksumErrors(), 1);
        QCOMPARE(framer.framesAccepted(), 1);
    }
};

QTEST_APPLESS_MAIN(TestFeetechFramer)
#include "tst_feetechframer.moc"
