// The motor replacement wizard: the new servo of one joint set up alone, the arm put back
// together and scanned, then that joint calibrated into the arm's LeRobot file.
#pragma once

#include "calibrationwizard.h"
#include "lerobotcalibration.h"
#include "motorsetupflow.h"
#include "palette.h"
#include "robottemplate.h"

#include <QDialog>
#include <QPointer>
#include <QVector>

namespace feetech {
class BusClient;
}

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QStackedWidget;

// Modeless, as the set-up wizard: the set-up is MotorSetupFlow's, the calibration the calibration
// wizard's, opened on the one joint with the arm's file to update.
class ReplaceMotorWizard : public QDialog
{
    Q_OBJECT

public:
    enum class Page { Choice, SetUp, Reassemble };

    explicit ReplaceMotorWizard(feetech::BusClient *client, QWidget *parent = nullptr);

    Page page() const;
    feetech::MotorSetupFlow *flow() const { return m_flow; }
    QComboBox *robotChoice() const { return m_robotChoice; }
    QComboBox *jointChoice() const { return m_jointChoice; }
    QLineEdit *fileEdit() const { return m_fileEdit; }
    QLabel *status() const { return m_status; }
    // The calibration wizard of the joint, once the arm was scanned (nullptr before).
    CalibrationWizard *calibrationWizard() const { return m_calibration; }

    // The steps, for tests and keyboard users alike (each is what its page's button does).
    void next(); // from the choice: the file must have the joint
    void find();
    void setUp();
    void scanArm();
    void calibrate();

signals:
    void pageChanged(ReplaceMotorWizard::Page page);

protected:
    void reject() override;

private:
    QWidget *buildChoicePage();
    QWidget *buildSetUpPage();
    QWidget *buildReassemblePage();
    void loadRobots();
    void chooseRobot(int index);
    void browse();
    void showPage(Page page);
    void showStatus(const QString &html, palette::Tone tone);
    void updateActions();
    void onProgress(int step, int steps, const QString &text);
    void onSetUpFinished(feetech::MotorSetupFlow::Work work,
                         const feetech::MotorSetupResult &result);
    void onScanFinished(bool completed, const QString &message);
    const feetech::RobotJoint *chosenJoint() const;

    feetech::BusClient *m_client = nullptr;
    feetech::MotorSetupFlow *m_flow = nullptr;
    QVector<feetech::RobotTemplate> m_robots;
    feetech::RobotJoint m_joint; // the template's joint whose motor is replaced
    feetech::LeRobotMotor m_fileMotor; // that joint as the arm's file names it
    QString m_file;
    bool m_scanning = false; // a scan of ours is running
    QPointer<CalibrationWizard> m_calibration;

    QStackedWidget *m_pages = nullptr;
    QComboBox *m_robotChoice = nullptr;
    QComboBox *m_jointChoice = nullptr;
    QLineEdit *m_fileEdit = nullptr;
    QPushButton *m_next = nullptr;
    QLabel *m_setUpInstruction = nullptr;
    QPushButton *m_back = nullptr;
    QPushButton *m_find = nullptr;
    QPushButton *m_setUp = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_step = nullptr;
    QLabel *m_setUpDone = nullptr;
    QPushButton *m_scan = nullptr;
    QPushButton *m_calibrate = nullptr;
    QLabel *m_status = nullptr;
};
