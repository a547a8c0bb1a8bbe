// The Monitor page's CSV recording: the file chosen, feetech::TelemetryRecorder writing it,
// and what the page says while it records and when it ends or fails.
#include "monitorpage.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QStandardPaths>

bool MonitorPage::startRecording(const QString &path, QString *error)
{
    stopRecording();
    // A header that could not be written goes through failRecording(), which says why; a file
    // that could not be opened is said here.
    bool reported = false;
    const QMetaObject::Connection watch = connect(m_recorder, &feetech::TelemetryRecorder::failed,
                                                  this, [&reported] { reported = true; });
    QString why;
    const bool opened = m_recorder->open(path, &why);
    disconnect(watch);
    if (!opened) {
        if (reported)
            why = m_message->text();
        else
            showMessage(why, true);
        if (error)
            *error = why;
        return false;
    }
    showMessage({}, false);
    updateRecordingLabel();
    updateControls();
    emit recordingChanged(true);
    return true;
}

void MonitorPage::stopRecording()
{
    if (!isRecording())
        return;
    if (!m_recorder->finish())
        return; // failRecording() has said why and closed it
    const QString path = m_recorder->fileName();
    m_recordingLabel->setText(tr("%Ln row(s) saved to %1.", nullptr, int(recordedRows()))
                                  .arg(QFileInfo(path).fileName()));
    m_recordingLabel->setToolTip(QDir::toNativeSeparators(path));
    updateControls();
    emit recordingChanged(false);
}

void MonitorPage::toggleRecording()
{
    if (isRecording()) {
        stopRecording();
        return;
    }
    const QString directory = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Record telemetry"),
        QDir(directory).filePath(QStringLiteral("servobench-telemetry.csv")),
        tr("CSV files (*.csv)"));
    if (!path.isEmpty())
        startRecording(path);
}

void MonitorPage::updateRecordingLabel()
{
    if (!isRecording()) {
        if (m_recordingLabel->text().isEmpty())
            m_recordingLabel->setText(tr("Not recording."));
        return;
    }
    const QString path = m_recorder->fileName();
    m_recordingLabel->setText(tr("Recording to %1: %Ln row(s).", nullptr, int(recordedRows()))
                                  .arg(QFileInfo(path).fileName()));
    m_recordingLabel->setToolTip(QDir::toNativeSeparators(path));
}

void MonitorPage::failRecording(const QString &why)
{
    const QString path = QDir::toNativeSeparators(m_recorder->fileName());
    const QString message =
        tr("Recording to %1 failed after %Ln row(s): %2", nullptr, int(recordedRows()))
            .arg(path, why);
    m_recordingLabel->setText(tr("Recording failed."));
    showMessage(message, true);
    emit problem(message);
    updateControls();
    emit recordingChanged(false);
}
