// The arm calibration wizard: choose the joints and the order, switch torque off, record each
// joint's range by hand with live bars, then write the offsets and limits, verified, and save
// LeRobot's calibration file.
#pragma once

#include "armcalibration.h"
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

class CalibrationSteps;
class QButtonGroup;
class QComboBox;
class QGridLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QRadioButton;
class QStackedWidget;
class QTableWidget;
class RangeBar;

// The joints of the scanned servos as a robot template names them: a joint whose ID the template
// has takes its name and full-turn flag, any other servo is "id_N". `index` is the client's.
struct ArmJoint
{
    int index = 0;
    feetech::RobotJoint joint;
};
QVector<ArmJoint> armJoints(const feetech::BusClient &client, const feetech::RobotTemplate *robot);
// The template ServoBench offers first: the SO-101 follower when it is there.
int defaultRobotTemplate(const QVector<feetech::RobotTemplate> &templates);
// Where to offer saving or loading a LeRobot file for `robot`: its folder in LeRobot's
// calibration folder when that exists, else the folder of the calibration file used last, else
// the nearest folder of LeRobot's that exists.
QString defaultCalibrationFolder(const feetech::RobotTemplate *robot);

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
    // Saves the written joints; false and *error when it could not.
    bool saveLeRobotFile(const QString &path, QString *error) const;

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
    // Building the pages (calibrationwizardpages.cpp).
    QWidget *buildJointsPage();
    QWidget *buildWarningPage();
    QWidget *buildMiddlePosePage();
    QWidget *buildRecordingPage();
    QWidget *buildResultsPage();
    void fillJointTable();
    void buildBars();
    void showResults();

    // The flow (calibrationwizard.cpp).
    void showPage(Page page);
    feetech::CalibrationOrder order() const;
    void onStepFinished(int step, bool ok, const QString &message);
    void onTelemetry(const QVector<feetech::FeedbackSample> &samples);
    void onTelemetryStats(const feetech::TelemetryStats &stats);
    void refreshBars();
    void stopRecording();
    void chooseFileToSave();
    void fail(const QString &message);

    enum class Stage { Choosing, Reading, TorqueOff, Recording, Writing, Done };

    feetech::BusClient *m_client = nullptr;
    CalibrationSteps *m_steps = nullptr;
    QVector<feetech::RobotTemplate> m_templates;
    Stage m_stage = Stage::Choosing;
    QVector<int> m_indexes; // of the joints being calibrated, as the client lists them
    QVector<feetech::JointRecording> m_recordings;
    // Per joint: its last position received since this recording started, none while it has
    // sent none or since it went missing (the client's latest sample may be an old one).
    QVector<std::optional<double>> m_freshPositions;
    QVector<feetech::JointCalibration> m_results;
    QVector<bool> m_written; // per result: written and verified
    QVector<int> m_writeRows; // the result row of each write step

    QStackedWidget *m_pages = nullptr;
    QComboBox *m_template = nullptr;
    QTableWidget *m_jointTable = nullptr;
    QRadioButton *m_rangeFirst = nullptr;
    QRadioButton *m_middleFirst = nullptr;
    QLabel *m_warning = nullptr;
    QLabel *m_middleList = nullptr;
    QGridLayout *m_barGrid = nullptr;
    QVector<RangeBar *> m_bars;
    QVector<QLabel *> m_barValues;
    QTableWidget *m_resultTable = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_next = nullptr;
    QPushButton *m_torqueOff = nullptr;
    QPushButton *m_takeMiddle = nullptr;
    QPushButton *m_finish = nullptr;
    QPushButton *m_write = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_again = nullptr;
    QPushButton *m_cancel = nullptr;
};
