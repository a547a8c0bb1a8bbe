// Motor set-up wizard: its widgets, the robot and joint shown, and which buttons may be used.
#include "setupwizard.h"

#include "registertable.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QShowEvent>
#include <QSignalBlocker>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace {

enum Column { NameColumn, IdColumn, ModelColumn, StatusColumn };

} // namespace

SetupWizard::SetupWizard(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
{
    setWindowTitle(tr("Set up motors"));
    setObjectName(QStringLiteral("setupWizard"));
    buildUi();
    loadRobots();
    connect(m_robotChoice, &QComboBox::currentIndexChanged, this, [this](int index) {
        chooseRobot(index);
        if (isVisible())
            checkBus();
    });
    connect(m_client->motorSetup(), &feetech::MotorSetupService::progress, this,
            &SetupWizard::onProgress);
    connect(m_client->motorSetup(), &feetech::MotorSetupService::finished, this,
            &SetupWizard::onFinished);
    connect(m_client->motorSetup(), &feetech::MotorSetupService::jointsChecked, this,
            &SetupWizard::onChecked);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        showCurrent();
        updateActions();
    });
    connect(m_client, &feetech::BusClient::busyChanged, this, &SetupWizard::updateActions);
    chooseRobot(0);
}

void SetupWizard::buildUi()
{
    auto *layout = new QVBoxLayout(this);

    auto *robotRow = new QHBoxLayout;
    robotRow->addWidget(new QLabel(tr("Robot:"), this));
    m_robotChoice = new QComboBox(this);
    m_robotChoice->setObjectName(QStringLiteral("robotChoice"));
    robotRow->addWidget(m_robotChoice, 1);
    m_check = new QPushButton(tr("Check the bus"), this);
    m_check->setObjectName(QStringLiteral("checkBusButton"));
    m_check->setToolTip(tr("Ask every joint's ID at the robot's rate: joints whose servo already "
                           "answers there, as its model and with its settings, are done"));
    connect(m_check, &QPushButton::clicked, this, &SetupWizard::checkBus);
    robotRow->addWidget(m_check);
    layout->addLayout(robotRow);

    m_templateProblems = new QLabel(this);
    m_templateProblems->setWordWrap(true);
    QPalette warning = m_templateProblems->palette();
    warning.setColor(QPalette::WindowText,
                     palette::toneColor(palette::Tone::Warning, m_templateProblems->palette()));
    m_templateProblems->setPalette(warning);
    layout->addWidget(m_templateProblems);

    m_jointList = new QTreeWidget(this);
    m_jointList->setObjectName(QStringLiteral("jointList"));
    m_jointList->setHeaderLabels({tr("Joint"), tr("ID"), tr("Model"), tr("Status")});
    m_jointList->setRootIsDecorated(false);
    m_jointList->setUniformRowHeights(true);
    m_jointList->header()->setStretchLastSection(true);
    m_jointList->setColumnWidth(NameColumn, 130);
    m_jointList->setColumnWidth(IdColumn, 40);
    m_jointList->setColumnWidth(ModelColumn, 80);
    connect(m_jointList, &QTreeWidget::itemClicked, this,
            [this](QTreeWidgetItem *item) { chooseJoint(m_jointList->indexOfTopLevelItem(item)); });
    // Room for a six-joint arm; the rest goes to what the current joint's work reports.
    m_jointList->setMinimumHeight(m_jointList->fontMetrics().lineSpacing() * 9);
    layout->addWidget(m_jointList, 1);

    m_currentBox = new QGroupBox(this);
    auto *current = new QVBoxLayout(m_currentBox);
    m_instruction = new QLabel(m_currentBox);
    m_instruction->setObjectName(QStringLiteral("setupInstruction"));
    m_instruction->setWordWrap(true);
    m_instruction->setTextFormat(Qt::RichText);
    current->addWidget(m_instruction);
    auto *buttons = new QHBoxLayout;
    m_find = new QPushButton(tr("&Find"), m_currentBox);
    m_find->setObjectName(QStringLiteral("findButton"));
    m_find->setToolTip(tr("Look for the one servo on the bus, at every ID and baud rate; nothing "
                          "is written"));
    connect(m_find, &QPushButton::clicked, this, &SetupWizard::find);
    m_setUp = new QPushButton(tr("&Set up"), m_currentBox);
    m_setUp->setObjectName(QStringLiteral("setUpButton"));
    m_setUp->setToolTip(tr("Give the servo found the joint's ID, the robot's baud rate and the "
                           "joint's settings, each read back"));
    connect(m_setUp, &QPushButton::clicked, this, &SetupWizard::setUp);
    m_stop = new QPushButton(tr("S&top"), m_currentBox);
    m_stop->setObjectName(QStringLiteral("stopButton"));
    m_stop->setToolTip(tr("Stop before the next step; a step under way ends first, so the "
                          "servo's EEPROM is always locked again"));
    connect(m_stop, &QPushButton::clicked, this, &SetupWizard::stop);
    buttons->addWidget(m_find);
    buttons->addWidget(m_setUp);
    buttons->addWidget(m_stop);
    buttons->addStretch(1);
    current->addLayout(buttons);
    m_progress = new QProgressBar(m_currentBox);
    m_progress->setObjectName(QStringLiteral("setupProgress"));
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(8);
    m_progress->hide();
    current->addWidget(m_progress);
    m_step = new QLabel(m_currentBox);
    m_step->setForegroundRole(QPalette::PlaceholderText);
    m_step->hide();
    current->addWidget(m_step);
    m_outcome = new QLabel(m_currentBox);
    m_outcome->setObjectName(QStringLiteral("setupOutcome"));
    m_outcome->setWordWrap(true);
    m_outcome->setTextFormat(Qt::RichText);
    m_outcome->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_outcome->setMinimumHeight(m_outcome->fontMetrics().lineSpacing() * 8);
    m_outcome->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    current->addWidget(m_outcome, 1);
    layout->addWidget(m_currentBox, 2);

    auto *close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(close);
    resize(640, 620);
}

void SetupWizard::loadRobots()
{
    QStringList problems;
    m_robots = feetech::availableRobotTemplates(&problems);
    const QSignalBlocker quiet(m_robotChoice);
    m_robotChoice->clear();
    for (const feetech::RobotTemplate &robot : std::as_const(m_robots))
        m_robotChoice->addItem(feetech::robotDisplayName(robot.name));
    m_templateProblems->setText(problems.join(u'\n'));
    m_templateProblems->setVisible(!problems.isEmpty());
}

void SetupWizard::showEvent(QShowEvent *event)
{
    QDialog::showEvent(event);
    if (event->spontaneous())
        return;
    // Reopened: templates may have been saved meanwhile (the choice and the joints' states stay
    // while the robot is still there), and the bus may have changed (servos set up elsewhere,
    // the arm built).
    if (!isWorking()) {
        const QString shown = feetech::robotDisplayName(m_robot.name);
        loadRobots();
        const int index = m_robotChoice->findText(shown);
        if (index >= 0) {
            const QSignalBlocker quiet(m_robotChoice);
            m_robotChoice->setCurrentIndex(index);
        } else {
            chooseRobot(0);
        }
    }
    checkBus();
}

void SetupWizard::chooseRobot(int index)
{
    if (index < 0 || index >= m_robots.size() || isWorking())
        return;
    m_robot = m_robots.at(index);
    m_joints = QVector<Joint>(m_robot.joints.size());
    m_current = m_robot.joints.isEmpty() ? -1 : 0;
    m_found.reset();
    m_jointList->clear();
    for (const feetech::RobotJoint &joint : std::as_const(m_robot.joints)) {
        auto *item = new QTreeWidgetItem(m_jointList);
        item->setText(NameColumn, feetech::jointDisplayName(joint.name));
        item->setText(IdColumn, QString::number(joint.id));
        item->setText(ModelColumn, joint.model);
    }
    showOutcome({}, palette::Tone::Accent);
    showJoints();
    showCurrent();
    updateActions();
}

void SetupWizard::chooseJoint(int joint)
{
    if (joint < 0 || joint >= m_joints.size() || isWorking() || joint == m_current)
        return;
    m_current = joint;
    m_found.reset();
    showOutcome({}, palette::Tone::Accent);
    showJoints();
    showCurrent();
    updateActions();
}

int SetupWizard::nextToDo(int from) const
{
    for (int step = 1; step <= m_joints.size(); ++step) {
        const int joint = (from + step) % int(m_joints.size());
        if (m_joints.at(joint).state != JointState::Done)
            return joint;
    }
    return -1;
}

void SetupWizard::showJoints()
{
    for (int i = 0; i < m_joints.size(); ++i) {
        QTreeWidgetItem *item = m_jointList->topLevelItem(i);
        const Joint &joint = m_joints.at(i);
        QString status;
        std::optional<palette::Tone> tone;
        switch (joint.state) {
        case JointState::Done:
            status = tr("Done");
            tone = palette::Tone::Good;
            break;
        case JointState::Failed:
            status = tr("Failed: %1").arg(joint.reason);
            tone = palette::Tone::Error;
            break;
        case JointState::ToDo:
            status = i == m_current ? tr("Current") : tr("To do");
            if (!joint.reason.isEmpty())
                status += QStringLiteral(" (%1)").arg(joint.reason);
            if (i == m_current)
                tone = palette::Tone::Accent;
            break;
        }
        if (i == m_current && joint.state != JointState::ToDo)
            status = tr("Current, %1").arg(status.left(1).toLower() + status.mid(1));
        item->setText(StatusColumn, status);
        item->setToolTip(StatusColumn, status);
        item->setForeground(StatusColumn,
                            tone ? QBrush(palette::toneColor(*tone, m_jointList->palette()))
                                 : m_jointList->palette().text());
        QFont font = item->font(NameColumn);
        font.setBold(i == m_current);
        for (int column = NameColumn; column <= StatusColumn; ++column)
            item->setFont(column, font);
    }
    if (m_current >= 0)
        m_jointList->setCurrentItem(m_jointList->topLevelItem(m_current));
}

void SetupWizard::showCurrent()
{
    if (!m_client->isConnected()) {
        m_currentBox->setTitle(tr("Not connected"));
        m_instruction->setText(tr("Open the Feetech port the servos are connected to first."));
        return;
    }
    if (m_current < 0) {
        m_currentBox->setTitle(tr("All done"));
        m_instruction->setText(
            tr("Every joint of the %1 is set up. Connect the servos in a chain and press "
               "<i>Check the bus</i> to confirm them together.")
                .arg(feetech::robotDisplayName(m_robot.name).toHtmlEscaped()));
        return;
    }
    const feetech::RobotJoint &joint = m_robot.joints.at(m_current);
    m_currentBox->setTitle(tr("Joint %1 of %2: %3")
                               .arg(m_current + 1)
                               .arg(m_robot.joints.size())
                               .arg(feetech::jointDisplayName(joint.name)));
    m_instruction->setText(
        tr("Connect only the <b>%1</b> servo (ID will be %2) and press <i>Find</i>.<br>"
           "<small>Unplug every other servo from the bus first and keep the power on. A new servo "
           "answers at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate.</small>")
            .arg(joint.name.toHtmlEscaped())
            .arg(joint.id));
}

void SetupWizard::showOutcome(const QString &html, palette::Tone tone)
{
    QPalette colours = m_outcome->palette();
    colours.setColor(QPalette::WindowText,
                     tone == palette::Tone::Accent ? palette().color(QPalette::WindowText)
                                                   : palette::toneColor(tone, palette()));
    m_outcome->setPalette(colours);
    m_outcome->setText(html);
}

void SetupWizard::updateActions()
{
    const bool connected = m_client->isConnected();
    const bool idle = !isWorking();
    const bool free = connected && idle && !m_client->isBusy();
    m_robotChoice->setEnabled(idle);
    m_check->setEnabled(free);
    m_find->setEnabled(free && m_current >= 0);
    m_setUp->setEnabled(free && m_current >= 0 && m_found.has_value());
    m_stop->setEnabled(isWorking() && !m_stopping);
    m_jointList->setEnabled(idle);
}

feetech::MotorTarget SetupWizard::currentTarget() const
{
    return feetech::motorTarget(m_robot, m_robot.joints.at(m_current));
}

int SetupWizard::jointAnsweringAt(const feetech::ServoInfo &servo) const
{
    for (int i = 0; i < m_robot.joints.size(); ++i) {
        if (i != m_current && m_robot.joints.at(i).id == servo.id && m_robot.baud == servo.baud)
            return i;
    }
    return -1;
}
