// Record and replay: joints moved by hand recorded on the connected Feetech bus, shown on a
// timeline, saved and opened as CSV, and played back eased in, at a speed, looped, held.
#pragma once

#include "motioncapture.h"
#include "motionplayer.h"
#include "motionrecording.h"

#include <QDialog>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSlider;
class QSpinBox;

namespace feetech {
class BusClient;
class OperationReply;
struct OperationProgress;
struct OperationResult;
} // namespace feetech

// Non-modal. Recording streams the joints picked (torque left as it is); playing submits one
// replay operation, whose Stop holds the arm where it stands. Nothing here blocks: both go
// through the client's telemetry hub and its session.
class RecordReplayDialog : public QDialog
{
    Q_OBJECT

public:
    explicit RecordReplayDialog(feetech::BusClient *client, QWidget *parent = nullptr);

    const feetech::MotionRecording &recording() const { return m_recording; }
    // The recording in `path` replaces the one shown; false (the reason shown) when unreadable.
    bool openFile(const QString &path);
    bool saveFile(const QString &path);

    QListWidget *jointList() const { return m_joints; }
    QPushButton *recordButton() const { return m_record; }
    QPushButton *playButton() const { return m_play; }
    QPushButton *stopButton() const { return m_stop; }
    QSlider *timeline() const { return m_timeline; }
    QDoubleSpinBox *speedBox() const { return m_speed; }
    QSpinBox *loopBox() const { return m_loops; }
    QCheckBox *releaseBox() const { return m_release; }
    QProgressBar *progressBar() const { return m_progress; }
    QLabel *statusLabel() const { return m_status; }

signals:
    // A replay ended: held, released, stopped (held where it stood) or failed.
    void replayFinished(const feetech::OperationResult &result);

protected:
    void hideEvent(QHideEvent *event) override;

private:
    void fillJoints();
    // Torque off on the joints to record (one at a time), then the recording starts.
    void startRecording();
    void switchNextTorqueOff();
    void stopRecording();
    void play();
    void stop();
    void chooseFileToOpen();
    void chooseFileToSave();
    void onFramesRecorded(int frames);
    void onReplayProgress(const feetech::OperationProgress &progress);
    void onReplayFinished(const feetech::OperationResult &result);
    void showFrame(int frame);
    void updateButtons();
    void showStatus(const QString &text, bool problem = false);

    feetech::BusClient *m_client = nullptr;
    feetech::MotionCapture *m_capture = nullptr;
    feetech::MotionPlayer *m_player = nullptr;
    feetech::MotionRecording m_recording;
    QListWidget *m_joints = nullptr;
    QPushButton *m_record = nullptr;
    QPushButton *m_open = nullptr;
    QPushButton *m_save = nullptr;
    QSlider *m_timeline = nullptr;
    QLabel *m_position = nullptr;
    QDoubleSpinBox *m_speed = nullptr;
    QSpinBox *m_loops = nullptr;
    QCheckBox *m_release = nullptr;
    QPushButton *m_play = nullptr;
    QPushButton *m_stop = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QVector<int> m_recordIndexes; // the joints a recording about to start takes
    int m_torqueOffNext = -1; // which of them has its torque switched off now; -1: none
};
