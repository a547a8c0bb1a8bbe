// Tests the telemetry CSV recorder: rows that parse back, absent values, samples before the
// start, an unwritable file, a device such as stdout, the flush interval and a failing disk.
#include "telemetrycsv.h"
#include "telemetryrecorder.h"

#include <QBuffer>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using feetech::FeedbackSample;
using feetech::Quantity;
using feetech::TelemetryRecorder;

namespace {

FeedbackSample sampleAt(quint8 id, qint64 steadyUs, double position)
{
    FeedbackSample sample;
    sample.id = id;
    sample.baud = 1000000;
    sample.steadyUs = steadyUs;
    sample.values[int(Quantity::Position)] = position;
    sample.values[int(Quantity::Speed)] = -35.0;
    sample.values[int(Quantity::Voltage)] = 12.1;
    sample.values[int(Quantity::Temperature)] = 31.0;
    return sample;
}

} // namespace

class TestTelemetryRecorder : public QObject
{
    Q_OBJECT

private slots:
    void init() { QVERIFY(m_dir.isValid()); }

    void rowsWrittenToAFileParseBackWithTheirIdsTimesAndValues()
    {
        const QString path = m_dir.filePath(QStringLiteral("rows.csv"));
        TelemetryRecorder recorder;
        util::FileError error;
        QVERIFY2(recorder.open(path, &error), qPrintable(error.describe()));
        QVERIFY(recorder.isRecording());
        QCOMPARE(recorder.fileName(), path);
        const qint64 start = recorder.startUs();
        QVector<FeedbackSample> samples;
        for (int i = 0; i < 20; ++i) {
            FeedbackSample sample = sampleAt(quint8(1 + i % 3), start + i * 20000, 2000.0 + i);
            sample.servoStatus = i == 7 ? 0x20 : 0;
            sample.moving = i % 2 == 0;
            samples.append(sample);
        }
        QCOMPARE(recorder.write(samples), samples.size());
        QCOMPARE(recorder.rowCount(), qint64(samples.size()));
        QVERIFY(recorder.finish());
        QVERIFY(!recorder.isRecording());

        QString unreadable;
        const auto rows = testsupport::readTelemetryCsv(path, &unreadable);
        QVERIFY2(rows, qPrintable(unreadable));
        testsupport::compareTelemetryRows(*rows, samples, start);
    }

    void valuesAServoDoesNotReportStayEmptyCells()
    {
        QBuffer buffer;
        QVERIFY(buffer.open(QIODevice::WriteOnly));
        TelemetryRecorder recorder;
        QVERIFY(recorder.start(&buffer));
        FeedbackSample sample = sampleAt(4, recorder.startUs(), 512.0);
        sample.values[int(Quantity::Current)].reset();
        sample.values[int(Quantity::Load)].reset();
        QVERIFY(recorder.write(sample));
        QVERIFY(recorder.finish());

        QString error;
        const auto rows = feetech::parseTelemetryCsv(QString::fromUtf8(buffer.data()), &error);
        QVERIFY2(rows, qPrintable(error));
        QCOMPARE(rows->size(), 1);
        QVERIFY(!rows->first().values.at(int(Quantity::Current)).has_value());
        QVERIFY(!rows->first().values.at(int(Quantity::Load)).has_value());
        QCOMPARE(rows->first().values.at(int(Quantity::Position)), std::optional<double>(512.0));
    }

    void samplesTakenBeforeTheStartAreNotRecorded()
    {
        QBuffer buffer;
        QVERIFY(buffer.open(QIODevice::WriteOnly));
        TelemetryRecorder recorder;
        QVERIFY(recorder.start(&buffer));
        recorder.setStartUs(1000000);
        QVERIFY(!recorder.write(sampleAt(1, 999999, 1.0)));
        QVERIFY(recorder.write(sampleAt(1, 1000000, 2.0)));
        QCOMPARE(recorder.rowCount(), qint64(1));
        QVERIFY(recorder.finish());
        QString error;
        const auto rows = feetech::parseTelemetryCsv(QString::fromUtf8(buffer.data()), &error);
        QVERIFY2(rows, qPrintable(error));
        QCOMPARE(rows->size(), 1);
        QCOMPARE(rows->first().timeSeconds, 0.0);
    }

    void writingToABufferGivesTheHeaderAndOneLinePerSample()
    {
        QBuffer buffer;
        QVERIFY(buffer.open(QIODevice::WriteOnly));
        TelemetryRecorder recorder;
        util::FileError error;
        QVERIFY2(recorder.start(&buffer, &error), qPrintable(error.describe()));
        QVERIFY(recorder.fileName().isEmpty());
        // The header is out at once, before any sample.
        QCOMPARE(buffer.data(), (feetech::telemetryCsvHeader() + QLatin1Char('\n')).toUtf8());
        const FeedbackSample sample = sampleAt(2, recorder.startUs() + 250000, 100.0);
        recorder.write(sample);
        QVERIFY(recorder.flush());
        const QStringList lines = QString::fromUtf8(buffer.data()).split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 3); // header, row, and the empty rest after the last newline
        QCOMPARE(lines.at(1), feetech::telemetryCsvRow(sample, recorder.startUs()));
        QVERIFY(recorder.finish());
        // The device is the caller's: it stays open.
        QVERIFY(buffer.isOpen());
    }

    void writingIntoACallersTextStreamGivesTheSameRows()
    {
        QString text;
        QTextStream stream(&text);
        TelemetryRecorder recorder;
        util::FileError error;
        QVERIFY2(recorder.start(stream, &error), qPrintable(error.describe()));
        QCOMPARE(text, feetech::telemetryCsvHeader() + QLatin1Char('\n'));
        const FeedbackSample sample = sampleAt(3, recorder.startUs() + 500000, 12.5);
        QVERIFY(recorder.write(sample));
        QVERIFY(recorder.finish());
        QCOMPARE(text.split(QLatin1Char('\n')).at(1),
                 feetech::telemetryCsvRow(sample, recorder.startUs()));
        // The stream is the caller's: it goes on after the recording.
        stream << "after";
        stream.flush();
        QVERIFY(text.endsWith(QStringLiteral("after")));
    }

    void aDeviceNotOpenForWritingIsRefused()
    {
        QBuffer buffer;
        TelemetryRecorder recorder;
        util::FileError error;
        QVERIFY(!recorder.start(&buffer, &error));
        QCOMPARE(error.code(), util::FileError::Code::CannotWrite);
        QVERIFY(!error.describe().isEmpty());
        QVERIFY(!recorder.isRecording());
    }

    void anUnwritablePathGivesAnErrorNamingTheFile()
    {
        const QString path = m_dir.filePath(QStringLiteral("no/such/folder/rows.csv"));
        TelemetryRecorder recorder;
        util::FileError error;
        QVERIFY(!recorder.open(path, &error));
        QVERIFY(!recorder.isRecording());
        QCOMPARE(error.code(), util::FileError::Code::CannotWrite);
        QCOMPARE(error.path(), path);
        QVERIFY2(error.describe().contains(QDir::toNativeSeparators(path)),
                 qPrintable(error.describe()));
        QCOMPARE(recorder.errorString(), error.describe());
        QVERIFY(!recorder.write(sampleAt(1, recorder.startUs(), 1.0)));
    }

    void anEmptyFileNameIsRefused()
    {
        TelemetryRecorder recorder;
        util::FileError error;
        QVERIFY(!recorder.open(QString(), &error));
        QCOMPARE(error.code(), util::FileError::Code::NoFileName);
        QVERIFY(!error.describe().isEmpty());
    }

    void rowsReachTheFileWithinTheFlushInterval()
    {
        const QString path = m_dir.filePath(QStringLiteral("flushed.csv"));
        TelemetryRecorder recorder;
        recorder.setFlushInterval(20);
        QSignalSpy flushed(&recorder, &TelemetryRecorder::flushed);
        QVERIFY(recorder.open(path));
        recorder.write(sampleAt(3, recorder.startUs(), 42.0));
        QTRY_VERIFY_WITH_TIMEOUT(!flushed.isEmpty(), 5000);
        QCOMPARE(flushed.last().at(0).toLongLong(), qint64(1));
        QString error;
        const auto rows = testsupport::readTelemetryCsv(path, &error); // while still recording
        QVERIFY2(rows, qPrintable(error));
        QCOMPARE(rows->size(), 1);
    }

    void aFullDiskEndsTheRecordingAndSaysWhy()
    {
        if (!QFile::exists(QStringLiteral("/dev/full")))
            QSKIP("needs /dev/full to fail writes");
        TelemetryRecorder recorder;
        QSignalSpy failed(&recorder, &TelemetryRecorder::failed);
        util::FileError error;
        QVERIFY(!recorder.open(QStringLiteral("/dev/full"), &error));
        QCOMPARE(error.code(), util::FileError::Code::CannotWrite);
        QCOMPARE(failed.count(), 1);
        QVERIFY(!failed.first().at(0).toString().isEmpty());
        QVERIFY(!recorder.isRecording());
    }

private:
    QTemporaryDir m_dir;
};

QTEST_GUILESS_MAIN(TestTelemetryRecorder)
#include "tst_telemetryrecorder.moc"
