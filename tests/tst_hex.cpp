// Tests hex text parsing and formatting as users type frames.
#include "hex.h"

#include <QtTest>

class TestHex : public QObject
{
    Q_OBJECT

private slots:
    void parsesSpacedJoinedAndPrefixedBytes_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("spaced") << QStringLiteral("AF FA 00 0a") << QByteArray::fromHex("affa000a");
        QTest::newRow("joined") << QStringLiteral("affa000a") << QByteArray::fromHex("affa000a");
        QTest::newRow("0x and commas")
            << QStringLiteral("0xAF,0xFA, 0x00") << QByteArray::fromHex("affa00");
        QTest::newRow("colons") << QStringLiteral("ff:ff:01") << QByteArray::fromHex("ffff01");
        QTest::newRow("empty") << QString() << QByteArray();
    }
    void parsesSpacedJoinedAndPrefixedBytes()
    {
        QFETCH(QString, text);
        QFETCH(QByteArray, bytes);
        const auto parsed = util::parseHex(text);
        QVERIFY(parsed.has_value());
        QCOMPARE(*parsed, bytes);
    }

    void rejectsOddDigitsAndNonHexWithAReason_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("odd") << QStringLiteral("AF F");
        QTest::newRow("not hex") << QStringLiteral("AF GG");
        QTest::newRow("odd joined") << QStringLiteral("affa0");
    }
    void rejectsOddDigitsAndNonHexWithAReason()
    {
        QFETCH(QString, text);
        QString error;
        QVERIFY(!util::parseHex(text, &error).has_value());
        QVERIFY(!error.isEmpty());
    }

    void formatsUpperCasePairs()
    {
        QCOMPARE(util::toHex(QByteArray::fromHex("affa000a")), QStringLiteral("AF FA 00 0A"));
    }

    void parsesDecimalAndHexIntegers()
    {
        QCOMPARE(util::parseInteger(QStringLiteral("42")).value_or(-1), 42);
        QCOMPARE(util::parseInteger(QStringLiteral("0x2A")).value_or(-1), 42);
        QVERIFY(!util::parseInteger(QStringLiteral("4x2")).has_value());
        QVERIFY(!util::parseInteger(QString()).has_value());
    }
};

QTEST_APPLESS_MAIN(TestHex)
#include "tst_hex.moc"
