// The calibration wizard's flow: torque off, recording from the telemetry stream with its pages,
// the results, the verified writes and the LeRobot file.
#include "calibrationwizard.h"

#include "busclient.h"
#include "calibrationfiles.h"
#include "calibrationresultspage.h"
#include "calibrationsteps.h"
#include "palette.h"
#include "rangebar.h"
#include "recentfiles.h"
#include "telemetry.h"
#include "widgethelpers.h"

#include <QDir>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

CalibrationWizard::CalibrationWizard(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_steps(new CalibrationSteps(client, this))
{
    setWindowTitle(tr("Calibrate the arm"));
    setObjectName(QStringLiteral("calibrationWizard"));
    resize(820, 560);
    auto *layout = new QVBoxLayout(this);
    m_pages = new QStackedWidget(this);
    m_jointsPage = new CalibrationJointsPage(client, this);
    connect(m_jointsPage->nextButton(), &QPushButton::clicked, this,
            &CalibrationWizard::goToWarning);
    m_pages->addWidget(m_jointsPage);
    m_pages->addWidget(buildWarningPage());
    m_pages->addWidget(buildMiddlePosePage());
    m_pages->addWidget(buildRecordingPage());
    m_resultsPage = new CalibrationResultsPage(this);
    connect(m_resultsPage->writeButton(), &QPushButton::clicked, this,
            &CalibrationWizard::writeToServos);
    connect(m_resultsPage->saveButton(), &QPushButton::clicked, this,
            &CalibrationWizard::chooseFileToSave);
    connect(m_resultsPage->recordAgainButton(), &QPushButton::clicked, this,
            &CalibrationWizard::recordAgain);
    m_pages->addWidget(m_resultsPage);
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
        m_resultsPage->progress()->setRange(0, total);
        m_resultsPage->progress()->setValue(done);
    });
    connect(m_steps, &CalibrationSteps::finished, this, [this](bool allOk) {
        if (m_stage == Stage::Reading) {
            if (!allOk)
                return; // onStepFinished said why; the warning page stays
            for (int i = 0; i < m_recordings.size(); ++i) {
                const auto offset = m_client->servos()
                                        ->parameters(m_indexes.at(i))
                                        ->deviceValue(QString::fromUtf16(feetech::kOffsetKey));
                m_recordings[i].currentOffset = qint32(offset.value_or(0));
            }
            feetech::Refusal refusal;
            if (!m_client->telemetry()->subscribe(this, m_indexes, feetech::kRecordingRateHz,
                                                  &refusal, feetech::kRecordingMissesBeforeLost)) {
                // Back to the choice: torque is off, so only the recording is to start again.
                m_stage = Stage::Choosing;
                m_torqueOff->setEnabled(true);
                fail(tr("Torque is off, but the recording could not start: %1")
                         .arg(refusal.describe()));
                return;
            }
            m_freshPositions = QVector<std::optional<double>>(m_recordings.size());
            m_stage = Stage::Recording;
            holdJoints();
            m_status->clear();
            buildBars();
            showPage(m_jointsPage->order() == feetech::CalibrationOrder::MiddlePoseFirst
                         ? Page::MiddlePose
                         : Page::Recording);
        } else if (m_stage == Stage::Writing) {
            m_stage = Stage::Done;
            m_cancel->setText(tr("Close"));
            m_cancel->setEnabled(true);
            const int verified = int(writtenMotors().size());
            m_resultsPage->saveButton()->setEnabled(verified > 0);
            m_resultsPage->recordAgainButton()->setEnabled(false);
            m_resultsPage->showWriteOutcome(verified, int(m_results.size()));
            // The page says what was written; the line below says what to do next.
            if (verified == 0)
                m_status->clear();
            else if (!m_updatedFile.isEmpty())
                m_status->setText(tr("Save the joint into %1: the file's other joints stay as "
                                     "they are.")
                                      .arg(QDir::toNativeSeparators(m_updatedFile)));
            else if (verified < m_results.size())
                m_status->setText(tr("Saving LeRobot's file keeps only the joints written and "
                                     "verified."));
            else
                m_status->setText(tr("Save LeRobot's file if you use LeRobot with this arm."));
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

QWidget *CalibrationWizard::buildWarningPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    m_warning = widgethelpers::wrappedLabel(QString(), page);
    m_warning->setObjectName(QStringLiteral("torqueWarning"));
    QFont bold = m_warning->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.2);
    m_warning->setFont(bold);
    QPalette colours = m_warning->palette();
    colours.setColor(QPalette::WindowText,
                     palette::toneColor(palette::Tone::Warning, m_warning->palette()));
    m_warning->setPalette(colours);
    layout->addWidget(m_warning);
    layout->addWidget(widgethelpers::wrappedLabel(
        tr("Nothing is written to the servos until you have seen the results and chosen to "
           "write them. Cancel at any point writes nothing (torque stays off)."),
        page));
    layout->addStretch(1);
    m_torqueOff = widgethelpers::actionButton(
        tr("I am supporting the arm: switch torque &off"), "torqueOffStartButton",
        tr("Switch torque off on the joints and start"), page);
    connect(m_torqueOff, &QPushButton::clicked, this, &CalibrationWizard::switchTorqueOffAndStart);
    auto *back = widgethelpers::actionButton(tr("&Back"), "calibrationBackButton",
                                             tr("Choose the joints again"), page);
    connect(back, &QPushButton::clicked, this, [this] {
        if (m_stage == Stage::Choosing)
            showPage(Page::Joints);
    });
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(back);
    buttons->addStretch(1);
    buttons->addWidget(m_torqueOff);
    layout->addLayout(buttons);
    return page;
}

QWidget *CalibrationWizard::buildMiddlePosePage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(widgethelpers::wrappedLabel(
        tr("Move every joint to the middle of its travel (LeRobot's middle pose: the arm "
           "stretched out level, the gripper half open), then take the pose. Each joint's "
           "present position there will read 2047."),
        page));
    m_middleList = widgethelpers::wrappedLabel(QString(), page);
    m_middleList->setObjectName(QStringLiteral("middlePoseList"));
    m_middleList->setTextFormat(Qt::PlainText);
    layout->addWidget(m_middleList, 1);
    m_takeMiddle =
        widgethelpers::actionButton(tr("&Take the middle pose"), "takeMiddlePoseButton",
                                    tr("Keep the present positions as the middle"), page);
    connect(m_takeMiddle, &QPushButton::clicked, this, &CalibrationWizard::takeMiddlePose);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_takeMiddle);
    layout->addLayout(buttons);
    return page;
}

QWidget *CalibrationWizard::buildRecordingPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(widgethelpers::wrappedLabel(
        tr("Move every joint slowly through its whole range, to both end stops, and back to "
           "the middle. Turn a full-turn joint as far as you want it to go. The bars show one "
           "turn of the encoder: the filled part is the range recorded so far, the line the "
           "present position, the dashed line the middle the range will be centred on."),
        page));
    auto *scroll = new QScrollArea(page);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *inner = new QWidget(scroll);
    m_barGrid = new QGridLayout(inner);
    m_barGrid->setColumnStretch(1, 1);
    m_barGrid->setRowStretch(100, 1);
    scroll->setWidget(inner);
    layout->addWidget(scroll, 1);
    m_finish = widgethelpers::actionButton(tr("&Finish recording"), "finishRecordingButton",
                                           tr("Stop recording and compute the calibration"), page);
    connect(m_finish, &QPushButton::clicked, this, &CalibrationWizard::finishRecording);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_finish);
    layout->addLayout(buttons);
    return page;
}

void CalibrationWizard::buildBars()
{
    QWidget *inner = m_barGrid->parentWidget();
    qDeleteAll(inner->findChildren<QWidget *>(QString(), Qt::FindDirectChildrenOnly));
    m_bars.clear();
    m_barValues.clear();
    for (int row = 0; row < m_recordings.size(); ++row) {
        const feetech::JointRecording &joint = m_recordings.at(row);
        auto *name = new QLabel(tr("%1 (%2)%3")
                                    .arg(feetech::jointDisplayName(joint.name))
                                    .arg(joint.id)
                                    .arg(joint.fullTurn ? tr(", full turn") : QString()),
                                inner);
        auto *bar = new RangeBar(inner);
        bar->setObjectName(QStringLiteral("rangeBar_%1").arg(joint.id));
        auto *values = new QLabel(inner);
        values->setObjectName(QStringLiteral("rangeValues_%1").arg(joint.id));
        values->setMinimumWidth(values->fontMetrics().horizontalAdvance(
            tr("min %1 · present %2 · max %3").arg(-99999).arg(-99999).arg(-99999)));
        m_barGrid->addWidget(name, row, 0);
        m_barGrid->addWidget(bar, row, 1);
        m_barGrid->addWidget(values, row, 2);
        m_bars.append(bar);
        m_barValues.append(values);
    }
    refreshBars();
}

CalibrationWizard::Page CalibrationWizard::page() const
{
    return Page(m_pages->currentIndex());
}

void CalibrationWizard::showPage(Page page)
{
    m_pages->setCurrentIndex(int(page));
    emit pageChanged(page);
}

void CalibrationWizard::fail(const QString &message)
{
    m_status->setText(message);
}

void CalibrationWizard::goToWarning()
{
    CalibrationJointsPage::Choice choice;
    QString error;
    const bool chosen = m_jointsPage->choose(&choice, &error);
    m_indexes = choice.indexes;
    m_recordings = choice.recordings;
    if (!chosen)
        return fail(error);
    m_status->clear();
    m_warning->setText(tr("Support the arm: torque goes off on these joints, and the arm will "
                          "fall under its own weight if nothing holds it.\n\n%1")
                           .arg(u"• " + choice.described.join(u"\n• ")));
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
        fail(tr("Servo %1: %2").arg(m_client->servos()->at(index).info.id).arg(message));
        return;
    }
    if (m_stage != Stage::Writing || step >= m_writeRows.size())
        return;
    const int row = m_writeRows.at(step);
    m_written[row] = ok;
    m_resultsPage->showWritten(row, ok, message);
}

void CalibrationWizard::onTelemetry(const QVector<feetech::FeedbackSample> &samples)
{
    if (m_stage != Stage::Recording)
        return;
    const bool recording = page() == Page::Recording;
    for (const feetech::FeedbackSample &sample : samples) {
        const auto position = sample.value(feetech::Quantity::Position);
        for (int i = 0; i < m_recordings.size(); ++i) {
            const feetech::ServoInfo &info = m_client->servos()->at(m_indexes.at(i)).info;
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
            const feetech::ServoInfo &info = m_client->servos()->at(m_indexes.at(i)).info;
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
        m_results.append(feetech::calibrateJoint(joint, m_jointsPage->order()));
    m_written = QVector<bool>(m_results.size(), false);
    m_resultsPage->showResults(m_results);
    const bool any = std::any_of(m_results.begin(), m_results.end(),
                                 [](const feetech::JointCalibration &r) { return r.ok(); });
    m_resultsPage->writeButton()->setEnabled(any);
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
    m_resultsPage->writeButton()->setEnabled(false);
    m_resultsPage->recordAgainButton()->setEnabled(false);
    m_cancel->setEnabled(false); // what is half written cannot be taken back
    m_resultsPage->progress()->show();
    m_resultsPage->showWriting();
    m_status->clear();
    m_steps->start(steps);
}

void CalibrationWizard::recordAgain()
{
    if (page() != Page::Results || m_stage != Stage::Choosing)
        return;
    feetech::Refusal refusal;
    if (!m_client->telemetry()->subscribe(this, m_indexes, feetech::kRecordingRateHz, &refusal,
                                          feetech::kRecordingMissesBeforeLost))
        return fail(refusal.describe());
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

bool CalibrationWizard::saveLeRobotFile(const QString &path, util::FileError *error) const
{
    QVector<feetech::LeRobotMotor> motors = writtenMotors();
    if (motors.isEmpty()) {
        util::report(error,
                     util::FileError(util::FileError::Code::NothingToSave,
                                     tr("No joint was written: there is nothing to save.")));
        return false;
    }
    if (!m_updatedFile.isEmpty())
        return feetech::updateLeRobotCalibrationFile(motors, path, error);
    feetech::keepDriveModes(motors, path);
    return feetech::saveLeRobotCalibration(motors, path, error);
}

bool CalibrationWizard::calibrateReplacedMotor(int id, const QString &name, bool fullTurn,
                                               const QString &file)
{
    if (m_stage != Stage::Choosing || !m_jointsPage->keepOnly(id, name, fullTurn))
        return false;
    m_updatedFile = file;
    setWindowTitle(tr("Calibrate the new %1 servo").arg(feetech::jointDisplayName(name)));
    m_resultsPage->saveButton()->setText(tr("&Save into %1").arg(QFileInfo(file).fileName()));
    m_resultsPage->saveButton()->setToolTip(
        tr("Update %1: this joint's offset and range replaced, the other joints kept")
            .arg(QDir::toNativeSeparators(file)));
    return true;
}

void CalibrationWizard::chooseFileToSave()
{
    const QString path = !m_updatedFile.isEmpty()
        ? m_updatedFile
        : chooseCalibrationFileToSave(this, tr("Save LeRobot calibration"),
                                      m_jointsPage->chosenTemplate());
    if (path.isEmpty())
        return;
    util::FileError error;
    if (saveLeRobotFile(path, &error)) {
        recentfiles::add(recentfiles::Kind::Calibration, path);
        m_status->setText(tr("Saved %1.").arg(QDir::toNativeSeparators(path)));
    } else {
        fail(error.describe());
    }
}

void CalibrationWizard::stopRecording()
{
    if (m_stage == Stage::Recording || m_stage == Stage::Reading)
        m_client->telemetry()->unsubscribe(this);
}

void CalibrationWizard::holdJoints()
{
    // The window stays usable meanwhile: Identify and the move test leave these joints alone
    // while a hand turns them and their calibration is written.
    releaseJoints();
    for (int i = 0; i < m_indexes.size(); ++i) {
        const feetech::ServoInfo &info = m_client->servos()->at(m_indexes.at(i)).info;
        m_held.append(info.address());
        m_client->identify()->hold(m_indexes.at(i),
                                   tr("Servo ID %1 is being calibrated: close the calibration "
                                      "wizard first.")
                                       .arg(info.id));
    }
}

void CalibrationWizard::releaseJoints()
{
    for (const feetech::ServoAddress &address : std::as_const(m_held))
        m_client->identify()->release(address);
    m_held.clear();
}

void CalibrationWizard::reject()
{
    if (m_stage == Stage::Writing)
        return; // the writes under way finish first; Cancel is disabled meanwhile
    stopRecording();
    releaseJoints();
    m_stage = Stage::Choosing;
    QDialog::reject();
}
