// Tests the Feetech packet descriptions the packet log shows, on the spec's frames.
#include "feetechdescription.h"
#include "specvectors.h"

#include <QtTest>

using specvectors::bytes;

class TestFeetechDescription : public QObject
{
    Q_OBJECT

private slots:
    void aRequestIsDescribedAlone()
    {
        const QByteArray read = bytes("FF FF 01 04 02 38 02 BE");
        QCOMPARE(feetech::describeFrame(read, {}),
                 QStringLiteral("READ ID 1 address 56 (0x38), length 2"));
    }

    void anAnswerWithItsRequestsVeryBytesIsAStatus()
    {
        // A servo with the voltage bit answers a PING with the PING's bytes.
        const QByteArray ping = bytes("FF FF 01 02 01 FB");
        const QString summary = feetech::describeFrame(ping, ping);
        QVERIFY2(summary.startsWith(QStringLiteral("status from ID 1: error 0x01 (voltage)")),
                 qPrintable(summary));
    }

    void aReplyIsReadAsTheStatusOfTheRequestBeforeIt()
    {
        // Alone, FF FF 01 02 01 FB would read as a PING; after a READ to ID 1 it is its status.
        const QString summary =
            feetech::describeFrame(bytes("FF FF 01 02 01 FB"), bytes("FF FF 01 04 02 38 02 BE"));
        QVERIFY2(summary.startsWith(QStringLiteral("status from ID 1: error 0x01 (voltage)")),
                 qPrintable(summary));
    }

    void aReadReplyShowsItsData()
    {
        const QString summary = feetech::describeFrame(bytes("FF FF 01 04 00 18 05 DD"),
                                                       bytes("FF FF 01 04 02 38 02 BE"));
        QCOMPARE(summary, QStringLiteral("status from ID 1: no error, data 18 05"));
    }

    void theStreamDecoderKeepsBadChecksumsAsFrames()
    {
        const auto frames = feetech::decodeStream(bytes("FF FF 01 02 01 FA FF"));
        QCOMPARE(frames.size(), 2);
        QVERIFY(!frames[0].checksumValid);
        QCOMPARE(frames[0].kind, QStringLiteral("instruction"));
        QCOMPARE(frames[1].kind, QStringLiteral("incomplete"));
    }
};

QTEST_APPLESS_MAIN(TestFeetechDescription)
#include "tst_feetechdescription.moc"
