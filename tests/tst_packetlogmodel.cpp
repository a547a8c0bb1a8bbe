// Tests the packet log model: batched appends, the capacity bound, pause, counts and export.
#include "packetlogentries.h"

#include "packetlogmodel.h"

#include <QBuffer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using seriallink::Direction;
using seriallink::PacketLogEntry;
using seriallink::PacketLogModel;

namespace {

using testsupport::logEntry;

QString cell(const PacketLogModel &log, int row, int column)
{
    return log.data(log.index(row, column)).toString();
}

} // namespace

class TestPacketLogModel : public QObject
{
    Q_OBJECT

private slots:
    void appendedEntriesAppearAfterTheBatchInterval()
    {
        PacketLogModel log;
        QSignalSpy inserts(&log, &QAbstractItemModel::rowsInserted);
        for (int n = 0; n < 500; ++n)
            log.append(logEntry(n));
        QCOMPARE(log.rowCount(), 0); // queued, not yet inserted
        QCOMPARE(log.totalCount(), 500);
        QTRY_COMPARE(log.rowCount(), 500);
        QCOMPARE(inserts.size(), 1); // the whole burst went in with one insert
        QCOMPARE(cell(log, 0, PacketLogModel::MeaningColumn), QStringLiteral("frame 0"));
        QCOMPARE(cell(log, 499, PacketLogModel::MeaningColumn), QStringLiteral("frame 499"));
    }

    void theBytesColumnShowsSpacedUpperCaseHex()
    {
        PacketLogModel log;
        log.append(logEntry(0x2b));
        log.flush();
        QCOMPARE(cell(log, 0, PacketLogModel::BytesColumn),
                 QStringLiteral("AF FA 00 0A 38 2B 00 00 00 42"));
        QCOMPARE(cell(log, 0, PacketLogModel::DirectionColumn), QStringLiteral("← in"));
        QCOMPARE(log.data(log.index(0, 0), PacketLogModel::RawBytesRole).toByteArray().size(), 10);
    }

    void theTimeColumnShowsLocalTimeWithMilliseconds()
    {
        PacketLogModel log;
        PacketLogEntry entry = logEntry(0);
        const QDateTime when(QDate(2024, 5, 6), QTime(13, 4, 5, 67));
        entry.timestampMs = when.toMSecsSinceEpoch();
        log.append(entry);
        log.flush();
        QCOMPARE(cell(log, 0, PacketLogModel::TimeColumn), QStringLiteral("13:04:05.067"));
    }

    void errorRowsAreMarkedAndCounted()
    {
        PacketLogModel log;
        QSignalSpy counts(&log, &PacketLogModel::countsChanged);
        log.append(logEntry(0));
        log.append(logEntry(1, QStringLiteral("bad checksum")));
        QTRY_COMPARE(log.rowCount(), 2);
        QVERIFY(!log.data(log.index(0, 0), PacketLogModel::HasErrorRole).toBool());
        QVERIFY(log.data(log.index(1, 0), PacketLogModel::HasErrorRole).toBool());
        QCOMPARE(cell(log, 1, PacketLogModel::ErrorColumn), QStringLiteral("bad checksum"));
        QCOMPARE(log.errorCount(), 1);
        QCOMPARE(counts.size(), 1);
        QCOMPARE(counts.last(), (QVariantList {2, 1}));
    }

    void aFullLogDropsItsOldestRows()
    {
        PacketLogModel log;
        log.setCapacity(100);
        for (int n = 0; n < 80; ++n)
            log.append(logEntry(n));
        log.flush();
        for (int n = 80; n < 150; ++n)
            log.append(logEntry(n));
        QTRY_COMPARE(cell(log, 99, PacketLogModel::MeaningColumn), QStringLiteral("frame 149"));
        QCOMPARE(log.rowCount(), 100);
        QCOMPARE(cell(log, 0, PacketLogModel::MeaningColumn), QStringLiteral("frame 50"));
        QCOMPARE(log.totalCount(), 150);

        // A burst bigger than the whole log keeps only its newest entries.
        for (int n = 150; n < 1000; ++n)
            log.append(logEntry(n));
        log.flush();
        QCOMPARE(log.rowCount(), 100);
        QCOMPARE(cell(log, 0, PacketLogModel::MeaningColumn), QStringLiteral("frame 900"));

        log.setCapacity(10);
        QCOMPARE(log.rowCount(), 10);
        QCOMPARE(cell(log, 0, PacketLogModel::MeaningColumn), QStringLiteral("frame 990"));
    }

    // Errors are what one looks for among thousands of frames: they outlast ordinary rows (the
    // header counted 31 errors while Errors only showed one), within half of the log.
    void errorsStayLongerThanOrdinaryRows()
    {
        PacketLogModel log;
        log.setCapacity(100);
        for (int n = 0; n < 1000; ++n) {
            PacketLogEntry entry = logEntry(n);
            if (n % 50 == 0)
                entry.error = QStringLiteral("timeout");
            log.append(entry);
            if (n % 10 == 9)
                log.flush();
        }
        log.flush();
        QCOMPARE(log.rowCount(), 100);
        int errors = 0;
        for (int row = 0; row < log.rowCount(); ++row)
            errors += !log.entry(row).error.isEmpty();
        QCOMPARE(errors, 20); // every one of them
        QCOMPARE(log.droppedErrorCount(), 0);
        QCOMPARE(log.entry(0).summary, QStringLiteral("frame 0")); // the oldest error, kept
        QCOMPARE(log.entry(99).summary, QStringLiteral("frame 999"));
        // Errors past half of the log go as the oldest rows do, and are counted.
        for (int n = 1000; n < 1200; ++n) {
            PacketLogEntry entry = logEntry(n);
            entry.error = QStringLiteral("timeout");
            log.append(entry);
        }
        log.flush();
        QCOMPARE(log.rowCount(), 100);
        QVERIFY(log.droppedErrorCount() > 0);
    }

    void pauseHoldsNewEntriesUntilResumed()
    {
        PacketLogModel log;
        log.setBatchInterval(std::chrono::milliseconds(1));
        log.append(logEntry(0));
        QTRY_COMPARE(log.rowCount(), 1);

        log.setPaused(true);
        QSignalSpy inserts(&log, &QAbstractItemModel::rowsInserted);
        QSignalSpy counts(&log, &PacketLogModel::countsChanged);
        log.append(logEntry(1));
        log.append(logEntry(2));
        log.flush();
        QCOMPARE(log.rowCount(), 1);
        QCOMPARE(log.heldCount(), 2);
        QCOMPARE(inserts.size(), 0);
        QCOMPARE(counts.size(), 0);

        log.setPaused(false);
        QCOMPARE(log.rowCount(), 3);
        QCOMPARE(log.heldCount(), 0);
        QCOMPARE(cell(log, 2, PacketLogModel::MeaningColumn), QStringLiteral("frame 2"));
        QCOMPARE(counts.size(), 1);
    }

    void entriesHeldWhilePausedStayWithinCapacity()
    {
        PacketLogModel log;
        log.setCapacity(5);
        log.setPaused(true);
        for (int n = 0; n < 20; ++n)
            log.append(logEntry(n));
        QCOMPARE(log.heldCount(), 5);
        log.setPaused(false);
        QCOMPARE(log.rowCount(), 5);
        QCOMPARE(cell(log, 0, PacketLogModel::MeaningColumn), QStringLiteral("frame 15"));
    }

    void clearEmptiesTheLogAndResetsTheCounts()
    {
        PacketLogModel log;
        log.append(logEntry(0, QStringLiteral("timeout")));
        log.append(logEntry(1));
        QTRY_COMPARE(log.rowCount(), 2);
        log.append(logEntry(2)); // still queued
        QSignalSpy counts(&log, &PacketLogModel::countsChanged);
        log.clear();
        QCOMPARE(log.rowCount(), 0);
        QCOMPARE(log.totalCount(), 0);
        QCOMPARE(log.errorCount(), 0);
        QCOMPARE(counts.last(), (QVariantList {0, 0}));
        log.flush();
        QCOMPARE(log.rowCount(), 0); // the queued entry went with the rest
    }

    void exportWritesAHeaderAndOneLinePerEntry()
    {
        PacketLogModel log;
        log.append(logEntry(0));
        log.append(logEntry(1, QStringLiteral("bad\tchecksum")));
        QBuffer buffer;
        QString error;
        QVERIFY2(log.exportTo(buffer, &error), qPrintable(error)); // queued entries included
        const QStringList lines = QString::fromUtf8(buffer.data()).split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(lines[0], QStringLiteral("time\tdirection\thex\tmeaning\terror"));
        const QStringList fields = lines[2].split(u'\t');
        QCOMPARE(fields.size(), 5);
        QCOMPARE(fields[1], QStringLiteral("in"));
        QCOMPARE(fields[2], QStringLiteral("AF FA 00 0A 38 01 00 00 00 42"));
        QCOMPARE(fields[3], QStringLiteral("frame 1"));
        QCOMPARE(fields[4], QStringLiteral("bad checksum"));
        QVERIFY(fields[0].endsWith(QDateTime::fromMSecsSinceEpoch(logEntry(1).timestampMs)
                                       .toString(QStringLiteral("ss.zzz"))));
    }

    void exportToFileWritesTheFileOrSaysWhyNot()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        PacketLogModel log;
        log.append(logEntry(0));
        QString error;
        const QString path = dir.filePath(QStringLiteral("log.tsv"));
        QVERIFY2(log.exportToFile(path, &error), qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readAll().count('\n'), 2);

        QVERIFY(!log.exportToFile(dir.filePath(QStringLiteral("missing/log.tsv")), &error));
        QVERIFY(error.contains(QStringLiteral("missing/log.tsv")));
    }
};

QTEST_GUILESS_MAIN(TestPacketLogModel)
#include "tst_packetlogmodel.moc"
