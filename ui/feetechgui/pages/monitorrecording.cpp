// The Monitor page's CSV recording: the file chosen, feetech::TelemetryRecorder writing it,
// and what the group says while it records and when it ends or fails.
#include "monitorrecording.h"

#include "recentfiles.h"
#include "widgethelpers.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>

MonitorRecording::MonitorRecording(QWidget *parent)
    : QGroupBox(tr("Recording"), parent)
{
    auto *layout = new QVBoxLayout(this);
    m_button = widgethelpers::actionButton(
        tr("Record CSV…"), "monitorRecordButton",
        tr("Write every sample of the ticked servos to a CSV file"), this);
    connect(m_button, &QPushButton::clicked, this, &MonitorRecording::toggleRecording);
    layout->addWidget(m_button);
    m_label = new QLabel(this);
    m_label->setObjectName(QStringLiteral("monitorRecordingLabel"));
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_label);

    m_recorder = new feetech::TelemetryRecorder(this);
    m_recorder->setFlushInterval(kFlushIntervalMs);
    connect(m_recorder, &feetech::TelemetryRecorder::flushed, this, &MonitorRecording::updateLabel);
    connect(m_recorder, &feetech::TelemetryRecorder::failed, this, &MonitorRecording::fail);
    updateLabel();
}

MonitorRecording::~MonitorRecording()
{
    stopRecording(); // what was buffered reaches the disk
}

bool MonitorRecording::startRecording(const QString &path, util::FileError *error)
{
    stopRecording();
    // A header that could not be written goes through fail(), which says why; a file that
    // could not be opened is said here.
    QString failure;
    const QMetaObject::Connection watch =
        connect(this, &MonitorRecording::problem, this,
                [&failure](const QString &message) { failure = message; });
    util::FileError why;
    const bool opened = m_recorder->open(path, &why);
    disconnect(watch);
    if (!opened) {
        if (!failure.isEmpty())
            why = util::FileError(why.code(), failure);
        else
            emit reported(why.describe(), true);
        util::report(error, why);
        return false;
    }
    emit reported({}, false);
    updateLabel();
    updateButton();
    emit recordingChanged(true);
    return true;
}

void MonitorRecording::stopRecording()
{
    if (!isRecording())
        return;
    if (!m_recorder->finish())
        return; // fail() has said why and closed it
    const QString path = m_recorder->fileName();
    m_label->setText(tr("%Ln row(s) saved to %1.", nullptr, int(m_recorder->rowCount()))
                         .arg(QFileInfo(path).fileName()));
    m_label->setToolTip(QDir::toNativeSeparators(path));
    updateButton();
    emit recordingChanged(false);
}

void MonitorRecording::toggleRecording()
{
    if (isRecording()) {
        stopRecording();
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Record telemetry"),
        recentfiles::suggestedPath(recentfiles::Kind::TelemetryRecording,
                                   QStringLiteral("servobench-telemetry.csv")),
        tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    startRecording(path);
    if (isRecording())
        recentfiles::add(recentfiles::Kind::TelemetryRecording, path);
}

void MonitorRecording::updateLabel()
{
    if (!isRecording()) {
        if (m_label->text().isEmpty())
            m_label->setText(tr("Not recording."));
        return;
    }
    const QString path = m_recorder->fileName();
    m_label->setText(tr("Recording to %1: %Ln row(s).", nullptr, int(m_recorder->rowCount()))
                         .arg(QFileInfo(path).fileName()));
    m_label->setToolTip(QDir::toNativeSeparators(path));
}

void MonitorRecording::updateButton()
{
    m_button->setText(isRecording() ? tr("Stop recording") : tr("Record CSV…"));
}

void MonitorRecording::fail(const QString &why)
{
    const QString path = QDir::toNativeSeparators(m_recorder->fileName());
    const QString message =
        tr("Recording to %1 failed after %Ln row(s): %2", nullptr, int(m_recorder->rowCount()))
            .arg(path, why);
    m_label->setText(tr("Recording failed."));
    emit reported(message, true);
    emit problem(message);
    updateButton();
    emit recordingChanged(false);
}
