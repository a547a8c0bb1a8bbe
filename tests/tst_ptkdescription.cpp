// Tests the PTK frame descriptions the packet log shows, on the spec's frames.
#include "ptkdescription.h"
#include "specvectors.h"

#include <QtTest>

using specvectors::bytes;

class TestPtkDescription : public QObject
{
    Q_OBJECT

private slots:
    void aQueryIsDescribedAlone()
    {
        const QByteArray query = bytes(specvectors::kPtkExchanges[0].query);
        const QString summary = ptk::describeFrame(query, query);
        QVERIFY2(summary.startsWith(QStringLiteral("query N1 (command 0x38)")),
                 qPrintable(summary));
    }

    void aReplyIsDescribedNextToTheQueryItAnswers()
    {
        const auto &exchange = specvectors::kPtkExchanges[0];
        const QString summary = ptk::describeFrame(bytes(exchange.reply), bytes(exchange.query));
        QVERIFY2(summary.startsWith(QStringLiteral("reply to N1: ")), qPrintable(summary));
        QVERIFY(summary.contains(QStringLiteral("overload_power=800")));
    }

    void aReplyWithoutARequestKeepsItsRawWords()
    {
        const QString summary =
            ptk::describeFrame(bytes(specvectors::kPtkExchanges[0].reply), QByteArray());
        QVERIFY2(summary.startsWith(QStringLiteral("reply (query unknown)")), qPrintable(summary));
    }

    void aWriteNamesItsValues()
    {
        const QByteArray write = bytes(specvectors::kPtkWrites[2]);
        QVERIFY(ptk::describeFrame(write, write).contains(QStringLiteral("overload_time_ms=2000")));
    }

    void theStreamDecoderGivesEveryFrameWithItsOffset()
    {
        const QByteArray query = bytes(specvectors::kPtkExchanges[1].query);
        const QByteArray reply = bytes(specvectors::kPtkExchanges[1].reply);
        const auto frames = ptk::decodeStream(query + reply);
        QCOMPARE(frames.size(), 2);
        QCOMPARE(frames[0].offset, 0);
        QCOMPARE(frames[1].offset, query.size());
        QCOMPARE(frames[1].fields.value(QStringLiteral("answers")).toString(),
                 QStringLiteral("N2"));
    }
};

QTEST_APPLESS_MAIN(TestPtkDescription)
#include "tst_ptkdescription.moc"
