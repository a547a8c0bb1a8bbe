// The motor set-up wizard: a robot's joints set up one servo at a time (find, set up, verify).
#pragma once

#include "busclient.h"
#include "motorsetupflow.h"
#include "palette.h"
#include "robottemplate.h"

#include <QDialog>
#include <QVector>

class QComboBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTreeWidget;

// Modeless: the flow does the bus work, asynchronously; the wizard shows it and checks the bus
// on opening.
class SetupWizard : public QDialog
{
    Q_OBJECT

public:
    explicit SetupWizard(feetech::BusClient *client, QWidget *parent = nullptr);

    // The robot chosen, its joints' states and the work under way.
    feetech::MotorSetupFlow *flow() const { return m_flow; }

    QComboBox *robotChoice() const { return m_robotChoice; }
    QTreeWidget *jointList() const { return m_jointList; }
    QPushButton *findButton() const { return m_find; }
    QPushButton *setUpButton() const { return m_setUp; }
    QPushButton *stopButton() const { return m_stop; }
    QPushButton *checkButton() const { return m_check; }
    QLabel *instruction() const { return m_instruction; }
    QLabel *outcome() const { return m_outcome; }

    // What the buttons do.
    void checkBus();
    void find();
    void setUp();
    void stop();
    // Makes `joint` the one to set up next (a joint done may be set up again).
    void chooseJoint(int joint);

protected:
    void showEvent(QShowEvent *event) override;

private:
    // Each row as tall as its status, wrapped at the column's width, needs.
    void fitStatusRows();
    void buildUi();
    void loadRobots(); // the templates built in and saved, into the choice
    void chooseRobot(int index);
    void onProgress(int step, int steps, const QString &text);
    void onFinished(feetech::MotorSetupFlow::Work work, const feetech::MotorSetupResult &result);
    void showFound(const feetech::MotorSetupResult &result);
    void showSetUp(const feetech::MotorSetupResult &result);
    void onChecked(bool ok, const QString &message, int done);
    void startWork(const QString &text);
    void endWork();
    void showJoints();
    void showCurrent();
    void showOutcome(const QString &html, palette::Tone tone);
    void updateActions();

    feetech::BusClient *m_client = nullptr;
    QVector<feetech::RobotTemplate> m_robots;
    feetech::MotorSetupFlow *m_flow = nullptr;

    QComboBox *m_robotChoice = nullptr;
    QLabel *m_templateProblems = nullptr;
    QPushButton *m_check = nullptr;
    QTreeWidget *m_jointList = nullptr;
    QGroupBox *m_currentBox = nullptr;
    QLabel *m_instruction = nullptr;
    QPushButton *m_find = nullptr;
    QPushButton *m_setUp = nullptr;
    QPushButton *m_stop = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_step = nullptr;
    QLabel *m_outcome = nullptr;
};
