// The Control page's torque, goal position and operating-mode group boxes: their widgets, laid
// out and labelled; the page connects them and keeps them in step with the servo.
#pragma once

#include <QCoreApplication>

class QButtonGroup;
class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class RegisterSpinBox;
class QWidget;

// Like a form uic generates: setup() makes the widgets as children of the page.
class ServoControlGroups
{
    Q_DECLARE_TR_FUNCTIONS(ServoControlGroups)

public:
    void setup(QWidget *page);

    QGroupBox *torqueGroup = nullptr;
    // Each button's id in the group is the feetech::TorqueMode it stands for.
    QButtonGroup *torqueButtons = nullptr;
    QPushButton *torqueOff = nullptr;
    QPushButton *torqueOn = nullptr;
    QPushButton *torqueDamping = nullptr;
    QLabel *torqueState = nullptr;

    QGroupBox *modeGroup = nullptr;
    QComboBox *mode = nullptr;
    QPushButton *modeApply = nullptr;
    QLabel *modeNote = nullptr;

    QGroupBox *goalGroup = nullptr;
    QSlider *slider = nullptr;
    QLabel *sliderMinimum = nullptr;
    QLabel *sliderMaximum = nullptr;
    QSpinBox *goal = nullptr; // typing a goal moves the slider, not the servo
    QPushButton *move = nullptr;
    QLabel *present = nullptr;
    QLabel *rangeNote = nullptr;
    RegisterSpinBox *speed = nullptr; // in the register's unit, one step of it at a time
    RegisterSpinBox *acceleration = nullptr;
    QLabel *valueNote = nullptr; // a typed speed or acceleration that was put on a step

private:
    void setupTorqueGroup(QWidget *page);
    void setupModeGroup(QWidget *page);
    void setupGoalGroup(QWidget *page);
};
