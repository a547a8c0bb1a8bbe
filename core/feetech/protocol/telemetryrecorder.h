// Writes telemetry samples as CSV (telemetryCsvHeader / telemetryCsvRow) to a file or to any
// open device, for the Monitor page's recordings and for `servoctl feetech monitor --csv`.
#pragma once

#include "fileerror.h"
#include "telemetry.h"

#include <QObject>
#include <QString>
#include <QVector>

#include <memory>

class QFile;
class QIODevice;
class QTextStream;
class QTimer;

namespace feetech {

// Rows are buffered and written out every flushInterval() (or by flush()): a recording at full
// bus speed must not cost a write() per sample, yet a crash should lose at most half a second.
// The first failure to write ends the recording: failed() says why, and nothing more is written.
// A file it opened is then cut back to the rows flushed whole before (removed when there were
// none), so a full disk leaves no half-written row. It is written straight to its name, not
// through QSaveFile, whose unnamed temporary file (O_TMPFILE on Linux) would lose a whole
// recording to a crash.
class TelemetryRecorder : public QObject
{
    Q_OBJECT

public:
    static constexpr int kDefaultFlushIntervalMs = 500;

    explicit TelemetryRecorder(QObject *parent = nullptr);
    ~TelemetryRecorder() override; // finishes a recording still open

    // Creates (or truncates) `path` and writes the header. False and *error (NoFileName, or
    // CannotWrite naming the file) when it cannot be opened; nothing is recording then.
    bool open(const QString &path, util::FileError *error = nullptr);
    // Writes the header to `device`, which the caller keeps open and owns (stdout for the
    // command line). False and *error (CannotWrite) when it is not open for writing.
    bool start(QIODevice *device, util::FileError *error = nullptr);
    // Writes into a text stream the caller owns (servoctl's standard output, which may be a
    // string in tests); rows reach it at each flush.
    bool start(QTextStream &stream, util::FileError *error = nullptr);
    // Flushes and, for a file it opened, closes it. False when the last rows could not be
    // written (failed() has been emitted then).
    bool finish();

    bool isRecording() const { return m_stream != nullptr; }
    // The file open() last opened, kept after the recording ends for the messages about it;
    // empty after start().
    QString fileName() const { return m_path; }
    qint64 rowCount() const { return m_rows; }
    // Time 0 of the recording on the samples' clock (steadyMicroseconds() at open or start);
    // samples taken before it are not recorded.
    qint64 startUs() const { return m_startUs; }
    void setStartUs(qint64 startUs) { m_startUs = startUs; }
    QString errorString() const { return m_error; } // the reason of the last failure

    // 0: rows are written out only by flush() and finish().
    void setFlushInterval(int ms);
    int flushInterval() const { return m_flushIntervalMs; }

    // True when the sample became a row.
    bool write(const FeedbackSample &sample);
    int write(const QVector<FeedbackSample> &samples); // the rows written
    bool flush();

signals:
    void flushed(qint64 rows); // by the interval timer, after the rows reached the device
    void failed(const QString &reason);

private:
    bool begin(QTextStream *stream, util::FileError *error);
    void fail(const QString &reason);
    void close();

    std::unique_ptr<QFile> m_file; // only when open() opened it
    QString m_path;
    QIODevice *m_device = nullptr;
    std::unique_ptr<QTextStream> m_ownStream; // over m_device
    QTextStream *m_stream = nullptr; // m_ownStream, or the caller's
    QTimer *m_flushTimer = nullptr;
    int m_flushIntervalMs = kDefaultFlushIntervalMs;
    qint64 m_rows = 0;
    qint64 m_wholeBytes = 0; // of a file it opened: the size at the last successful flush
    qint64 m_wholeRows = 0; // the rows in those bytes
    qint64 m_startUs = 0;
    QString m_error;
};

} // namespace feetech
