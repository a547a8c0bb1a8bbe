// Motor set-up wizard: its widgets, the robot and joint shown, what the flow's work reported,
// and which buttons may be used.
#include "setupwizard.h"

#include "registertable.h"
#include "widgethelpers.h"

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

enum SetupColumn { SetupNameColumn, SetupIdColumn, SetupModelColumn, SetupStatusColumn };

QString servoDescription(const feetech::ServoInfo &servo)
{
    return SetupWizard::tr("servo %1 at %2, model %3, firmware %4")
        .arg(servo.id)
        .arg(feetech::baudText(servo.baud), servo.model.name, servo.firmware());
}

} // namespace

SetupWizard::SetupWizard(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_flow(new feetech::MotorSetupFlow(client, this))
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
    connect(m_flow, &feetech::MotorSetupFlow::finished, this, &SetupWizard::onFinished);
    connect(m_flow, &feetech::MotorSetupFlow::checked, this, &SetupWizard::onChecked);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        showCurrent();
        updateActions();
    });
    connect(m_client, &feetech::BusClient::busyChanged, this, &SetupWizard::updateActions);
    chooseRobot(m_robotChoice->currentIndex());
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
    // A status says why a joint is not done ("ID 3 answers as an SCS15, not an STS3215"): it
    // wraps onto as many lines as it needs rather than end in "…".
    m_jointList->setWordWrap(true);
    m_jointList->setUniformRowHeights(false);
    // The rows' heights follow the status column's width (a tree sizes rows by their hints).
    connect(m_jointList->header(), &QHeaderView::sectionResized, this, &SetupWizard::fitStatusRows);
    m_jointList->header()->setStretchLastSection(true);
    m_jointList->setColumnWidth(SetupNameColumn, 130);
    m_jointList->setColumnWidth(SetupIdColumn, 40);
    m_jointList->setColumnWidth(SetupModelColumn, 80);
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
    m_robotChoice->setCurrentIndex(feetech::defaultRobotTemplate(m_robots));
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
    if (!m_flow->isWorking()) {
        const QString shown = feetech::robotDisplayName(m_flow->robot().name);
        loadRobots();
        const int index = m_robotChoice->findText(shown);
        if (index >= 0) {
            const QSignalBlocker quiet(m_robotChoice);
            m_robotChoice->setCurrentIndex(index);
        } else {
            chooseRobot(m_robotChoice->currentIndex()); // the default, as loadRobots chose it
        }
    }
    checkBus();
}

void SetupWizard::chooseRobot(int index)
{
    if (index < 0 || index >= m_robots.size() || m_flow->isWorking())
        return;
    m_flow->setRobot(m_robots.at(index));
    m_jointList->clear();
    for (const feetech::RobotJoint &joint : std::as_const(m_flow->robot().joints)) {
        auto *item = new QTreeWidgetItem(m_jointList);
        item->setText(SetupNameColumn, feetech::jointDisplayName(joint.name));
        item->setText(SetupIdColumn, QString::number(joint.id));
        item->setText(SetupModelColumn, joint.model);
    }
    showOutcome({}, palette::Tone::Accent);
    showJoints();
    showCurrent();
    updateActions();
}

void SetupWizard::chooseJoint(int joint)
{
    if (!m_flow->chooseJoint(joint))
        return;
    showOutcome({}, palette::Tone::Accent);
    showJoints();
    showCurrent();
    updateActions();
}

void SetupWizard::showJoints()
{
    using JointState = feetech::MotorSetupFlow::JointState;
    const int current = m_flow->currentJoint();
    for (int i = 0; i < m_flow->jointCount(); ++i) {
        QTreeWidgetItem *item = m_jointList->topLevelItem(i);
        const JointState state = m_flow->jointState(i);
        const QString reason = m_flow->jointReason(i);
        QString status;
        std::optional<palette::Tone> tone;
        switch (state) {
        case JointState::Done:
            status = tr("Done");
            tone = palette::Tone::Good;
            break;
        case JointState::Failed:
            status = tr("Failed: %1").arg(reason);
            tone = palette::Tone::Error;
            break;
        case JointState::ToDo:
            status = i == current ? tr("Current") : tr("To do");
            if (!reason.isEmpty())
                status += QStringLiteral(" (%1)").arg(reason);
            if (i == current)
                tone = palette::Tone::Accent;
            break;
        }
        if (i == current && state != JointState::ToDo)
            status = tr("Current, %1").arg(status.left(1).toLower() + status.mid(1));
        item->setText(SetupStatusColumn, status);
        item->setToolTip(SetupStatusColumn, status);
        item->setForeground(SetupStatusColumn,
                            tone ? QBrush(palette::toneColor(*tone, m_jointList->palette()))
                                 : m_jointList->palette().text());
        QFont font = item->font(SetupNameColumn);
        font.setBold(i == current);
        for (int column = SetupNameColumn; column <= SetupStatusColumn; ++column)
            item->setFont(column, font);
    }
    if (current >= 0)
        m_jointList->setCurrentItem(m_jointList->topLevelItem(current));
    fitStatusRows();
}

void SetupWizard::fitStatusRows()
{
    const int width = std::max(40, m_jointList->columnWidth(SetupStatusColumn) - 8);
    bool changed = false;
    for (int row = 0; row < m_jointList->topLevelItemCount(); ++row) {
        QTreeWidgetItem *item = m_jointList->topLevelItem(row);
        const QFontMetrics metrics(item->font(SetupStatusColumn));
        const int height = metrics
                               .boundingRect(QRect(0, 0, width, 10000), Qt::TextWordWrap,
                                             item->text(SetupStatusColumn))
                               .height()
            + 4;
        if (item->sizeHint(SetupStatusColumn).height() != height) {
            // A size hint with no width is none at all: the column's width goes with it.
            item->setSizeHint(SetupStatusColumn, QSize(width, height));
            changed = true;
        }
    }
    if (changed)
        m_jointList->doItemsLayout(); // the tree keeps its rows' heights until told
}

void SetupWizard::showCurrent()
{
    if (!m_client->link()->isConnected()) {
        m_currentBox->setTitle(tr("Not connected"));
        m_instruction->setText(tr("Open the Feetech port the servos are connected to first."));
        return;
    }
    const feetech::RobotTemplate &robot = m_flow->robot();
    const int current = m_flow->currentJoint();
    if (current < 0) {
        m_currentBox->setTitle(tr("All done"));
        m_instruction->setText(
            tr("Every joint of the %1 is set up. Connect the servos in a chain and press "
               "<i>Check the bus</i> to confirm them together.")
                .arg(feetech::robotDisplayName(robot.name).toHtmlEscaped()));
        return;
    }
    const feetech::RobotJoint &joint = robot.joints.at(current);
    m_currentBox->setTitle(tr("Joint %1 of %2: %3")
                               .arg(current + 1)
                               .arg(robot.joints.size())
                               .arg(feetech::jointDisplayName(joint.name)));
    m_instruction->setText(
        tr("Connect only the <b>%1</b> servo (ID will be %2) and press <i>Find</i>.<br>"
           "<small>Unplug every other servo from the bus first and keep the power on. A new servo "
           "answers at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate.</small>")
            .arg(feetech::jointDisplayName(joint.name).toHtmlEscaped())
            .arg(joint.id));
}

void SetupWizard::showOutcome(const QString &html, palette::Tone tone)
{
    palette::showInTone(m_outcome, html, tone);
}

void SetupWizard::updateActions()
{
    const bool idle = !m_flow->isWorking();
    const bool free = m_flow->isBusFree();
    const bool current = m_flow->currentJoint() >= 0;
    m_robotChoice->setEnabled(idle);
    m_check->setEnabled(free);
    m_find->setEnabled(free && current);
    m_setUp->setEnabled(free && current && m_flow->found().has_value());
    m_stop->setEnabled(m_flow->isWorking() && !m_flow->isStopping());
    m_jointList->setEnabled(idle);
}

void SetupWizard::startWork(const QString &text)
{
    m_progress->setRange(0, 0); // busy until the first step reports
    m_progress->show();
    m_step->setText(text);
    m_step->show();
    updateActions();
}

void SetupWizard::endWork()
{
    m_progress->hide();
    m_step->hide();
    updateActions();
}

void SetupWizard::checkBus()
{
    feetech::Refusal refusal;
    if (m_flow->checkBus(&refusal))
        startWork(
            tr("Asking every joint's ID at %1…").arg(feetech::baudText(m_flow->robot().baud)));
    else if (refusal)
        showOutcome(refusal.describe().toHtmlEscaped(), palette::Tone::Error);
}

void SetupWizard::find()
{
    feetech::Refusal refusal;
    if (m_flow->find(&refusal)) {
        showOutcome({}, palette::Tone::Accent);
        startWork(tr("Looking for the servo at every baud rate…"));
    } else if (refusal) {
        showOutcome(refusal.describe().toHtmlEscaped(), palette::Tone::Error);
        updateActions();
    }
}

void SetupWizard::setUp()
{
    feetech::Refusal refusal;
    if (m_flow->setUp(&refusal)) {
        showOutcome({}, palette::Tone::Accent);
        startWork(tr("Looking for the servo at every baud rate…"));
    } else if (refusal) {
        showOutcome(refusal.describe().toHtmlEscaped(), palette::Tone::Error);
    }
}

void SetupWizard::stop()
{
    if (!m_flow->stop())
        return;
    m_step->setText(tr("Stopping after this step…"));
    updateActions();
}

void SetupWizard::onProgress(int step, int steps, const QString &text)
{
    if (!m_flow->isWorking())
        return;
    m_progress->setRange(0, steps);
    m_progress->setValue(step - 1); // the step has begun, not ended
    if (!m_flow->isStopping())
        m_step->setText(tr("Step %1 of %2: %3").arg(step).arg(steps).arg(text));
}

void SetupWizard::onFinished(feetech::MotorSetupFlow::Work work,
                             const feetech::MotorSetupResult &result)
{
    using Work = feetech::MotorSetupFlow::Work;
    endWork();
    if (work == Work::Finding && !result.setUp)
        showFound(result);
    else if (work == Work::SettingUp && result.setUp)
        showSetUp(result);
}

void SetupWizard::showFound(const feetech::MotorSetupResult &result)
{
    const feetech::MotorSearch &search = result.search;
    const int current = m_flow->currentJoint();
    if (current < 0)
        return;
    const feetech::RobotTemplate &robot = m_flow->robot();
    const feetech::RobotJoint &joint = robot.joints.at(current);
    if (!result.ok) {
        // Every message of a search that found no single servo says what to do next.
        QString html = QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped());
        if (search.needsNothingWrittenNote())
            html += QStringLiteral("<br>") + tr("Nothing was written to any servo.");
        showOutcome(html, result.stopped ? palette::Tone::Warning : palette::Tone::Error);
        showJoints();
        updateActions();
        return;
    }
    QString html =
        tr("<b>Found one servo:</b> %1.").arg(servoDescription(search.servo).toHtmlEscaped());
    const int other = m_flow->jointAnsweringAt(search.servo);
    if (other >= 0 && m_flow->jointState(other) == feetech::MotorSetupFlow::JointState::Done) {
        html += QStringLiteral("<br><span style=\"color: %1\">%2</span>")
                    .arg(palette::toneColor(palette::Tone::Warning, palette()).name(),
                         tr("It answers where %1 should: it may be the %1 servo, already set "
                            "up. Set it up as %2 only if it is the %2 servo.")
                             .arg(feetech::jointDisplayName(robot.joints.at(other).name),
                                  feetech::jointDisplayName(joint.name))
                             .toHtmlEscaped());
    }
    html += QStringLiteral("<br>")
        + tr("Press <i>Set up</i> to give it ID %2, %3 and the %1 settings (%n value(s), "
             "each read back).",
             nullptr, int(joint.settings.size()))
              .arg(feetech::jointDisplayName(joint.name).toHtmlEscaped())
              .arg(joint.id)
              .arg(feetech::baudText(robot.baud));
    showOutcome(html, palette::Tone::Accent);
    showJoints();
    updateActions();
}

void SetupWizard::showSetUp(const feetech::MotorSetupResult &result)
{
    if (!result.ok) {
        if (m_flow->currentJoint() < 0)
            return;
        QString html = QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped());
        if (result.search.needsNothingWrittenNote())
            html += QStringLiteral("<br>") + tr("Nothing was written to any servo.");
        if (result.steps.size() > 1) // more than the find
            html += QStringLiteral("<br>") + tr("Done before that:")
                + widgethelpers::stepList(result.steps);
        showOutcome(html, result.stopped ? palette::Tone::Warning : palette::Tone::Error);
        showJoints();
        updateActions();
        return;
    }
    // The flow has moved on to the next joint to do, if any.
    const int next = m_flow->currentJoint();
    QString html = QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped())
        + widgethelpers::stepList(result.steps);
    html += next >= 0
        ? tr("Unplug it and connect the next servo: <b>%1</b>.")
              .arg(feetech::jointDisplayName(m_flow->robot().joints.at(next).name).toHtmlEscaped())
        : tr("Every joint is set up.");
    showOutcome(html, palette::Tone::Good);
    showJoints();
    showCurrent();
    updateActions();
}

void SetupWizard::onChecked(bool ok, const QString &message, int done)
{
    endWork();
    if (!ok) {
        showOutcome(message.toHtmlEscaped(), palette::Tone::Error);
        return;
    }
    showOutcome(
        tr("Checked the bus at %1: %2 of %n joint(s) set up.", nullptr, m_flow->jointCount())
            .arg(feetech::baudText(m_flow->robot().baud))
            .arg(done),
        palette::Tone::Accent);
    showJoints();
    showCurrent();
    updateActions();
}
