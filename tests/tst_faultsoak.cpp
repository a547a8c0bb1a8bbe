// Tests the fault soak's short form: a few hundred reads and applies per family through the
// GUI's clients, on a link that drops, corrupts, truncates and pads replies and loses requests,
// and never a value shown or a write reported that the simulator does not hold.
#include "faultsoak.h"

#include <QJsonDocument>
#include <QtTest>

class TestFaultSoak : public QObject
{
    Q_OBJECT

private:
    static void verifyTrustworthy(const soak::SoakCounts &counts, int transactions)
    {
        const QByteArray figures = QJsonDocument(counts.toJson()).toJson(QJsonDocument::Compact);
        QVERIFY2(counts.trustworthy(), figures.constData());
        QCOMPARE(counts.transactions, transactions);
        // The faults were felt, and the work still got done.
        QVERIFY2(counts.readsFailed + counts.writesFailed + counts.writesUnknown
                         + counts.writesMismatch
                     > 0,
                 figures.constData());
        QVERIFY2(counts.readsOk > transactions / 5, figures.constData());
        QVERIFY2(counts.writesVerified > transactions / 5, figures.constData());
        QVERIFY2(counts.valuesChecked > counts.readsOk, figures.constData());
    }

    // A PTK transaction costs more (eight queries a read, twelve writes an apply): fewer.
    static constexpr int kFeetechTransactions = 150;
    static constexpr int kPtkTransactions = 36;

private slots:
    void feetechShowsOnlyHeldValuesAndReportsEveryWriteTruly()
    {
        soak::SoakOptions options;
        options.transactions = kFeetechTransactions;
        options.seed = 11;
        verifyTrustworthy(soak::soakFeetech(options), kFeetechTransactions);
    }

    void ptkShowsOnlyHeldValuesAndReportsEveryWriteTruly()
    {
        soak::SoakOptions options;
        options.transactions = kPtkTransactions;
        options.seed = 12;
        verifyTrustworthy(soak::soakPtk(options), kPtkTransactions);
    }
};

QTEST_GUILESS_MAIN(TestFaultSoak)
#include "tst_faultsoak.moc"
