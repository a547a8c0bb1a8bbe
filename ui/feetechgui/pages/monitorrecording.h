// The Monitor page's Recording group: the CSV file chosen, feetech::TelemetryRecorder writing it,
// and the label saying where it goes and how it ended.
#pragma once

#include "telemetryrecorder.h"

#include <QGroupBox>

class QLabel;
class QPushButton;

class MonitorRecording : public QGroupBox
{
    Q_OBJECT

public:
    // A recording reaches the disk at least this often.
    static constexpr int kFlushIntervalMs = feetech::TelemetryRecorder::kDefaultFlushIntervalMs;

    explicit MonitorRecording(QWidget *parent = nullptr);
    ~MonitorRecording() override;

    // Writes every sample given to the recorder from now on to `path` as CSV; false and *error
    // (also reported) when the file cannot be written.
    bool startRecording(const QString &path, util::FileError *error = nullptr);
    void stopRecording();
    bool isRecording() const { return m_recorder->isRecording(); }
    // The samples go here; its rows and start time are the recording's.
    feetech::TelemetryRecorder *recorder() const { return m_recorder; }

signals:
    void recordingChanged(bool recording);
    // What the page's message line should say: empty to clear it.
    void reported(const QString &text, bool isError);
    void problem(const QString &message);

private:
    void toggleRecording();
    void updateLabel();
    void updateButton();
    void fail(const QString &why);

    feetech::TelemetryRecorder *m_recorder = nullptr;
    QPushButton *m_button = nullptr;
    QLabel *m_label = nullptr;
};
