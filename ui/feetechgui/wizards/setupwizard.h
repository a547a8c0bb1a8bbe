// The motor set-up wizard: a robot's joints set up one servo at a time (find, set up, verify).
#pragma once

#include "busclient.h"
#include "motorsetup.h"
#include "palette.h"
#include "robottemplate.h"

#include <QDialog>
#include <QVector>

#include <optional>

class QComboBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTreeWidget;

// Modeless: all bus work goes through the client, asynchronously. The joints set up while the
// wizard lives stay done; a check of the bus (on opening, or asked for) marks the joints whose
// servo already answers at its ID, as its model and with its settings, as done too.
class SetupWizard : public QDialog
{
    Q_OBJECT

public:
    enum class JointState { ToDo, Done, Failed };

    explicit SetupWizard(feetech::BusClient *client, QWidget *parent = nullptr);

    const feetech::RobotTemplate &robot() const { return m_robot; }
    int currentJoint() const { return m_current; } // -1 once every joint is done
    JointState jointState(int joint) const { return m_joints.at(joint).state; }
    QString jointReason(int joint) const { return m_joints.at(joint).reason; }
    bool isWorking() const { return m_work != Work::None; }

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
    enum class Work { None, Checking, Finding, SettingUp };
    struct Joint
    {
        JointState state = JointState::ToDo;
        QString reason; // why it failed, or what a check found at its ID
    };

    void buildUi();
    void loadRobots(); // the templates built in and saved, into the choice
    void chooseRobot(int index);
    void onProgress(int step, int steps, const QString &text);
    void onFinished(const feetech::MotorSetupResult &result);
    void onFound(const feetech::MotorSetupResult &result);
    void onSetUp(const feetech::MotorSetupResult &result);
    void onChecked(const QVector<feetech::JointCheck> &joints, bool ok, const QString &message);
    void startWork(Work work, const QString &text);
    void endWork();
    // The next joint not done after `from` (wrapping around); -1 when every joint is done.
    int nextToDo(int from) const;
    void showJoints();
    void showCurrent();
    void showOutcome(const QString &html, palette::Tone tone);
    void updateActions();
    feetech::MotorTarget currentTarget() const;
    // The joint whose servo answers where `servo` does, other than the current one; -1: none.
    int jointAnsweringAt(const feetech::ServoInfo &servo) const;

    feetech::BusClient *m_client = nullptr;
    QVector<feetech::RobotTemplate> m_robots;
    feetech::RobotTemplate m_robot;
    QVector<Joint> m_joints;
    int m_current = 0;
    Work m_work = Work::None;
    bool m_stopping = false;
    std::optional<feetech::ServoInfo> m_found; // what the last find found, to be set up

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
