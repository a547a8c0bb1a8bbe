// Motor replacement wizard: its pages, the checks of the choice and the file, the set-up through
// the flow, the scan of the arm put back together, and the calibration wizard it opens.
#include "replacemotorwizard.h"

#include "busclient.h"
#include "calibrationfiles.h"
#include "calibrationjointspage.h"
#include "calibrationwizard.h"
#include "recentfiles.h"
#include "widgethelpers.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace {

QLabel *richLabel(const QString &objectName, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setTextFormat(Qt::RichText);
    label->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    return label;
}

} // namespace

ReplaceMotorWizard::ReplaceMotorWizard(feetech::BusClient *client, QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_flow(new feetech::MotorSetupFlow(client, this))
{
    setWindowTitle(tr("Replace a motor"));
    setObjectName(QStringLiteral("replaceMotorWizard"));
    auto *layout = new QVBoxLayout(this);
    m_pages = new QStackedWidget(this);
    m_pages->addWidget(buildChoicePage());
    m_pages->addWidget(buildSetUpPage());
    m_pages->addWidget(buildReassemblePage());
    layout->addWidget(m_pages, 1);
    m_status = richLabel(QStringLiteral("replaceStatus"), this);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_status);
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(close, &QDialogButtonBox::rejected, this, &ReplaceMotorWizard::reject);
    layout->addWidget(close);
    resize(640, 440);

    loadRobots();
    connect(m_client->motorSetup(), &feetech::MotorSetupService::progress, this,
            &ReplaceMotorWizard::onProgress);
    connect(m_flow, &feetech::MotorSetupFlow::finished, this, &ReplaceMotorWizard::onSetUpFinished);
    connect(m_client, &feetech::BusClient::scanFinished, this, &ReplaceMotorWizard::onScanFinished);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        updateActions();
        if (!m_client->link()->isConnected() && page() != Page::Choice)
            showStatus(tr("The Feetech port is closed: open it again to go on."),
                       palette::Tone::Error);
    });
    connect(m_client, &feetech::BusClient::busyChanged, this, &ReplaceMotorWizard::updateActions);
    showPage(Page::Choice);
}

QWidget *ReplaceMotorWizard::buildChoicePage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    auto *intro = richLabel(QStringLiteral("replaceIntro"), page);
    intro->setText(
        tr("A new servo takes the place of one joint of an arm set up and calibrated before. "
           "ServoBench sets it up as that joint (its ID, the robot's baud rate and the joint's "
           "settings, each read back), then calibrates that joint alone and updates the arm's "
           "LeRobot calibration file with it: the file's other joints stay as they are."));
    layout->addWidget(intro);
    auto *form = new QFormLayout;
    m_robotChoice = new QComboBox(page);
    m_robotChoice->setObjectName(QStringLiteral("replaceRobotChoice"));
    connect(m_robotChoice, &QComboBox::currentIndexChanged, this, &ReplaceMotorWizard::chooseRobot);
    form->addRow(tr("Robot:"), m_robotChoice);
    m_jointChoice = new QComboBox(page);
    m_jointChoice->setObjectName(QStringLiteral("replaceJointChoice"));
    form->addRow(tr("Joint replaced:"), m_jointChoice);
    auto *fileRow = new QHBoxLayout;
    m_fileEdit = new QLineEdit(page);
    m_fileEdit->setObjectName(QStringLiteral("replaceFileEdit"));
    m_fileEdit->setPlaceholderText(tr("The arm's LeRobot calibration file"));
    m_fileEdit->setText(recentfiles::list(recentfiles::Kind::Calibration).value(0));
    fileRow->addWidget(m_fileEdit, 1);
    auto *browse =
        widgethelpers::actionButton(tr("&Browse…"), "replaceBrowseButton",
                                    tr("Choose the arm's LeRobot calibration file"), page);
    connect(browse, &QPushButton::clicked, this, &ReplaceMotorWizard::browse);
    fileRow->addWidget(browse);
    form->addRow(tr("Calibration file:"), fileRow);
    layout->addLayout(form);
    layout->addStretch(1);
    m_next = widgethelpers::actionButton(tr("&Next"), "replaceNextButton",
                                         tr("Check that the file has the joint, then set up "
                                            "the new servo"),
                                         page);
    connect(m_next, &QPushButton::clicked, this, &ReplaceMotorWizard::next);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_next);
    layout->addLayout(buttons);
    return page;
}

QWidget *ReplaceMotorWizard::buildSetUpPage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    m_setUpInstruction = richLabel(QStringLiteral("replaceSetUpInstruction"), page);
    layout->addWidget(m_setUpInstruction);
    auto *buttons = new QHBoxLayout;
    m_back = widgethelpers::actionButton(tr("&Back"), "replaceBackButton",
                                         tr("Choose another joint or file"), page);
    connect(m_back, &QPushButton::clicked, this, [this] {
        if (!m_flow->isWorking())
            showPage(Page::Choice);
    });
    m_find = widgethelpers::actionButton(
        tr("&Find"), "replaceFindButton",
        tr("Look for the one servo on the bus, at every ID and baud rate; nothing is written"),
        page);
    connect(m_find, &QPushButton::clicked, this, &ReplaceMotorWizard::find);
    m_setUp = widgethelpers::actionButton(tr("&Set up"), "replaceSetUpButton",
                                          tr("Give the servo found the joint's ID, the robot's "
                                             "baud rate and the joint's settings, each read back"),
                                          page);
    connect(m_setUp, &QPushButton::clicked, this, &ReplaceMotorWizard::setUp);
    buttons->addWidget(m_back);
    buttons->addStretch(1);
    buttons->addWidget(m_find);
    buttons->addWidget(m_setUp);
    layout->addLayout(buttons);
    m_progress = new QProgressBar(page);
    m_progress->setObjectName(QStringLiteral("replaceProgress"));
    m_progress->setTextVisible(false);
    m_progress->setMaximumHeight(8);
    m_progress->hide();
    layout->addWidget(m_progress);
    m_step = new QLabel(page);
    m_step->setForegroundRole(QPalette::PlaceholderText);
    m_step->hide();
    layout->addWidget(m_step);
    layout->addStretch(1);
    return page;
}

QWidget *ReplaceMotorWizard::buildReassemblePage()
{
    auto *page = new QWidget(this);
    auto *layout = new QVBoxLayout(page);
    m_setUpDone = richLabel(QStringLiteral("replaceSetUpDone"), page);
    layout->addWidget(m_setUpDone);
    layout->addStretch(1);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    m_scan = widgethelpers::actionButton(
        tr("S&can the arm"), "replaceScanButton",
        tr("Look for the arm's servos at the robot's baud rate; nothing is written"), page);
    connect(m_scan, &QPushButton::clicked, this, &ReplaceMotorWizard::scanArm);
    m_calibrate = widgethelpers::actionButton(
        tr("&Calibrate the joint…"), "replaceCalibrateButton",
        tr("Record the new servo's range by hand and update the calibration file"), page);
    connect(m_calibrate, &QPushButton::clicked, this, &ReplaceMotorWizard::calibrate);
    buttons->addWidget(m_scan);
    buttons->addWidget(m_calibrate);
    layout->addLayout(buttons);
    return page;
}

void ReplaceMotorWizard::loadRobots()
{
    QStringList problems;
    m_robots = feetech::availableRobotTemplates(&problems);
    {
        const QSignalBlocker quiet(m_robotChoice);
        m_robotChoice->clear();
        for (const feetech::RobotTemplate &robot : std::as_const(m_robots))
            m_robotChoice->addItem(feetech::robotDisplayName(robot.name));
        m_robotChoice->setCurrentIndex(std::max(0, feetech::defaultRobotTemplate(m_robots)));
    }
    chooseRobot(m_robotChoice->currentIndex());
    if (!problems.isEmpty())
        showStatus(problems.join(QStringLiteral("<br>")).toHtmlEscaped(), palette::Tone::Warning);
}

void ReplaceMotorWizard::chooseRobot(int index)
{
    m_jointChoice->clear();
    if (index < 0 || index >= m_robots.size())
        return;
    for (const feetech::RobotJoint &joint : std::as_const(m_robots.at(index).joints))
        m_jointChoice->addItem(
            tr("%1 (ID %2)").arg(feetech::jointDisplayName(joint.name)).arg(joint.id));
}

const feetech::RobotJoint *ReplaceMotorWizard::chosenJoint() const
{
    const int robot = m_robotChoice->currentIndex();
    const int joint = m_jointChoice->currentIndex();
    if (robot < 0 || robot >= m_robots.size() || joint < 0
        || joint >= m_robots.at(robot).joints.size())
        return nullptr;
    return &m_robots.at(robot).joints.at(joint);
}

void ReplaceMotorWizard::browse()
{
    const int robot = m_robotChoice->currentIndex();
    const QString folder = m_fileEdit->text().isEmpty()
        ? defaultCalibrationFolder(robot >= 0 && robot < m_robots.size() ? &m_robots.at(robot)
                                                                         : nullptr)
        : QFileInfo(m_fileEdit->text()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("The arm's LeRobot calibration"),
                                                      folder, tr("LeRobot calibration (*.json)"));
    if (!path.isEmpty())
        m_fileEdit->setText(QDir::toNativeSeparators(path));
}

ReplaceMotorWizard::Page ReplaceMotorWizard::page() const
{
    return Page(m_pages->currentIndex());
}

void ReplaceMotorWizard::showPage(Page page)
{
    m_pages->setCurrentIndex(int(page));
    updateActions();
    emit pageChanged(page);
}

void ReplaceMotorWizard::showStatus(const QString &html, palette::Tone tone)
{
    palette::showInTone(m_status, html, tone);
}

void ReplaceMotorWizard::updateActions()
{
    const bool connected = m_client->link()->isConnected();
    const bool working = m_flow->isWorking() || m_scanning;
    m_next->setEnabled(connected && !working);
    m_back->setEnabled(!working);
    m_find->setEnabled(m_flow->isBusFree() && !working);
    m_setUp->setEnabled(m_flow->isBusFree() && !working && m_flow->found().has_value());
    m_scan->setEnabled(connected && !working && !m_client->isBusy());
    m_calibrate->setEnabled(
        connected && !working
        && m_client->servos()->indexOf({quint8(m_fileMotor.id), m_flow->robot().baud}) >= 0);
}

void ReplaceMotorWizard::next()
{
    if (page() != Page::Choice || m_flow->isWorking())
        return;
    const feetech::RobotJoint *joint = chosenJoint();
    if (!m_client->link()->isConnected())
        return showStatus(tr("Open the Feetech port the new servo is connected to first."),
                          palette::Tone::Error);
    if (!joint)
        return showStatus(tr("Choose the robot and the joint whose motor is replaced."),
                          palette::Tone::Error);
    const QString path = QDir::fromNativeSeparators(m_fileEdit->text().trimmed());
    if (path.isEmpty())
        return showStatus(tr("Choose the arm's LeRobot calibration file: the new joint's "
                             "calibration goes into it."),
                          palette::Tone::Error);
    util::FileError error;
    const auto motors = feetech::loadLeRobotCalibration(path, &error);
    if (!motors)
        return showStatus(error.describe().toHtmlEscaped(), palette::Tone::Error);
    const feetech::LeRobotMotor *motor = feetech::leRobotMotorWithId(*motors, joint->id);
    if (!motor)
        return showStatus(
            tr("%1 has no joint with ID %2: choose the file of the arm whose %3 "
               "motor is replaced.")
                .arg(QDir::toNativeSeparators(path), QString::number(joint->id), joint->name)
                .toHtmlEscaped(),
            palette::Tone::Error);
    m_fileMotor = *motor;
    m_joint = *joint;
    m_file = path;
    const feetech::RobotTemplate &robot = m_robots.at(m_robotChoice->currentIndex());
    m_flow->setRobot(robot);
    m_flow->chooseJoint(m_jointChoice->currentIndex());
    m_setUpInstruction->setText(
        tr("<b>Unplug every servo of the arm from the bus</b> and connect only the new servo for "
           "<b>%1</b>, then press <i>Find</i>.<br><small>Keep the power on. A new servo answers "
           "at ID 1 and 1 Mbps; ServoBench finds it at any ID and rate and gives it ID %2 and "
           "%3.</small>")
            .arg(motor->name.toHtmlEscaped())
            .arg(joint->id)
            .arg(feetech::baudText(robot.baud)));
    showStatus({}, palette::Tone::Accent);
    showPage(Page::SetUp);
}

void ReplaceMotorWizard::find()
{
    feetech::Refusal refusal;
    if (page() != Page::SetUp || !m_flow->find(&refusal)) {
        if (refusal)
            showStatus(refusal.describe().toHtmlEscaped(), palette::Tone::Error);
        return;
    }
    showStatus({}, palette::Tone::Accent);
    m_progress->setRange(0, 0); // busy until the first step reports
    m_progress->show();
    m_step->setText(tr("Looking for the servo at every baud rate…"));
    m_step->show();
    updateActions();
}

void ReplaceMotorWizard::setUp()
{
    feetech::Refusal refusal;
    if (page() != Page::SetUp || !m_flow->setUp(&refusal)) {
        if (refusal)
            showStatus(refusal.describe().toHtmlEscaped(), palette::Tone::Error);
        return;
    }
    showStatus({}, palette::Tone::Accent);
    m_progress->setRange(0, 0);
    m_progress->show();
    m_step->setText(tr("Setting up the servo…"));
    m_step->show();
    updateActions();
}

void ReplaceMotorWizard::onProgress(int step, int steps, const QString &text)
{
    if (!m_flow->isWorking())
        return;
    m_progress->setRange(0, steps);
    m_progress->setValue(step - 1); // the step has begun, not ended
    m_step->setText(tr("Step %1 of %2: %3").arg(step).arg(steps).arg(text));
}

void ReplaceMotorWizard::onSetUpFinished(feetech::MotorSetupFlow::Work work,
                                         const feetech::MotorSetupResult &result)
{
    using Work = feetech::MotorSetupFlow::Work;
    m_progress->hide();
    m_step->hide();
    updateActions();
    if (!result.ok) {
        // Every message of a find or set-up that failed says what to do next.
        QString html = QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped());
        if (result.search.needsNothingWrittenNote())
            html += QStringLiteral("<br>") + tr("Nothing was written to any servo.");
        else if (result.steps.size() > 1)
            html += QStringLiteral("<br>") + tr("Done before that:")
                + widgethelpers::stepList(result.steps);
        showStatus(html, result.stopped ? palette::Tone::Warning : palette::Tone::Error);
        return;
    }
    if (work == Work::Finding) {
        const feetech::ServoInfo &servo = result.search.servo;
        showStatus(tr("<b>Found one servo:</b> servo %1 at %2, model %3. Press <i>Set up</i> to "
                      "make it the %4 joint.")
                       .arg(servo.id)
                       .arg(feetech::baudText(servo.baud), servo.model.name.toHtmlEscaped(),
                            feetech::jointDisplayName(m_fileMotor.name).toHtmlEscaped()),
                   palette::Tone::Accent);
        return;
    }
    if (work != Work::SettingUp)
        return;
    m_setUpDone->setText(
        QStringLiteral("<b>%1</b>").arg(result.message.toHtmlEscaped())
        + widgethelpers::stepList(result.steps)
        + tr("<b>Put the arm back together:</b> connect every servo in its chain as before, keep "
             "the power on, and press <i>Scan the arm</i>. The %1 joint is then calibrated alone "
             "into %2.")
              .arg(feetech::jointDisplayName(m_fileMotor.name).toHtmlEscaped(),
                   QDir::toNativeSeparators(m_file).toHtmlEscaped()));
    m_calibrate->setText(tr("&Calibrate %1…").arg(feetech::jointDisplayName(m_fileMotor.name)));
    showStatus({}, palette::Tone::Accent);
    showPage(Page::Reassemble);
}

void ReplaceMotorWizard::scanArm()
{
    if (page() != Page::Reassemble || m_scanning || !m_client->link()->isConnected()
        || m_client->isBusy())
        return;
    const feetech::RobotTemplate &robot = m_flow->robot();
    feetech::ScanOptions options;
    options.lastId = 0;
    for (const feetech::RobotJoint &joint : robot.joints)
        options.lastId = std::max(options.lastId, joint.id);
    options.bauds = {robot.baud};
    m_scanning = true;
    showStatus(tr("Looking for the arm's servos at %1…").arg(feetech::baudText(robot.baud)),
               palette::Tone::Accent);
    updateActions();
    m_client->scan(options);
}

void ReplaceMotorWizard::onScanFinished(bool completed, const QString &message)
{
    if (!m_scanning)
        return;
    m_scanning = false;
    updateActions();
    if (!completed)
        return showStatus(message.toHtmlEscaped(), palette::Tone::Error);
    const qint32 baud = m_flow->robot().baud;
    if (m_client->servos()->indexOf({quint8(m_fileMotor.id), baud}) < 0)
        return showStatus(tr("The new %1 servo does not answer at ID %2 and %3: check its cable "
                             "and the power, then scan again.")
                              .arg(feetech::jointDisplayName(m_fileMotor.name))
                              .arg(m_fileMotor.id)
                              .arg(feetech::baudText(baud))
                              .toHtmlEscaped(),
                          palette::Tone::Error);
    showStatus(
        tr("%n servo(s) answer, the new one among them.", nullptr, m_client->servos()->count()),
        palette::Tone::Good);
    calibrate();
}

void ReplaceMotorWizard::calibrate()
{
    if (page() != Page::Reassemble || m_scanning)
        return;
    if (!m_calibration) {
        m_calibration = new CalibrationWizard(m_client, this);
        m_calibration->setAttribute(Qt::WA_DeleteOnClose);
        if (!m_calibration->calibrateReplacedMotor(m_fileMotor.id, m_fileMotor.name,
                                                   m_joint.fullTurn, m_file)) {
            delete m_calibration;
            return showStatus(
                tr("The scan did not list servo %1: scan the arm again.").arg(m_fileMotor.id),
                palette::Tone::Error);
        }
    }
    // Not modal, as Calibrate arm's wizard is not: the Simulator dock turns the joint, the
    // Monitor shows it, while the joint is recorded.
    m_calibration->show();
    m_calibration->raise();
}

void ReplaceMotorWizard::reject()
{
    // A step under way ends first, so that the servo's EEPROM is always locked again.
    if (m_flow->isWorking()) {
        if (m_flow->stop())
            m_step->setText(tr("Stopping after this step…"));
        return;
    }
    if (m_scanning)
        m_client->cancelScan();
    QDialog::reject();
}
