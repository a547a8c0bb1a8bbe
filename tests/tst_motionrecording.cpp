// Motion recordings: the CSV file written and read back, its refusals, and the recorder that
// makes frames from telemetry batches.
#include "motionrecorder.h"
#include "motionrecording.h"

#include <QtTest>

Q_DECLARE_METATYPE(util::FileError::Code)

namespace {

feetech::FeedbackSample positionSample(quint8 id, qint64 steadyUs, double position,
                                       qint32 baud = 1000000)
{
    feetech::FeedbackSample sample;
    sample.id = id;
    sample.baud = baud;
    sample.steadyUs = steadyUs;
    sample.values[int(feetech::Quantity::Position)] = position;
    return sample;
}

} // namespace

class TestMotionRecording : public QObject
{
    Q_OBJECT

private slots:
    void aRecordingReadsBackAsItWasWritten()
    {
        feetech::MotionRecording recording;
        recording.joints = {{QStringLiteral("shoulder_pan"), 1}, {QString(), 7}};
        recording.times = {0.0, 0.02, 0.041};
        recording.frames = {{2048, 1000}, {2050, 990}, {2061, 985}};
        const QByteArray csv = feetech::motionRecordingCsv(recording);
        QCOMPARE(csv,
                 QByteArray("time_s,shoulder_pan@1,id_7\n0.000,2048,1000\n0.020,2050,990\n"
                            "0.041,2061,985\n"));
        util::FileError error;
        const auto read = feetech::motionRecordingFromCsv(csv, &error);
        QVERIFY2(read, qPrintable(error.describe()));
        QCOMPARE(read->joints.size(), 2);
        QCOMPARE(read->joints.at(0).name, QStringLiteral("shoulder_pan"));
        QCOMPARE(read->joints.at(1).id, quint8(7));
        QCOMPARE(read->times, recording.times);
        QCOMPARE(read->frames, recording.frames);
        QCOMPARE(read->duration(), 0.041);
    }

    void framesAreFoundByTheirTime()
    {
        feetech::MotionRecording recording;
        recording.times = {1.0, 1.5, 2.0};
        recording.frames = {{1}, {2}, {3}};
        QCOMPARE(recording.frameAt(0.0), 0);
        QCOMPARE(recording.frameAt(0.49), 0);
        QCOMPARE(recording.frameAt(0.5), 1);
        QCOMPARE(recording.frameAt(5.0), 2);
        QCOMPARE(feetech::MotionRecording().frameAt(0.0), -1);
    }

    void badFilesSayWhyByCode_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<util::FileError::Code>("code");
        using Code = util::FileError::Code;
        QTest::newRow("empty") << QByteArray("\n") << Code::MissingField;
        QTest::newRow("no time column") << QByteArray("id_1\n2000\n") << Code::MissingField;
        QTest::newRow("no joint") << QByteArray("time_s\n0\n") << Code::MissingField;
        QTest::newRow("no frame") << QByteArray("time_s,id_1\n") << Code::MissingField;
        QTest::newRow("an ID beyond 253") << QByteArray("time_s,id_254\n0,1\n") << Code::BadValue;
        QTest::newRow("a name without an ID")
            << QByteArray("time_s,elbow\n0,1\n") << Code::BadValue;
        QTest::newRow("one servo twice")
            << QByteArray("time_s,id_3,wrist@3\n0,1,1\n") << Code::Duplicate;
        QTest::newRow("a missing cell") << QByteArray("time_s,id_1,id_2\n0,1\n") << Code::BadValue;
        QTest::newRow("a negative time") << QByteArray("time_s,id_1\n-1,1\n") << Code::BadValue;
        QTest::newRow("time going back") << QByteArray("time_s,id_1\n2,1\n1,1\n") << Code::BadValue;
        QTest::newRow("a word for a position")
            << QByteArray("time_s,id_1\n0,left\n") << Code::BadValue;
    }

    void badFilesSayWhyByCode()
    {
        QFETCH(QByteArray, csv);
        QFETCH(util::FileError::Code, code);
        util::FileError error;
        QVERIFY(!feetech::motionRecordingFromCsv(csv, &error));
        QCOMPARE(error.code(), code);
        QVERIFY(!error.describe().isEmpty());
    }

    void nothingRecordedIsNotSaved()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("none.csv"));
        util::FileError error;
        QVERIFY(!feetech::saveMotionRecording(path, {}, &error));
        QCOMPARE(error.code(), util::FileError::Code::NothingToSave);
        QVERIFY(!QFile::exists(path));
    }

    void theRecorderMakesAFrameOfEachCycleThatSawEveryJoint()
    {
        feetech::MotionRecorder recorder;
        recorder.start({{QString(), 1}, {QString(), 2}}, 1000000);
        // A servo at another rate with the same ID, and one that is no joint: left out.
        recorder.addSamples({positionSample(1, 1000000, 100),
                             positionSample(1, 1000100, 999, 115200),
                             positionSample(3, 1000200, 555), positionSample(2, 1000300, 200)});
        recorder.addSamples({positionSample(1, 1020000, 110)});
        recorder.addSamples({positionSample(2, 1020400, 210), positionSample(1, 1040000, 120),
                             positionSample(2, 1040300, 220)});
        const feetech::MotionRecording &recording = recorder.recording();
        QCOMPARE(recording.frames.size(), 3);
        QCOMPARE(recording.times, (QVector<double> {0.0, 0.02, 0.04}));
        QCOMPARE(recording.frames.at(0), (QVector<qint32> {100, 200}));
        QCOMPARE(recording.frames.at(1), (QVector<qint32> {110, 210}));
        QCOMPARE(recording.frames.at(2), (QVector<qint32> {120, 220}));
    }

    void aJointThatMissesACycleKeepsItsLastPosition()
    {
        feetech::MotionRecorder recorder;
        recorder.start({{QString(), 1}, {QString(), 2}}, 1000000);
        // No frame before every joint has been seen once.
        recorder.addSamples({positionSample(1, 0, 100), positionSample(1, 20000, 105)});
        QVERIFY(recorder.recording().isEmpty());
        recorder.addSamples({positionSample(2, 20300, 200), positionSample(1, 40000, 110),
                             positionSample(1, 60000, 120)});
        const feetech::MotionRecording &recording = recorder.recording();
        QCOMPARE(recording.frames.size(), 2);
        QCOMPARE(recording.frames.at(0), (QVector<qint32> {105, 200}));
        QCOMPARE(recording.frames.at(1), (QVector<qint32> {110, 200}));
        QCOMPARE(recording.times.at(1), 0.02);
    }
};

QTEST_GUILESS_MAIN(TestMotionRecording)
#include "tst_motionrecording.moc"
