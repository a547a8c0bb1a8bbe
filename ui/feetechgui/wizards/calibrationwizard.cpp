// The calibration wizard's flow: torque off, recording from the telemetry stream, the results,
// the verified writes and the LeRobot file.
#include "calibrationwizard.h"

#include "busclient.h"
#include "calibrationsteps.h"
#include "palette.h"
#include "rangebar.h"
#include "recentfiles.h"
#include "telemetry.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSet>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace {

enum JointColumn { CalibrateColumn, IdColumn, ModelColumn, NameColumn, FullTurnColumn };
constexpr int kStatusColumn = 4;

} // namespace

CalibrationWizard::CalibrationWizard(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_steps(new CalibrationSteps(client, this))
    , m_templates(feetech::availableRobotTemplates())
{
    setWindowTitle(tr("Calibrate the arm"));
    setObjectName(QStringLiteral("calibrationWizard"));
    resize(820, 560);
    auto *layout = new QVBoxLayout(this);
    m_pages = new QStackedWidget(this);
    m_pages->addWidget(buildJointsPage());
    m_pages->addWidget(buildWarningPage());
    m_pages->addWidget(buildMiddlePosePage());
    m_pages->addWidget(buildRecordingPage());
    m_pages->addWidget(buildResultsPage());
    layout->addWidget(m_pages, 1);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("calibrationStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("calibrationCancelButton"));
    m_cancel->setAutoDefault(false);
    connect(m_cancel, &QPushButton::clicked, this, &CalibrationWizard::reject);
    auto *bottom = new QHBoxLayout;
    bottom->addStretch(1);
    bottom->addWidget(m_cancel);
    layout->addLayout(bottom);

    connect(m_steps, &CalibrationSteps::stepFinished, this, &CalibrationWizard::onStepFinished);
    connect(m_steps, &CalibrationSteps::progress, this, [this](int done, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(done);
    });
    connect(m_steps, &CalibrationSteps::finished, this, [this](bool allOk) {
        if (m_stage == Stage::Reading) {
            if (!allOk)
                return; // onStepFinished said why; the warning page stays
            for (int i = 0; i < m_recordings.size(); ++i) {
                const auto offset = m_client->parameters(m_indexes.at(i))
                                        ->deviceValue(QString::fromUtf16(feetech::kOffsetKey));
                m_recordings[i].currentOffset = qint32(offset.value_or(0));
            }
            QString error;
            if (!m_client->telemetry()->subscribe(this, m_indexes, feetech::kRecordingRateHz,
                                                  &error, feetech::kRecordingMissesBeforeLost)) {
                // Back to the choice: torque is off, so only the recording is to start again.
                m_stage = Stage::Choosing;
                m_torqueOff->setEnabled(true);
                fail(tr("Torque is off, but the recording could not start: %1").arg(error));
                return;
            }
            m_freshPositions = QVector<std::optional<double>>(m_recordings.size());
            m_stage = Stage::Recording;
            m_status->clear();
            buildBars();
            showPage(order() == feetech::CalibrationOrder::MiddlePoseFirst ? Page::MiddlePose
                                                                           : Page::Recording);
        } else if (m_stage == Stage::Writing) {
            m_stage = Stage::Done;
            m_cancel->setText(tr("Close"));
            m_cancel->setEnabled(true);
            m_save->setEnabled(!writtenMotors().isEmpty());
            m_again->setEnabled(false);
            m_status->setText(allOk ? tr("Every joint was written and verified. Save LeRobot's "
                                         "file if you use LeRobot with this arm.")
                                    : tr("Not every joint was written: see the status column."));
            emit writingFinished(allOk);
        }
    });
    connect(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived, this,
            &CalibrationWizard::onTelemetry);
    connect(m_client->telemetry(), &feetech::TelemetryHub::statsChanged, this,
            &CalibrationWizard::onTelemetryStats);
    showPage(Page::Joints);
}

// The client may be gone already (the main window's members go before its child dialogs):
// Cancel and Close are what stop the recording.
CalibrationWizard::~CalibrationWizard() = default;

CalibrationWizard::Page CalibrationWizard::page() const
{
    return Page(m_pages->currentIndex());
}

void CalibrationWizard::showPage(Page page)
{
    m_pages->setCurrentIndex(int(page));
    emit pageChanged(page);
}

feetech::CalibrationOrder CalibrationWizard::order() const
{
    return m_middleFirst->isChecked() ? feetech::CalibrationOrder::MiddlePoseFirst
                                      : feetech::CalibrationOrder::RangeFirst;
}

void CalibrationWizard::fail(const QString &message)
{
    m_status->setText(message);
}

void CalibrationWizard::goToWarning()
{
    m_indexes.clear();
    m_recordings.clear();
    QSet<QString> names;
    QStringList described;
    for (int row = 0; row < m_jointTable->rowCount(); ++row) {
        if (m_jointTable->item(row, CalibrateColumn)->checkState() != Qt::Checked)
            continue;
        const int index = m_jointTable->item(row, CalibrateColumn)->data(Qt::UserRole).toInt();
        const feetech::ServoInfo &info = m_client->servo(index).info;
        const QString name = m_jointTable->item(row, NameColumn)->text().trimmed();
        if (!feetech::isLeRobotMotorName(name))
            return fail(tr("\"%1\" is not a joint name: use letters, digits and _, a letter "
                           "first (LeRobot's motor names, such as shoulder_pan).")
                            .arg(name));
        if (names.contains(name))
            return fail(tr("Two joints are named \"%1\": give each its own name.").arg(name));
        names.insert(name);
        const auto limits =
            info.hasTable() ? feetech::calibrationLimits(info.table()) : std::nullopt;
        if (!limits)
            return fail(tr("Servo %1 (%2) has no position offset on a 4096-step encoder: it "
                           "cannot be calibrated. Leave it out.")
                            .arg(info.id)
                            .arg(info.model.name));
        feetech::JointRecording joint;
        joint.name = name;
        joint.id = info.id;
        joint.fullTurn = m_jointTable->item(row, FullTurnColumn)->checkState() == Qt::Checked;
        joint.limits = *limits;
        m_recordings.append(joint);
        m_indexes.append(index);
        described.append(tr("%1 (ID %2)").arg(name).arg(info.id));
    }
    if (m_recordings.isEmpty())
        return fail(tr("Choose at least one joint to calibrate."));
    m_status->clear();
    m_warning->setText(tr("Support the arm: torque goes off on these joints, and the arm will "
                          "fall under its own weight if nothing holds it.\n\n%1")
                           .arg(described.join(QStringLiteral(", "))));
    showPage(Page::Warning);
}

void CalibrationWizard::switchTorqueOffAndStart()
{
    if (m_stage != Stage::Choosing || page() != Page::Warning)
        return;
    // A fresh read first (the offset the servo has now converts what it reports while
    // recording), then torque off, which is never a move.
    QVector<CalibrationSteps::Step> steps;
    for (const int index : std::as_const(m_indexes))
        steps.append(CalibrationSteps::Step {index, {}});
    for (const int index : std::as_const(m_indexes))
        steps.append({index, {{QStringLiteral("torque_enable"), 0}}});
    m_stage = Stage::Reading;
    m_torqueOff->setEnabled(false);
    m_status->setText(tr("Reading the joints and switching torque off…"));
    m_steps->start(steps);
}

void CalibrationWizard::onStepFinished(int step, bool ok, const QString &message)
{
    if (m_stage == Stage::Reading) {
        if (ok)
            return;
        const int index = m_indexes.at(step % m_indexes.size());
        m_stage = Stage::Choosing;
        m_torqueOff->setEnabled(true);
        fail(tr("Servo %1: %2").arg(m_client->servo(index).info.id).arg(message));
        return;
    }
    if (m_stage != Stage::Writing || step >= m_writeRows.size())
        return;
    const int row = m_writeRows.at(step);
    m_written[row] = ok;
    auto *status = new QTableWidgetItem(ok ? tr("Written and verified") : message);
    if (!ok)
        status->setForeground(palette::toneColor(palette::Tone::Error, m_resultTable->palette()));
    m_resultTable->setItem(row, kStatusColumn, status);
}

void CalibrationWizard::onTelemetry(const QVector<feetech::FeedbackSample> &samples)
{
    if (m_stage != Stage::Recording)
        return;
    const bool recording = page() == Page::Recording;
    for (const feetech::FeedbackSample &sample : samples) {
        const auto position = sample.value(feetech::Quantity::Position);
        for (int i = 0; i < m_recordings.size(); ++i) {
            const feetech::ServoInfo &info = m_client->servo(m_indexes.at(i)).info;
            if (!position || info.id != sample.id || info.baud != sample.baud)
                continue;
            if (i < m_freshPositions.size())
                m_freshPositions[i] = *position;
            if (recording)
                m_recordings[i].range.addSample(int(std::lround(*position)));
        }
    }
    refreshBars();
}

void CalibrationWizard::onTelemetryStats(const feetech::TelemetryStats &stats)
{
    if (m_stage != Stage::Recording)
        return;
    const bool recording = page() == Page::Recording;
    for (const feetech::ServoTelemetry &servo : stats.servos) {
        for (int i = 0; i < m_recordings.size(); ++i) {
            const feetech::ServoInfo &info = m_client->servo(m_indexes.at(i)).info;
            if (!servo.missing || info.id != servo.id || info.baud != servo.baud)
                continue;
            if (i < m_freshPositions.size())
                m_freshPositions[i].reset(); // its last position is no longer where it is
            if (recording)
                m_recordings[i].range.markLost();
        }
    }
    refreshBars();
}

void CalibrationWizard::refreshBars()
{
    if (page() == Page::MiddlePose) {
        QStringList lines;
        for (int i = 0; i < m_recordings.size(); ++i) {
            const auto position = m_freshPositions.value(i);
            lines.append(tr("%1 (%2): %3")
                             .arg(feetech::jointDisplayName(m_recordings.at(i).name))
                             .arg(m_recordings.at(i).id)
                             .arg(position ? QString::number(*position) : tr("no reading yet")));
        }
        m_middleList->setText(lines.join(u'\n'));
        return;
    }
    for (int i = 0; i < m_recordings.size() && i < m_bars.size(); ++i) {
        const feetech::JointRangeRecorder &range = m_recordings.at(i).range;
        if (!range.hasSamples()) {
            m_bars.at(i)->setRange(std::nullopt, std::nullopt, std::nullopt, range.isLost());
            m_barValues.at(i)->setText(tr("no reading yet"));
            continue;
        }
        m_bars.at(i)->setRange(range.minimum(), range.present(), range.maximum(), range.isLost());
        m_barValues.at(i)->setText(range.isLost() ? tr("stopped answering")
                                                  : tr("min %1 · present %2 · max %3")
                                                        .arg(range.minimum())
                                                        .arg(range.present())
                                                        .arg(range.maximum()));
    }
}

void CalibrationWizard::takeMiddlePose()
{
    if (m_stage != Stage::Recording || page() != Page::MiddlePose)
        return;
    for (int i = 0; i < m_recordings.size(); ++i) {
        const auto position = m_freshPositions.value(i);
        if (!position)
            return fail(tr("No position has come from %1 (ID %2) yet: check that it answers.")
                            .arg(feetech::jointDisplayName(m_recordings.at(i).name))
                            .arg(m_recordings.at(i).id));
        m_recordings[i].middlePose = int(std::lround(*position));
    }
    m_status->clear();
    showPage(Page::Recording);
    refreshBars();
}

void CalibrationWizard::finishRecording()
{
    if (m_stage != Stage::Recording || page() != Page::Recording)
        return;
    stopRecording();
    m_stage = Stage::Choosing;
    m_results.clear();
    for (const feetech::JointRecording &joint : std::as_const(m_recordings))
        m_results.append(feetech::calibrateJoint(joint, order()));
    m_written = QVector<bool>(m_results.size(), false);
    showResults();
    const bool any = std::any_of(m_results.begin(), m_results.end(),
                                 [](const feetech::JointCalibration &r) { return r.ok(); });
    m_write->setEnabled(any);
    m_status->setText(any ? tr("Check the results, then write them to the servos.")
                          : tr("No joint can be calibrated from this recording: press Record "
                               "again and move every joint through its range."));
    showPage(Page::Results);
}

void CalibrationWizard::writeToServos()
{
    if (page() != Page::Results || m_stage != Stage::Choosing)
        return;
    QVector<CalibrationSteps::Step> steps;
    m_writeRows.clear();
    for (int row = 0; row < m_results.size(); ++row) {
        const feetech::JointCalibration &result = m_results.at(row);
        if (!result.ok())
            continue;
        steps.append(
            {m_indexes.at(row),
             feetech::calibrationWrites(result.offset, result.minimumLimit, result.maximumLimit)});
        m_writeRows.append(row);
    }
    if (steps.isEmpty())
        return;
    m_stage = Stage::Writing;
    m_write->setEnabled(false);
    m_again->setEnabled(false);
    m_cancel->setEnabled(false); // what is half written cannot be taken back
    m_progress->show();
    m_status->setText(tr("Writing to EEPROM and verifying…"));
    m_steps->start(steps);
}

void CalibrationWizard::recordAgain()
{
    if (page() != Page::Results || m_stage != Stage::Choosing)
        return;
    QString error;
    if (!m_client->telemetry()->subscribe(this, m_indexes, feetech::kRecordingRateHz, &error,
                                          feetech::kRecordingMissesBeforeLost))
        return fail(error);
    for (feetech::JointRecording &joint : m_recordings)
        joint.range = {};
    m_freshPositions = QVector<std::optional<double>>(m_recordings.size());
    m_results.clear();
    m_stage = Stage::Recording;
    m_status->clear();
    showPage(Page::Recording);
    refreshBars();
}

QVector<feetech::LeRobotMotor> CalibrationWizard::writtenMotors() const
{
    QVector<feetech::LeRobotMotor> motors;
    for (int row = 0; row < m_results.size(); ++row) {
        const feetech::JointCalibration &result = m_results.at(row);
        if (row < m_written.size() && m_written.at(row))
            motors.append({result.name, result.id, 0, result.offset, result.minimumLimit,
                           result.maximumLimit});
    }
    return motors;
}

bool CalibrationWizard::saveLeRobotFile(const QString &path, QString *error) const
{
    QVector<feetech::LeRobotMotor> motors = writtenMotors();
    if (motors.isEmpty()) {
        *error = tr("No joint was written: there is nothing to save.");
        return false;
    }
    feetech::keepDriveModes(motors, path);
    return feetech::saveLeRobotCalibration(motors, path, error);
}

void CalibrationWizard::chooseFileToSave()
{
    const int chosen = m_template->currentIndex();
    const feetech::RobotTemplate *robot =
        chosen >= 0 && chosen < m_templates.size() ? &m_templates.at(chosen) : nullptr;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save LeRobot calibration"),
        QDir(defaultCalibrationFolder(robot)).filePath(QStringLiteral("arm.json")),
        tr("LeRobot calibration (*.json)"));
    if (path.isEmpty())
        return;
    QString error;
    if (saveLeRobotFile(path, &error)) {
        recentfiles::add(recentfiles::Kind::Calibration, path);
        m_status->setText(tr("Saved %1.").arg(QDir::toNativeSeparators(path)));
    } else {
        fail(error);
    }
}

void CalibrationWizard::stopRecording()
{
    if (m_stage == Stage::Recording || m_stage == Stage::Reading)
        m_client->telemetry()->unsubscribe(this);
}

void CalibrationWizard::reject()
{
    if (m_stage == Stage::Writing)
        return; // the writes under way finish first; Cancel is disabled meanwhile
    stopRecording();
    m_stage = Stage::Choosing;
    QDialog::reject();
}
