// Tests Feetech register value encoding: SCS big-endian vs STS little-endian, sign-magnitude.
#include "feetechvalue.h"

#include <QtTest>

#include <algorithm>
#include <cstdlib>

using feetech::ByteOrder;
using feetech::ValueFormat;

Q_DECLARE_METATYPE(feetech::ByteOrder)

namespace {

QByteArray hex(const char *text)
{
    return QByteArray::fromHex(text);
}

ValueFormat format(int size, ByteOrder order, std::optional<int> signBit = std::nullopt)
{
    return ValueFormat {size, order, signBit};
}

} // namespace

class TestFeetechValue : public QObject
{
    Q_OBJECT

private slots:
    void position1304IsHighByteFirstOnScsAndLowByteFirstOnSts_data()
    {
        QTest::addColumn<ByteOrder>("order");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("SCS, big-endian") << ByteOrder::Big << hex("0518");
        QTest::newRow("STS, little-endian (seed example 2)") << ByteOrder::Little << hex("1805");
    }

    void position1304IsHighByteFirstOnScsAndLowByteFirstOnSts()
    {
        QFETCH(ByteOrder, order);
        QFETCH(QByteArray, bytes);
        const auto encoded = feetech::encodeValue(1304, format(2, order));
        QVERIFY(encoded.has_value());
        QCOMPARE(*encoded, bytes);
        QCOMPARE(feetech::decodeValue(bytes, format(2, order)), 1304);
        QCOMPARE(feetech::encodeRaw(0x0518, 2, order), bytes);
        QCOMPARE(feetech::decodeRaw(bytes, order), quint16(0x0518));
    }

    void oneByteRegistersIgnoreByteOrder()
    {
        for (const ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
            const auto encoded = feetech::encodeValue(0xC8, format(1, order));
            QVERIFY(encoded.has_value());
            QCOMPARE(*encoded, hex("C8"));
            QCOMPARE(feetech::decodeValue(hex("C8"), format(1, order)), 0xC8);
        }
    }

    void signMagnitudeRoundTripsAtTheExtremes_data()
    {
        QTest::addColumn<int>("signBit");
        QTest::addColumn<int>("value");
        QTest::addColumn<QByteArray>("littleEndian");
        QTest::newRow("bit 15, +32767") << 15 << 32767 << hex("FF7F");
        QTest::newRow("bit 15, -32767") << 15 << -32767 << hex("FFFF");
        QTest::newRow("bit 11, +2047") << 11 << 2047 << hex("FF07");
        QTest::newRow("bit 11, -2047") << 11 << -2047 << hex("FF0F");
        QTest::newRow("bit 11, -1") << 11 << -1 << hex("0108");
        QTest::newRow("bit 11, -5") << 11 << -5 << hex("0508");
        QTest::newRow("bit 10, +1023") << 10 << 1023 << hex("FF03");
        QTest::newRow("bit 10, -1023") << 10 << -1023 << hex("FF07");
        QTest::newRow("bit 10, -1000 (load)") << 10 << -1000 << hex("E807");
        QTest::newRow("bit 15, 0") << 15 << 0 << hex("0000");
    }

    void signMagnitudeRoundTripsAtTheExtremes()
    {
        QFETCH(int, signBit);
        QFETCH(int, value);
        QFETCH(QByteArray, littleEndian);
        const ValueFormat little = format(2, ByteOrder::Little, signBit);
        const auto encoded = feetech::encodeValue(value, little);
        QVERIFY(encoded.has_value());
        QCOMPARE(*encoded, littleEndian);
        QCOMPARE(feetech::decodeValue(*encoded, little), value);

        const ValueFormat big = format(2, ByteOrder::Big, signBit);
        QByteArray bigEndian = littleEndian;
        std::reverse(bigEndian.begin(), bigEndian.end());
        const auto encodedBig = feetech::encodeValue(value, big);
        QVERIFY(encodedBig.has_value());
        QCOMPARE(*encodedBig, bigEndian);
        QCOMPARE(feetech::decodeValue(bigEndian, big), value);
    }

    void minusOneWithSignBitElevenIs0x0801()
    {
        QCOMPARE(feetech::toSignMagnitude(-1, 11), std::optional<quint16>(0x0801));
        QCOMPARE(feetech::fromSignMagnitude(0x0801, 11), -1);
        QCOMPARE(feetech::toRaw(-1, format(2, ByteOrder::Little, 11)),
                 std::optional<quint16>(0x0801));
    }

    void valuesOutsideTheFormatAreRefused_data()
    {
        QTest::addColumn<int>("value");
        QTest::addColumn<int>("size");
        QTest::addColumn<int>("signBit"); // -1: unsigned
        QTest::newRow("2048 with sign bit 11") << 2048 << 2 << 11;
        QTest::newRow("-2048 with sign bit 11") << -2048 << 2 << 11;
        QTest::newRow("1024 with sign bit 10") << 1024 << 2 << 10;
        QTest::newRow("-32768 with sign bit 15") << -32768 << 2 << 15;
        QTest::newRow("32768 with sign bit 15") << 32768 << 2 << 15;
        QTest::newRow("70000 unsigned 2-byte") << 70000 << 2 << -1;
        QTest::newRow("65536 unsigned 2-byte") << 65536 << 2 << -1;
        QTest::newRow("-1 unsigned 2-byte") << -1 << 2 << -1;
        QTest::newRow("256 unsigned 1-byte") << 256 << 1 << -1;
        QTest::newRow("-1 unsigned 1-byte") << -1 << 1 << -1;
    }

    void valuesOutsideTheFormatAreRefused()
    {
        QFETCH(int, value);
        QFETCH(int, size);
        QFETCH(int, signBit);
        const std::optional<int> sign = signBit < 0 ? std::nullopt : std::optional<int>(signBit);
        for (const ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
            QVERIFY(!feetech::encodeValue(value, format(size, order, sign)).has_value());
            QVERIFY(!feetech::toRaw(value, format(size, order, sign)).has_value());
        }
        if (sign)
            QVERIFY(!feetech::toSignMagnitude(value, *sign).has_value());
    }

    void negativeZeroWithSignBitFifteenDecodesToZero()
    {
        QCOMPARE(feetech::fromSignMagnitude(0x8000, 15), 0);
        QCOMPARE(feetech::decodeValue(hex("0080"), format(2, ByteOrder::Little, 15)), 0);
        QCOMPARE(feetech::decodeValue(hex("8000"), format(2, ByteOrder::Big, 15)), 0);
    }

    void everyValueWithSignBitElevenRoundTripsInBothByteOrders()
    {
        for (const ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
            const ValueFormat offset = format(2, order, 11);
            for (int value = -2047; value <= 2047; ++value) {
                const auto encoded = feetech::encodeValue(value, offset);
                QVERIFY2(encoded.has_value(), qPrintable(QString::number(value)));
                QCOMPARE(encoded->size(), 2);
                const quint16 raw = feetech::decodeRaw(*encoded, order);
                // Sign-magnitude: bit 11 is the sign, bits 0-10 the magnitude, nothing above.
                QCOMPARE(raw, quint16((value < 0 ? 0x0800 : 0) | std::abs(value)));
                QCOMPARE(feetech::decodeValue(*encoded, offset), value);
            }
        }
    }

    void unsignedMaximaEncodeAsAllOnes()
    {
        for (const ByteOrder order : {ByteOrder::Big, ByteOrder::Little}) {
            QCOMPARE(feetech::encodeValue(65535, format(2, order)),
                     std::optional<QByteArray>(hex("FFFF")));
            QCOMPARE(feetech::decodeValue(hex("FFFF"), format(2, order)), 65535);
            QCOMPARE(feetech::encodeValue(255, format(1, order)),
                     std::optional<QByteArray>(hex("FF")));
            QCOMPARE(feetech::decodeValue(hex("FF"), format(1, order)), 255);
        }
        QCOMPARE(feetech::maximumMagnitude(format(2, ByteOrder::Little)), 65535);
        QCOMPARE(feetech::maximumMagnitude(format(1, ByteOrder::Little)), 255);
        QCOMPARE(feetech::minimumValue(format(2, ByteOrder::Little)), 0);
    }

    void signedRangeIsSymmetricAroundZero()
    {
        QCOMPARE(feetech::maximumMagnitude(format(2, ByteOrder::Little, 15)), 32767);
        QCOMPARE(feetech::minimumValue(format(2, ByteOrder::Little, 15)), -32767);
        QCOMPARE(feetech::maximumMagnitude(format(2, ByteOrder::Big, 11)), 2047);
        QCOMPARE(feetech::minimumValue(format(2, ByteOrder::Big, 10)), -1023);
    }
};

QTEST_APPLESS_MAIN(TestFeetechValue)
#include "tst_feetechvalue.moc"
