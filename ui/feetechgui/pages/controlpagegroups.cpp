// The Control page's torque, goal and operating-mode groups: their widgets and what each
// control does when used.
#include "controlpage.h"

#include "busclient.h"
#include "registerkeys.h"
#include "registerwidgets.h"
#include "servoparameters.h"
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

using namespace feetech::registerkeys;
using registerwidgets::spinBox;
using registerwidgets::valueLabel;
using widgethelpers::actionButton;

namespace {
constexpr int kSliderMinimumWidth = 220;
} // namespace

QGroupBox *ControlPage::buildTorqueGroup()
{
    m_torqueGroup = new QGroupBox(tr("Torque"), this);
    m_torqueGroup->setObjectName(QStringLiteral("torqueGroup"));
    auto *layout = new QVBoxLayout(m_torqueGroup);
    auto *row = new QHBoxLayout;
    row->setSpacing(0);
    m_torqueOff =
        actionButton(tr("Off"), "torqueOffButton",
                     tr("Torque off: the horn turns freely (torque enable 0)."), m_torqueGroup);
    m_torqueOn = actionButton(tr("On"), "torqueOnButton",
                              tr("Torque on: the servo holds its goal position (torque enable 1)."),
                              m_torqueGroup);
    m_torqueDamping = actionButton(
        tr("Damping"), "torqueDampingButton",
        tr("Damping: the horn can be turned by hand against a resistance (torque enable 2)."),
        m_torqueGroup);
    m_torqueButtons = new QButtonGroup(this);
    m_torqueButtons->setExclusive(true);
    // Each button stands for a torque mode; the value it writes comes from the servo's table.
    for (const auto &[button, mode] : {std::pair(m_torqueOff, feetech::TorqueMode::Off),
                                       std::pair(m_torqueOn, feetech::TorqueMode::On),
                                       std::pair(m_torqueDamping, feetech::TorqueMode::Damping)}) {
        button->setCheckable(true);
        button->setMinimumWidth(88);
        m_torqueButtons->addButton(button, int(mode));
        row->addWidget(button);
    }
    row->addStretch(1);
    connect(m_torqueButtons, &QButtonGroup::idClicked, this, &ControlPage::setTorque);
    layout->addLayout(row);
    m_torqueState = new QLabel(m_torqueGroup);
    m_torqueState->setObjectName(QStringLiteral("torqueStateLabel"));
    m_torqueState->setWordWrap(true);
    m_torqueState->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(m_torqueState);
    return m_torqueGroup;
}

QGroupBox *ControlPage::buildModeGroup()
{
    m_modeGroup = new QGroupBox(tr("Operating mode"), this);
    m_modeGroup->setObjectName(QStringLiteral("modeGroup"));
    auto *layout = new QVBoxLayout(m_modeGroup);
    auto *row = new QHBoxLayout;
    m_mode = new QComboBox(m_modeGroup);
    m_mode->setObjectName(QStringLiteral("modeCombo"));
    m_mode->setMinimumWidth(200);
    m_mode->setToolTip(tr("How the servo uses its goal registers. Stored in EEPROM."));
    m_modeApply =
        actionButton(tr("Set mode…"), "modeApplyButton",
                     tr("Write the chosen operating mode to the servo's EEPROM."), m_modeGroup);
    row->addWidget(m_mode, 1);
    row->addWidget(m_modeApply);
    layout->addLayout(row);
    m_modeNote = new QLabel(m_modeGroup);
    m_modeNote->setObjectName(QStringLiteral("modeNote"));
    m_modeNote->setWordWrap(true);
    m_modeNote->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(m_modeNote);

    connect(m_mode, &QComboBox::activated, this, [this] {
        const auto device = m_index >= 0 && m_client->parameters(m_index)
            ? m_client->parameters(m_index)->deviceValue(kMode)
            : std::nullopt;
        m_modeEdited = !device || m_mode->currentData().toLongLong() != *device;
        updateEnabled();
    });
    connect(m_modeApply, &QPushButton::clicked, this, &ControlPage::changeMode);
    return m_modeGroup;
}

QGroupBox *ControlPage::buildGoalGroup()
{
    m_goalGroup = new QGroupBox(tr("Goal position"), this);
    m_goalGroup->setObjectName(QStringLiteral("goalGroup"));
    auto *grid = new QGridLayout(m_goalGroup);
    grid->setHorizontalSpacing(10);
    grid->setVerticalSpacing(8);

    m_sliderMinimum = new QLabel(m_goalGroup);
    m_sliderMaximum = new QLabel(m_goalGroup);
    m_sliderMinimum->setForegroundRole(QPalette::PlaceholderText);
    m_sliderMaximum->setForegroundRole(QPalette::PlaceholderText);
    m_slider = new QSlider(Qt::Horizontal, m_goalGroup);
    m_slider->setObjectName(QStringLiteral("goalSlider"));
    m_slider->setTickPosition(QSlider::TicksBelow);
    m_slider->setMinimumWidth(kSliderMinimumWidth);
    m_slider->setToolTip(tr("Drag to move the servo: goals are sent as fast as the servo "
                            "confirms them, always the newest one."));
    auto *sliderRow = new QHBoxLayout;
    sliderRow->addWidget(m_sliderMinimum);
    sliderRow->addWidget(m_slider, 1);
    sliderRow->addWidget(m_sliderMaximum);
    grid->addLayout(sliderRow, 0, 0, 1, 3);

    m_goal = spinBox("goalSpinBox", m_goalGroup);
    m_goal->setSuffix(tr(" step"));
    m_move = actionButton(tr("Move"), "moveButton",
                          tr("Send this goal position with the speed and acceleration below."),
                          m_goalGroup);
    m_present = valueLabel("presentPositionLabel", m_goalGroup);
    QFont bold = m_present->font();
    bold.setBold(true);
    m_present->setFont(bold);
    m_present->setToolTip(tr("Where the horn is: the monitor's newest sample, or the last read "
                             "of the present position."));
    grid->addWidget(new QLabel(tr("Goal"), m_goalGroup), 1, 0);
    grid->addWidget(m_goal, 1, 1);
    grid->addWidget(m_move, 1, 2);
    grid->addWidget(new QLabel(tr("Present"), m_goalGroup), 2, 0);
    grid->addWidget(m_present, 2, 1, 1, 2);

    m_speed = spinBox("goalSpeedSpinBox", m_goalGroup);
    m_speed->setToolTip(tr("Goal speed, in register units (0: the servo's maximum)."));
    m_speedUnit = new QLabel(m_goalGroup);
    m_acceleration = spinBox("accelerationSpinBox", m_goalGroup);
    m_acceleration->setToolTip(tr("Acceleration, in register units (0: the servo's maximum)."));
    m_accelerationUnit = new QLabel(m_goalGroup);
    grid->addWidget(new QLabel(tr("Speed"), m_goalGroup), 3, 0);
    grid->addWidget(m_speed, 3, 1);
    grid->addWidget(m_speedUnit, 3, 2);
    grid->addWidget(new QLabel(tr("Acceleration"), m_goalGroup), 4, 0);
    grid->addWidget(m_acceleration, 4, 1);
    grid->addWidget(m_accelerationUnit, 4, 2);
    grid->setColumnStretch(2, 1);

    m_rangeNote = new QLabel(m_goalGroup);
    m_rangeNote->setObjectName(QStringLiteral("goalRangeNote"));
    m_rangeNote->setWordWrap(true);
    m_rangeNote->setForegroundRole(QPalette::PlaceholderText);
    grid->addWidget(m_rangeNote, 5, 0, 1, 3);

    connect(m_slider, &QSlider::valueChanged, this, &ControlPage::onSliderMoved);
    connect(m_goal, &QSpinBox::valueChanged, this, [this](int value) {
        const QSignalBlocker blocker(m_slider); // typing does not move the servo; Move does
        m_slider->setValue(value);
    });
    connect(m_move, &QPushButton::clicked, this, [this] { moveTo(m_goal->value()); });
    return m_goalGroup;
}
