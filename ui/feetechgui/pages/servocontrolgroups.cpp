// The Control page's torque, goal position and operating-mode group boxes: their widgets.
#include "servocontrolgroups.h"

#include "registerspinbox.h"
#include "registerwidgets.h"
#include "tablefacts.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

using registerwidgets::registerSpinBox;
using registerwidgets::spinBox;
using registerwidgets::valueLabel;
using widgethelpers::actionButton;

namespace {
constexpr int kSliderMinimumWidth = 220;
} // namespace

void ServoControlGroups::setup(QWidget *page)
{
    setupTorqueGroup(page);
    setupGoalGroup(page);
    setupModeGroup(page);
}

void ServoControlGroups::setupTorqueGroup(QWidget *page)
{
    torqueGroup = new QGroupBox(tr("Torque"), page);
    torqueGroup->setObjectName(QStringLiteral("torqueGroup"));
    auto *layout = new QVBoxLayout(torqueGroup);
    auto *row = new QHBoxLayout;
    row->setSpacing(0);
    torqueOff =
        actionButton(tr("Off"), "torqueOffButton",
                     tr("Torque off: the horn turns freely (torque enable 0)."), torqueGroup);
    torqueOn = actionButton(tr("On"), "torqueOnButton",
                            tr("Torque on: the servo holds its goal position (torque enable 1)."),
                            torqueGroup);
    torqueDamping = actionButton(
        tr("Damping"), "torqueDampingButton",
        tr("Damping: the horn can be turned by hand against a resistance (torque enable 2)."),
        torqueGroup);
    torqueButtons = new QButtonGroup(page);
    torqueButtons->setExclusive(true);
    // Each button stands for a torque mode; the value it writes comes from the servo's table.
    for (const auto &[button, torqueMode] :
         {std::pair(torqueOff, feetech::TorqueMode::Off),
          std::pair(torqueOn, feetech::TorqueMode::On),
          std::pair(torqueDamping, feetech::TorqueMode::Damping)}) {
        button->setCheckable(true);
        button->setMinimumWidth(88);
        torqueButtons->addButton(button, int(torqueMode));
        row->addWidget(button);
    }
    row->addStretch(1);
    layout->addLayout(row);
    torqueState = new QLabel(torqueGroup);
    torqueState->setObjectName(QStringLiteral("torqueStateLabel"));
    torqueState->setWordWrap(true);
    torqueState->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(torqueState);
}

void ServoControlGroups::setupModeGroup(QWidget *page)
{
    modeGroup = new QGroupBox(tr("Operating mode"), page);
    modeGroup->setObjectName(QStringLiteral("modeGroup"));
    auto *layout = new QVBoxLayout(modeGroup);
    auto *row = new QHBoxLayout;
    mode = new QComboBox(modeGroup);
    mode->setObjectName(QStringLiteral("modeCombo"));
    mode->setMinimumWidth(200);
    mode->setToolTip(tr("How the servo uses its goal registers. Stored in EEPROM."));
    modeApply =
        actionButton(tr("Set mode…"), "modeApplyButton",
                     tr("Write the chosen operating mode to the servo's EEPROM."), modeGroup);
    row->addWidget(mode, 1);
    row->addWidget(modeApply);
    layout->addLayout(row);
    modeNote = new QLabel(modeGroup);
    modeNote->setObjectName(QStringLiteral("modeNote"));
    modeNote->setWordWrap(true);
    modeNote->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(modeNote);
}

void ServoControlGroups::setupGoalGroup(QWidget *page)
{
    goalGroup = new QGroupBox(tr("Goal position"), page);
    goalGroup->setObjectName(QStringLiteral("goalGroup"));
    auto *grid = new QGridLayout(goalGroup);
    grid->setHorizontalSpacing(10);
    grid->setVerticalSpacing(8);

    sliderMinimum = new QLabel(goalGroup);
    sliderMaximum = new QLabel(goalGroup);
    sliderMinimum->setForegroundRole(QPalette::PlaceholderText);
    sliderMaximum->setForegroundRole(QPalette::PlaceholderText);
    slider = new QSlider(Qt::Horizontal, goalGroup);
    slider->setObjectName(QStringLiteral("goalSlider"));
    slider->setTickPosition(QSlider::TicksBelow);
    slider->setMinimumWidth(kSliderMinimumWidth);
    slider->setToolTip(tr("Drag to move the servo: goals are sent as fast as the servo "
                          "confirms them, always the newest one."));
    auto *sliderRow = new QHBoxLayout;
    sliderRow->addWidget(sliderMinimum);
    sliderRow->addWidget(slider, 1);
    sliderRow->addWidget(sliderMaximum);
    grid->addLayout(sliderRow, 0, 0, 1, 3);

    goal = spinBox("goalSpinBox", goalGroup);
    goal->setSuffix(registerwidgets::stepSuffix());
    move = actionButton(tr("Move"), "moveButton",
                        tr("Send this goal position with the speed and acceleration below."),
                        goalGroup);
    present = valueLabel("presentPositionLabel", goalGroup);
    QFont bold = present->font();
    bold.setBold(true);
    present->setFont(bold);
    present->setToolTip(tr("Where the horn is: the monitor's newest sample, or the last read "
                           "of the present position."));
    grid->addWidget(new QLabel(tr("Goal"), goalGroup), 1, 0);
    grid->addWidget(goal, 1, 1);
    grid->addWidget(move, 1, 2);
    grid->addWidget(new QLabel(tr("Present"), goalGroup), 2, 0);
    grid->addWidget(present, 2, 1, 1, 2);

    speed = registerSpinBox("goalSpeedSpinBox", goalGroup);
    speed->setToolTip(tr("Goal speed (0: the servo's maximum). The arrows move by one step of "
                         "the register."));
    acceleration = registerSpinBox("accelerationSpinBox", goalGroup);
    acceleration->setToolTip(tr("Acceleration (0: the servo's maximum). The arrows move by one "
                                "step of the register."));
    grid->addWidget(new QLabel(tr("Speed"), goalGroup), 3, 0);
    grid->addWidget(speed, 3, 1);
    grid->addWidget(new QLabel(tr("Acceleration"), goalGroup), 4, 0);
    grid->addWidget(acceleration, 4, 1);
    grid->setColumnStretch(2, 1);
    valueNote = new QLabel(goalGroup);
    valueNote->setObjectName(QStringLiteral("controlValueNote"));
    valueNote->setWordWrap(true);
    valueNote->hide();
    grid->addWidget(valueNote, 6, 0, 1, 3);
    for (RegisterSpinBox *box : {speed, acceleration}) {
        QObject::connect(box, &RegisterSpinBox::snapped, valueNote,
                         [valueNote = valueNote](const QString &note) {
                             valueNote->setText(note);
                             valueNote->show();
                         });
    }

    rangeNote = new QLabel(goalGroup);
    rangeNote->setObjectName(QStringLiteral("goalRangeNote"));
    rangeNote->setWordWrap(true);
    rangeNote->setForegroundRole(QPalette::PlaceholderText);
    grid->addWidget(rangeNote, 5, 0, 1, 3);

    QObject::connect(goal, &QSpinBox::valueChanged, slider, [slider = slider](int value) {
        const QSignalBlocker blocker(slider); // typing does not move the servo; Move does
        slider->setValue(value);
    });
}
