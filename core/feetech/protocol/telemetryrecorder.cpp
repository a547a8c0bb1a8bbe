// The telemetry CSV writer: header, one row per sample, buffered and flushed on a timer.
#include "telemetryrecorder.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSignalBlocker>
#include <QTextStream>
#include <QTimer>

#include <algorithm>

namespace feetech {

TelemetryRecorder::TelemetryRecorder(QObject *parent)
    : QObject(parent)
    , m_flushTimer(new QTimer(this))
{
    m_flushTimer->setInterval(m_flushIntervalMs);
    connect(m_flushTimer, &QTimer::timeout, this, [this] {
        if (flush())
            emit flushed(m_rows);
    });
}

TelemetryRecorder::~TelemetryRecorder()
{
    // No one listens any more: a last failure has nobody to tell.
    const QSignalBlocker blocker(this);
    finish();
}

bool TelemetryRecorder::open(const QString &path, util::FileError *error)
{
    using util::FileError;
    finish();
    m_path = path;
    const auto refuse = [this, error](const FileError &why) {
        m_error = why.describe();
        util::report(error, why);
        return false;
    };
    if (path.isEmpty())
        return refuse(FileError(FileError::Code::NoFileName,
                                tr("No file name was given for the recording.")));
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        return refuse(FileError(FileError::Code::CannotWrite, file->errorString())
                          .inFile(path, FileError::Action::Recording));
    }
    m_file = std::move(file);
    m_device = m_file.get();
    m_ownStream = std::make_unique<QTextStream>(m_device);
    return begin(m_ownStream.get(), error);
}

bool TelemetryRecorder::start(QIODevice *device, util::FileError *error)
{
    finish();
    m_path.clear();
    if (!device || !device->isWritable()) {
        m_error = tr("The telemetry output is not open for writing.");
        util::report(error, util::FileError(util::FileError::Code::CannotWrite, m_error));
        return false;
    }
    m_device = device;
    m_ownStream = std::make_unique<QTextStream>(m_device);
    return begin(m_ownStream.get(), error);
}

bool TelemetryRecorder::start(QTextStream &stream, util::FileError *error)
{
    finish();
    m_path.clear();
    return begin(&stream, error);
}

bool TelemetryRecorder::begin(QTextStream *stream, util::FileError *error)
{
    m_stream = stream;
    m_rows = 0;
    m_wholeBytes = 0;
    m_wholeRows = 0;
    m_startUs = steadyMicroseconds();
    m_error.clear();
    *m_stream << telemetryCsvHeader() << '\n';
    // An unwritable target (a full disk) shows at once, not half a second into the recording.
    if (!flush()) {
        // The sentence names the file and what became of it.
        util::report(error, util::FileError(util::FileError::Code::CannotWrite, m_error));
        return false;
    }
    if (m_flushIntervalMs > 0)
        m_flushTimer->start();
    return true;
}

bool TelemetryRecorder::finish()
{
    if (!m_stream)
        return true;
    const bool written = flush();
    close();
    return written;
}

void TelemetryRecorder::setFlushInterval(int ms)
{
    m_flushIntervalMs = std::max(0, ms);
    m_flushTimer->setInterval(m_flushIntervalMs);
    if (m_flushIntervalMs == 0)
        m_flushTimer->stop();
    else if (m_stream)
        m_flushTimer->start();
}

bool TelemetryRecorder::write(const FeedbackSample &sample)
{
    // Samples taken before the recording started are not part of it.
    if (!m_stream || sample.steadyUs < m_startUs)
        return false;
    *m_stream << telemetryCsvRow(sample, m_startUs) << '\n';
    ++m_rows;
    return true;
}

int TelemetryRecorder::write(const QVector<FeedbackSample> &samples)
{
    int written = 0;
    for (const FeedbackSample &sample : samples)
        written += write(sample) ? 1 : 0;
    return written;
}

bool TelemetryRecorder::flush()
{
    if (!m_stream)
        return true;
    m_stream->flush();
    const auto *file = qobject_cast<const QFileDevice *>(m_device);
    if (m_stream->status() != QTextStream::Ok || (file && file->error() != QFileDevice::NoError)) {
        fail(m_device ? m_device->errorString() : tr("The telemetry output cannot be written."));
        return false;
    }
    if (m_file) { // everything up to here is on the disk, whole
        m_wholeBytes = m_file->size();
        m_wholeRows = m_rows;
    }
    return true;
}

void TelemetryRecorder::fail(const QString &reason)
{
    m_error = reason;
    const bool ownFile = m_file != nullptr;
    close();
    // A regular file only: a pipe or a device named as the target stays. Hours of rows are
    // not thrown away for their last half second: the file is cut back to the rows that were
    // written whole (shrinking needs no room on the disk), or removed if there were none.
    const QString path = QDir::toNativeSeparators(m_path);
    if (ownFile && QFileInfo(m_path).isFile()) {
        if (m_wholeRows > 0 && QFile::resize(m_path, m_wholeBytes))
            m_error = tr("%1; the %n row(s) written before it are kept whole in %2.", nullptr,
                         int(m_wholeRows))
                          .arg(reason, path);
        else if (QFile::remove(m_path))
            m_error = tr("%1; the incomplete file %2 was removed.").arg(reason, path);
    }
    emit failed(m_error);
}

void TelemetryRecorder::close()
{
    m_flushTimer->stop();
    m_stream = nullptr;
    m_ownStream.reset();
    if (m_file)
        m_file->close();
    m_file.reset();
    m_device = nullptr;
}

} // namespace feetech
