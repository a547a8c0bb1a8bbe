// Tests the generic framer's bookkeeping with a toy format: 'S', length byte, payload, sum.
#include "streamframer.h"

#include <QtTest>

namespace {

// Frames look like 'S' N payload[N] checksum, checksum = N + sum(payload) mod 256.
class ToyFormat final : public seriallink::FrameFormat
{
public:
    int frameLength(QByteArrayView buffer) const override
    {
        if (buffer.isEmpty())
            return 0;
        if (buffer[0] != 'S')
            return -1;
        if (buffer.size() < 2)
            return 0;
        return quint8(buffer[1]) + 3;
    }
    bool checksumValid(QByteArrayView frame) const override
    {
        unsigned sum = 0;
        for (qsizetype i = 1; i + 1 < frame.size(); ++i)
            sum += quint8(frame[i]);
        return quint8(sum) == quint8(frame.back());
    }
};

// The same frames, declaring their fixed first byte: the framer then scans for it itself.
class ToyFormatWithPrefix final : public seriallink::FrameFormat
{
public:
    int frameLength(QByteArrayView buffer) const override { return m_toy.frameLength(buffer); }
    bool checksumValid(QByteArrayView frame) const override { return m_toy.checksumValid(frame); }
    QByteArrayView framePrefix() const override { return "S"; }

private:
    ToyFormat m_toy;
};

using Items = QList<std::tuple<seriallink::StreamItem::Kind, QByteArray, qint64>>;

// Every item of `stream` delivered in pieces of `pieceSize`, with where each one started.
Items itemsOf(const seriallink::FrameFormat &format, const QByteArray &stream, int pieceSize)
{
    seriallink::StreamFramer framer(format);
    Items items;
    for (qsizetype at = 0; at < stream.size(); at += pieceSize) {
        framer.append(stream.mid(at, pieceSize));
        while (const auto item = framer.next())
            items.append({item->kind, item->bytes, item->offset});
    }
    return items;
}

QByteArray toyFrame(const QByteArray &payload)
{
    QByteArray frame("S");
    frame.append(char(payload.size()));
    frame.append(payload);
    unsigned sum = unsigned(payload.size());
    for (const char c : payload)
        sum += quint8(c);
    frame.append(char(sum));
    return frame;
}

} // namespace

class TestStreamFramer : public QObject
{
    Q_OBJECT

private slots:
    void saysNeedMoreOnAPartialFrameAndKeepsIt()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format);
        const QByteArray frame = toyFrame("abc");
        framer.append(frame.left(3));
        QVERIFY(!framer.next().has_value());
        QCOMPARE(framer.pendingBytes(), 3);
        framer.append(frame.mid(3));
        const auto item = framer.next();
        QVERIFY(item.has_value());
        QCOMPARE(item->kind, seriallink::StreamItem::Kind::Frame);
        QCOMPARE(item->bytes, frame);
        QCOMPARE(framer.framesAccepted(), 1);
    }

    void reportsGarbageAsOneRunWithItsOffset()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format);
        framer.append("xyz" + toyFrame("a"));
        const auto garbage = framer.next();
        QVERIFY(garbage.has_value());
        QCOMPARE(garbage->kind, seriallink::StreamItem::Kind::Garbage);
        QCOMPARE(garbage->bytes, QByteArray("xyz"));
        QCOMPARE(garbage->offset, 0);
        const auto frame = framer.next();
        QVERIFY(frame.has_value());
        QCOMPARE(frame->offset, 3);
        QCOMPARE(framer.bytesDiscarded(), 3);
    }

    void resyncPolicyFindsAFrameHiddenInsideABadCandidate()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format);
        // 'S' 3 then a real frame: the false header claims most of the real frame's bytes.
        const QByteArray real = toyFrame("ok");
        framer.append(QByteArray("S\x03", 2) + real);
        QList<seriallink::StreamItem> items;
        while (auto item = framer.next())
            items.append(*item);
        QVERIFY(!items.isEmpty());
        QCOMPARE(items.last().kind, seriallink::StreamItem::Kind::Frame);
        QCOMPARE(items.last().bytes, real);
        QCOMPARE(framer.checksumErrors(), 1);
    }

    void consumePolicyHandsOutTheBadFrameWhole()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format,
                                        seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame);
        QByteArray bad = toyFrame("abc");
        bad[bad.size() - 1] = char(bad.back() + 1);
        framer.append(bad + toyFrame("d"));
        const auto first = framer.next();
        QVERIFY(first.has_value());
        QCOMPARE(first->kind, seriallink::StreamItem::Kind::BadChecksum);
        QCOMPARE(first->bytes, bad);
        QCOMPARE(framer.bytesDiscarded(), bad.size());
        const auto second = framer.next();
        QVERIFY(second.has_value());
        QCOMPARE(second->kind, seriallink::StreamItem::Kind::Frame);
    }

    void discardPendingDropsAndCountsBufferedBytes()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format);
        framer.append(toyFrame("abcd").left(4));
        QVERIFY(!framer.next().has_value());
        QCOMPARE(framer.discardPending(), 4);
        QCOMPARE(framer.pendingBytes(), 0);
        QCOMPARE(framer.bytesDiscarded(), 4);
        framer.append(toyFrame("z"));
        const auto item = framer.next();
        QVERIFY(item.has_value());
        QCOMPARE(item->offset, 4);
    }

    void flushHandsOutTheIncompleteRest()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format);
        framer.append(QByteArray("S\x09", 2) + "ab");
        QVERIFY(!framer.next().has_value());
        const auto rest = framer.flush();
        QVERIFY(rest.has_value());
        QCOMPARE(rest->kind, seriallink::StreamItem::Kind::Incomplete);
        QCOMPARE(rest->bytes.size(), 4);
        QVERIFY(!framer.flush().has_value());
    }
    void byteByByteDeliveryGivesTheSameItemsAsOneDelivery()
    {
        ToyFormat format;
        // Garbage, a frame, a false header that resyncs onto a real frame, a frame cut short.
        const QByteArray stream = "xy" + toyFrame("abc") + QByteArray("S\x03", 2) + toyFrame("ok")
            + toyFrame("long payload").left(5);
        const auto items = [&format](const QList<QByteArray> &chunks) {
            seriallink::StreamFramer framer(format);
            QList<std::pair<seriallink::StreamItem::Kind, QByteArray>> seen;
            for (const QByteArray &chunk : chunks) {
                framer.append(chunk);
                while (auto item = framer.next()) {
                    // A garbage run is reported up to the end of what has arrived, so its
                    // pieces depend on the delivery; frames must not.
                    if (item->kind != seriallink::StreamItem::Kind::Garbage)
                        seen.append({item->kind, item->bytes});
                }
            }
            seen.append({seriallink::StreamItem::Kind::Incomplete,
                         QByteArray::number(framer.pendingBytes())});
            seen.append({seriallink::StreamItem::Kind::Garbage,
                         QByteArray::number(framer.bytesDiscarded())});
            return seen;
        };
        QList<QByteArray> single;
        for (const char byte : stream)
            single.append(QByteArray(1, byte));
        const auto whole = items({stream});
        QCOMPARE(items(single), whole);
        QCOMPARE(whole.at(0).second, toyFrame("abc"));
        QCOMPARE(whole.at(whole.size() - 2).second, QByteArray("5"));
    }
    void aDeclaredFramePrefixChangesNoItem_data()
    {
        QTest::addColumn<int>("pieceSize");
        QTest::newRow("byte by byte") << 1;
        QTest::newRow("three bytes") << 3;
        QTest::newRow("one block") << 100000;
    }
    void aDeclaredFramePrefixChangesNoItem()
    {
        // Frames, noise with and without false headers, a bad checksum, a frame cut short.
        QFETCH(int, pieceSize);
        QRandomGenerator random(7);
        QByteArray stream;
        for (int i = 0; i < 300; ++i) {
            QByteArray payload;
            for (int n = int(random.bounded(6)); n > 0; --n)
                payload.append(char(random.bounded(256)));
            QByteArray frame = toyFrame(payload);
            if (i % 11 == 5)
                frame.back() = char(frame.back() + 1);
            stream += frame;
            for (int n = int(random.bounded(4)); n > 0; --n)
                stream += random.bounded(3) == 0 ? 'S' : char(random.bounded(256));
        }
        stream += toyFrame("cut short").left(4);
        const Items plain = itemsOf(ToyFormat(), stream, pieceSize);
        QCOMPARE(itemsOf(ToyFormatWithPrefix(), stream, pieceSize), plain);
        QVERIFY(plain.size() > 300);
    }
    void anItemKeptByItsReceiverIsNotOverwrittenByTheNext()
    {
        ToyFormat format;
        seriallink::StreamFramer framer(format);
        framer.append(toyFrame("first") + toyFrame("other"));
        const auto first = framer.next();
        QVERIFY(first.has_value());
        const auto second = framer.next();
        QVERIFY(second.has_value());
        QCOMPARE(first->bytes, toyFrame("first"));
        QCOMPARE(second->bytes, toyFrame("other"));
    }
    void sumOfBytesAddsEveryByte()
    {
        QRandomGenerator random(3);
        for (int size = 0; size <= 40; ++size) {
            QByteArray bytes(size, char(0xFF));
            quint32 expected = 255u * quint32(size);
            QCOMPARE(seriallink::sumOfBytes(bytes), expected);
            expected = 0;
            for (char &byte : bytes) {
                byte = char(random.bounded(256));
                expected += quint8(byte);
            }
            QCOMPARE(seriallink::sumOfBytes(bytes), expected);
        }
    }
};

QTEST_APPLESS_MAIN(TestStreamFramer)
#include "tst_streamframer.moc"
