// The arm calibration wizard: choose the joints and the order, switch torque off, record each
// joint's range by hand with live bars, then write the offsets and limits, verified, and save
// LeRobot's calibration file.
#pragma once

#include "armcalibration.h"
#include "calibrationjointspage.h"
#include "lerobotcalibration.h"
#include "robottemplate.h"

#include <QDialog>
#include <QVector>

#include <optional>

namespace feetech {
class BusClient;
struct FeedbackSample;
struct TelemetryStats;
} // namespace feetech

class CalibrationResultsPage;
class CalibrationSteps;
class QGridLayout;
class QLabel;
class QPushButton;
class QStackedWidget;
class RangeBar;

class CalibrationWizard : public QDialog
{
    Q_OBJECT

public:
    enum class Page { Joints, Warning, MiddlePose, Recording, Results };

    explicit CalibrationWizard(feetech::BusClient *client, QWidget *parent = nullptr);
    ~CalibrationWizard() override;

    Page page() const;
    // The joints being calibrated and what was recorded of them.
    const QVector<feetech::JointRecording> &recordings() const { return m_recordings; }
    const QVector<feetech::JointCalibration> &results() const { return m_results; }
    // What the last write left of the results: written and verified, per joint.
    QVector<feetech::LeRobotMotor> writtenMotors() const;
    // Saves the written joints; false and *error when it could not. Once calibrateReplacedMotor
    // chose a file, that file is updated instead: the written joint replaced, the others kept.
    bool saveLeRobotFile(const QString &path, util::FileError *error) const;
    // Calibrates the servo with ID `id` alone (a replaced motor) as the joint `name` of the
    // LeRobot file `file`, which Save updates; false when no scanned servo has that ID.
    bool calibrateReplacedMotor(int id, const QString &name, bool fullTurn, const QString &file);
    const QString &updatedFile() const { return m_updatedFile; }

    // The steps, for tests and keyboard users alike (each is what its page's button does).
    void goToWarning(); // from the joint choice
    void switchTorqueOffAndStart();
    void takeMiddlePose();
    void finishRecording();
    void writeToServos();
    void recordAgain(); // from the results, before anything is written

signals:
    void pageChanged(CalibrationWizard::Page page);
    void writingFinished(bool allOk);

protected:
    void reject() override;

private:
    QWidget *buildWarningPage();
    QWidget *buildMiddlePosePage();
    QWidget *buildRecordingPage();
    void buildBars();

    void showPage(Page page);
    void onStepFinished(int step, bool ok, const QString &message);
    void onTelemetry(const QVector<feetech::FeedbackSample> &samples);
    void onTelemetryStats(const feetech::TelemetryStats &stats);
    void refreshBars();
    void stopRecording();
    // Held from torque off until the wizard closes: see IdentifyService::hold.
    void holdJoints();
    void releaseJoints();
    void chooseFileToSave();
    void fail(const QString &message);

    enum class Stage { Choosing, Reading, TorqueOff, Recording, Writing, Done };

    feetech::BusClient *m_client = nullptr;
    CalibrationSteps *m_steps = nullptr;
    Stage m_stage = Stage::Choosing;
    QVector<int> m_indexes; // of the joints being calibrated, as the client lists them
    QVector<feetech::JointRecording> m_recordings;
    // Per joint: its last position received since this recording started, none while it has
    // sent none or since it went missing (the client's latest sample may be an old one).
    QVector<std::optional<double>> m_freshPositions;
    QVector<feetech::JointCalibration> m_results;
    QVector<bool> m_written; // per result: written and verified
    QVector<int> m_writeRows; // the result row of each write step
    QString m_updatedFile; // the arm's file a replaced motor is calibrated into
    QVector<feetech::ServoAddress> m_held; // the joints held for this calibration

    QStackedWidget *m_pages = nullptr;
    CalibrationJointsPage *m_jointsPage = nullptr;
    QLabel *m_warning = nullptr;
    QLabel *m_middleList = nullptr;
    QGridLayout *m_barGrid = nullptr;
    QVector<RangeBar *> m_bars;
    QVector<QLabel *> m_barValues;
    CalibrationResultsPage *m_resultsPage = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_torqueOff = nullptr;
    QPushButton *m_takeMiddle = nullptr;
    QPushButton *m_finish = nullptr;
    QPushButton *m_cancel = nullptr;
};
