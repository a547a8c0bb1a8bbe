// Record and replay: the dialog around MotionCapture, MotionPlayer and a recording's CSV file.
#include "recordreplaydialog.h"

#include "busclient.h"
#include "jointnames.h"
#include "operationreply.h"
#include "palette.h"
#include "recentfiles.h"
#include "servolist.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHideEvent>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

namespace {

constexpr int kAddressRole = Qt::UserRole;
constexpr int kBaudRole = Qt::UserRole + 1;

} // namespace

RecordReplayDialog::RecordReplayDialog(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_capture(new feetech::MotionCapture(client, this))
    , m_player(new feetech::MotionPlayer(client, this))
{
    setObjectName(QStringLiteral("recordReplayDialog"));
    setWindowTitle(tr("Record and replay"));
    setModal(false);

    auto *joints = new QGroupBox(tr("Joints to record"), this);
    m_joints = new QListWidget(joints);
    m_joints->setObjectName(QStringLiteral("recordJoints"));
    m_joints->setToolTip(tr("The servos whose positions are recorded; Record switches their "
                            "torque off so that they can be moved by hand"));
    auto *jointLayout = new QVBoxLayout(joints);
    jointLayout->addWidget(m_joints);

    m_record = new QPushButton(tr("Torque off and &record"), this);
    m_record->setObjectName(QStringLiteral("recordButton"));
    m_record->setToolTip(tr("Support the arm: torque goes off on the joints to record, so that "
                            "you can move them by hand"));
    // As wide as its widest text: the row does not move when it changes.
    m_record->setMinimumWidth(std::max(
        m_record->sizeHint().width(),
        m_record->fontMetrics().horizontalAdvance(tr("Stop &recording").remove(u'&')) * 5 / 4));
    m_open = new QPushButton(tr("&Open…"), this);
    m_open->setObjectName(QStringLiteral("openRecordingButton"));
    m_save = new QPushButton(tr("&Save…"), this);
    m_save->setObjectName(QStringLiteral("saveRecordingButton"));
    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_record);
    fileRow->addStretch();
    fileRow->addWidget(m_open);
    fileRow->addWidget(m_save);

    auto *timelineBox = new QGroupBox(tr("Recording"), this);
    m_timeline = new QSlider(Qt::Horizontal, timelineBox);
    m_timeline->setObjectName(QStringLiteral("recordingTimeline"));
    m_timeline->setRange(0, 0);
    m_position = new QLabel(tr("Nothing recorded yet."), timelineBox);
    m_position->setObjectName(QStringLiteral("recordingPosition"));
    m_position->setWordWrap(true);
    auto *timelineLayout = new QVBoxLayout(timelineBox);
    timelineLayout->addWidget(m_timeline);
    timelineLayout->addWidget(m_position);

    auto *playBox = new QGroupBox(tr("Replay"), this);
    m_speed = new QDoubleSpinBox(playBox);
    m_speed->setObjectName(QStringLiteral("replaySpeed"));
    m_speed->setRange(0.1, 10.0);
    m_speed->setSingleStep(0.1);
    m_speed->setDecimals(1);
    m_speed->setValue(1.0);
    m_speed->setSuffix(tr(" ×"));
    m_speed->setToolTip(tr("2 plays twice as fast, 0.5 at half speed"));
    m_loops = new QSpinBox(playBox);
    m_loops->setObjectName(QStringLiteral("replayLoops"));
    m_loops->setRange(1, 1000);
    m_loops->setToolTip(tr("Between two loops the arm eases back to the first frame"));
    m_release = new QCheckBox(tr("Switch torque off at the end"), playBox);
    m_release->setObjectName(QStringLiteral("replayRelease"));
    m_release->setToolTip(tr("Otherwise the arm holds the last frame"));
    m_play = new QPushButton(tr("&Play"), playBox);
    m_play->setObjectName(QStringLiteral("playButton"));
    m_play->setToolTip(tr("Torque on where the arm stands, a gentle move to the first frame, "
                          "then the frames at their recorded times"));
    m_stop = new QPushButton(tr("S&top"), playBox);
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_stop->setToolTip(tr("Stop recording, or stop the replay with the arm held where it "
                          "stands"));
    auto *form = new QFormLayout;
    form->addRow(tr("Speed:"), m_speed);
    form->addRow(tr("Loops:"), m_loops);
    form->addRow(QString(), m_release);
    auto *playRow = new QHBoxLayout;
    playRow->addStretch();
    playRow->addWidget(m_play);
    playRow->addWidget(m_stop);
    auto *playLayout = new QVBoxLayout(playBox);
    playLayout->addLayout(form);
    playLayout->addLayout(playRow);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("replayProgress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("recordReplayStatus"));
    m_status->setWordWrap(true);
    // Two lines are kept for it: a longer sentence does not push the buttons around.
    m_status->setMinimumHeight(m_status->fontMetrics().lineSpacing() * 2);
    m_status->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(joints);
    layout->addLayout(fileRow);
    layout->addWidget(timelineBox);
    layout->addWidget(playBox);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    // Wide enough for a frame's positions on two lines rather than a column of them.
    setMinimumWidth(fontMetrics().averageCharWidth() * 60);

    connect(m_record, &QPushButton::clicked, this, [this] {
        if (m_capture->isRecording())
            stopRecording();
        else
            startRecording();
    });
    connect(m_open, &QPushButton::clicked, this, &RecordReplayDialog::chooseFileToOpen);
    connect(m_save, &QPushButton::clicked, this, &RecordReplayDialog::chooseFileToSave);
    connect(m_play, &QPushButton::clicked, this, &RecordReplayDialog::play);
    connect(m_stop, &QPushButton::clicked, this, &RecordReplayDialog::stop);
    connect(m_timeline, &QSlider::valueChanged, this, &RecordReplayDialog::showFrame);
    connect(m_capture, &feetech::MotionCapture::framesRecorded, this,
            &RecordReplayDialog::onFramesRecorded);
    connect(m_capture, &feetech::MotionCapture::stopped, this, [this] {
        m_recording = m_capture->recording();
        m_timeline->setRange(0, std::max(0, int(m_recording.frames.size()) - 1));
        showStatus(m_recording.isEmpty() ? tr("Nothing was recorded: not every joint answered.")
                                         : tr("Recorded %n frame(s) over %1 s.", nullptr,
                                              int(m_recording.frames.size()))
                                               .arg(m_recording.duration(), 0, 'f', 2),
                   m_recording.isEmpty());
        showFrame(m_timeline->value());
        updateButtons();
    });
    connect(client->servos(), &feetech::ServoList::servosChanged, this,
            &RecordReplayDialog::fillJoints);
    connect(client, &feetech::BusClient::statusChanged, this, &RecordReplayDialog::updateButtons);
    connect(client, &feetech::BusClient::busyChanged, this, &RecordReplayDialog::updateButtons);
    fillJoints();
}

void RecordReplayDialog::fillJoints()
{
    QSet<feetech::ServoAddress> checked;
    for (int row = 0; row < m_joints->count(); ++row) {
        const QListWidgetItem *item = m_joints->item(row);
        if (item->checkState() == Qt::Checked)
            checked.insert(
                {quint8(item->data(kAddressRole).toInt()), item->data(kBaudRole).toInt()});
    }
    const bool first = m_joints->count() == 0;
    m_joints->clear();
    const feetech::ServoList &servos = *m_client->servos();
    // Named by joint where the arm matches a template, as in the tree and the Monitor.
    const feetech::JointNames joints = feetech::JointNames::of(*m_client);
    for (int i = 0; i < servos.count(); ++i) {
        const feetech::ServoInfo &servo = servos.at(i).info;
        auto *item = new QListWidgetItem(tr("%1 · %2 · %3 bps")
                                             .arg(joints.label(servo.address()))
                                             .arg(servo.model.name)
                                             .arg(servo.baud),
                                         m_joints);
        item->setData(kAddressRole, servo.id);
        item->setData(kBaudRole, servo.baud);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        // Every servo at first: an arm is recorded whole unless told otherwise.
        item->setCheckState(first || checked.contains(servo.address()) ? Qt::Checked
                                                                       : Qt::Unchecked);
    }
    updateButtons();
}

void RecordReplayDialog::startRecording()
{
    QVector<int> indexes;
    for (int row = 0; row < m_joints->count(); ++row) {
        const QListWidgetItem *item = m_joints->item(row);
        if (item->checkState() != Qt::Checked)
            continue;
        indexes.append(m_client->servos()->indexOf(
            {quint8(item->data(kAddressRole).toInt()), item->data(kBaudRole).toInt()}));
    }
    if (indexes.isEmpty()) {
        showStatus(feetech::Refusal(feetech::Refusal::Code::NoServoToMonitor).describe(), true);
        return;
    }
    // Moved by hand means limp: a servo that holds its position (after teleoperation, a replay)
    // would only fight the hand. Torque off is never a move.
    m_recordIndexes = indexes;
    m_torqueOffNext = 0;
    showStatus(tr("Switching torque off on %n joint(s)…", nullptr, int(indexes.size())));
    updateButtons();
    switchNextTorqueOff();
}

void RecordReplayDialog::switchNextTorqueOff()
{
    if (m_torqueOffNext < 0)
        return;
    if (m_torqueOffNext >= m_recordIndexes.size()) {
        m_torqueOffNext = -1;
        feetech::Refusal refusal;
        if (!m_capture->start(m_recordIndexes, feetech::MotionCapture::kDefaultRateHz, &refusal)) {
            showStatus(refusal.describe(), true);
            updateButtons();
            return;
        }
        m_record->setText(tr("Stop &recording"));
        showStatus(tr("Recording: torque is off, move the joints by hand, then Stop."));
        updateButtons();
        return;
    }
    const int index = m_recordIndexes.at(m_torqueOffNext);
    const feetech::ServoInfo &servo = m_client->servos()->at(index).info;
    const auto fail = [this, address = servo.address()](const QString &why) {
        m_torqueOffNext = -1;
        // Named only when it failed: the names read the templates from disk.
        const QString name = feetech::JointNames::of(*m_client).label(address);
        showStatus(
            tr("Torque could not be switched off on %1: %2 Nothing is recorded.").arg(name, why),
            true);
        updateButtons();
    };
    const auto off = servo.table().torqueValue(feetech::TorqueMode::Off);
    feetech::Refusal refusal;
    feetech::OperationReply *reply = off
        ? m_client->writeValues(index, {{QStringLiteral("torque_enable"), *off}}, &refusal)
        : nullptr;
    if (!reply)
        return fail(off ? refusal.describe() : tr("its model has no torque enable."));
    connect(reply, &feetech::OperationReply::finished, this,
            [this, fail](const feetech::OperationResult &result) {
                if (!result.ok)
                    return fail(result.message);
                ++m_torqueOffNext;
                switchNextTorqueOff();
            });
}

void RecordReplayDialog::stopRecording()
{
    m_capture->stop(); // its stopped signal takes the recording
    m_record->setText(tr("Torque off and &record"));
}

void RecordReplayDialog::onFramesRecorded(int frames)
{
    const feetech::MotionRecording &recording = m_capture->recording();
    m_position->setText(
        tr("Recording: %n frame(s), %1 s", nullptr, frames).arg(recording.duration(), 0, 'f', 2));
}

void RecordReplayDialog::play()
{
    feetech::ReplayPlan settings;
    settings.speed = m_speed->value();
    settings.loops = m_loops->value();
    settings.release = m_release->isChecked();
    feetech::Refusal refusal;
    feetech::OperationReply *reply = m_player->play(m_recording, settings, &refusal);
    if (!reply) {
        showStatus(refusal.describe(), true);
        return;
    }
    connect(reply, &feetech::OperationReply::progress, this, &RecordReplayDialog::onReplayProgress);
    connect(reply, &feetech::OperationReply::finished, this, &RecordReplayDialog::onReplayFinished);
    m_progress->setRange(0, int(m_recording.frames.size()) * settings.loops);
    m_progress->setValue(0);
    showStatus(tr("Replaying: the arm eases to the first frame first."));
    updateButtons();
}

void RecordReplayDialog::stop()
{
    if (m_capture->isRecording()) {
        stopRecording();
        return;
    }
    if (m_player->isPlaying()) {
        m_player->stop();
        showStatus(tr("Stopping: the arm is held where it stands…"));
    }
}

void RecordReplayDialog::onReplayProgress(const feetech::OperationProgress &progress)
{
    m_progress->setRange(0, std::max(1, progress.total));
    m_progress->setValue(progress.done);
    const auto position = progress.detail.value<feetech::ReplayPosition>();
    if (position.frame >= 0) {
        const QSignalBlocker quiet(m_timeline);
        m_timeline->setValue(position.frame);
        showFrame(position.frame);
    }
    showStatus(progress.text);
}

void RecordReplayDialog::onReplayFinished(const feetech::OperationResult &result)
{
    showStatus(result.message, !result.ok && result.failure != feetech::OperationFailure::Stopped);
    if (result.ok)
        m_progress->setValue(m_progress->maximum());
    updateButtons();
    emit replayFinished(result);
}

void RecordReplayDialog::showFrame(int frame)
{
    if (m_recording.isEmpty() || frame < 0 || frame >= m_recording.frames.size()) {
        m_position->setText(tr("Nothing recorded yet."));
        return;
    }
    QStringList positions;
    for (int j = 0; j < m_recording.joints.size(); ++j)
        positions.append(tr("%1: %2")
                             .arg(m_recording.joints.at(j).describe())
                             .arg(m_recording.frames.at(frame).at(j)));
    m_position->setText(tr("%1 s of %2 s, frame %3 of %4 — %5")
                            .arg(m_recording.times.at(frame) - m_recording.times.first(), 0, 'f', 2)
                            .arg(m_recording.duration(), 0, 'f', 2)
                            .arg(frame + 1)
                            .arg(m_recording.frames.size())
                            .arg(positions.join(QStringLiteral(", "))));
}

void RecordReplayDialog::chooseFileToOpen()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open recording"), recentfiles::directory(recentfiles::Kind::MotionRecording),
        tr("Motion recordings (*.csv)"));
    if (!path.isEmpty() && openFile(path))
        recentfiles::add(recentfiles::Kind::MotionRecording, path);
}

void RecordReplayDialog::chooseFileToSave()
{
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save recording"),
                                     recentfiles::suggestedPath(recentfiles::Kind::MotionRecording,
                                                                QStringLiteral("motion.csv")),
                                     tr("Motion recordings (*.csv)"));
    if (!path.isEmpty() && saveFile(path))
        recentfiles::add(recentfiles::Kind::MotionRecording, path);
}

bool RecordReplayDialog::openFile(const QString &path)
{
    util::FileError error;
    const auto recording = feetech::loadMotionRecording(path, &error);
    if (!recording) {
        showStatus(error.describe(), true);
        return false;
    }
    m_recording = *recording;
    m_timeline->setRange(0, int(m_recording.frames.size()) - 1);
    m_timeline->setValue(0);
    showFrame(0);
    showStatus(tr("Opened %1: %n frame(s) over %2 s.", nullptr, int(m_recording.frames.size()))
                   .arg(QDir::toNativeSeparators(path))
                   .arg(m_recording.duration(), 0, 'f', 2));
    updateButtons();
    return true;
}

bool RecordReplayDialog::saveFile(const QString &path)
{
    util::FileError error;
    if (!feetech::saveMotionRecording(path, m_recording, &error)) {
        showStatus(error.describe(), true);
        return false;
    }
    showStatus(tr("Saved to %1.").arg(QDir::toNativeSeparators(path)));
    return true;
}

void RecordReplayDialog::updateButtons()
{
    const bool connected = m_client->link()->isConnected();
    const bool recording = m_capture->isRecording();
    const bool playing = m_player->isPlaying();
    const bool starting = m_torqueOffNext >= 0;
    m_joints->setEnabled(!recording && !playing && !starting);
    m_record->setEnabled(connected && !playing && !starting && (recording || !m_client->isBusy()));
    m_open->setEnabled(!recording && !playing && !starting);
    m_save->setEnabled(!recording && !playing && !m_recording.isEmpty());
    m_play->setEnabled(connected && !recording && !playing && !m_recording.isEmpty()
                       && !m_client->isBusy());
    m_stop->setEnabled(recording || playing);
}

void RecordReplayDialog::showStatus(const QString &text, bool problem)
{
    m_status->setText(text);
    QPalette tinted = palette();
    if (problem)
        tinted.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Error, tinted));
    m_status->setPalette(tinted);
}

void RecordReplayDialog::hideEvent(QHideEvent *event)
{
    // Closed while it works: the recording ends, and the arm is held where it stands.
    if (m_capture->isRecording())
        stopRecording();
    if (m_player->isPlaying())
        m_player->stop();
    QDialog::hideEvent(event);
}
