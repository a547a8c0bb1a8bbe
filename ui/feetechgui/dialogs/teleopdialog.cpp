// Robot > Teleoperate…: the dialog around feetech::Teleoperation.
#include "teleopdialog.h"

#include "busclient.h"
#include "lerobotcalibration.h"
#include "palette.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHideEvent>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSettings>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace {

// What the dialog remembers between runs.
const QString kLeaderPortKey = QStringLiteral("teleop/leaderPort");
const QString kFollowerFileKey = QStringLiteral("teleop/followerCalibration");
const QString kLeaderFileKey = QStringLiteral("teleop/leaderCalibration");
const QString kMaxSpeedKey = QStringLiteral("teleop/maxSpeed");
const QString kRateKey = QStringLiteral("teleop/rate");
const QString kNormModeKey = QStringLiteral("teleop/normMode");

// The rate and latency change every cycle: read four times a second.
constexpr int kFiguresIntervalMs = 250;
// Bars in tenths of LeRobot's units, so a tenth shows as a move.
constexpr int kBarScale = 10;

void showNormalised(QProgressBar *bar, double value)
{
    bar->setValue(int(std::lround(value * kBarScale)));
    bar->setFormat(QLocale().toString(value, 'f', 1));
}

} // namespace

TeleopDialog::TeleopDialog(feetech::BusClient *follower, QWidget *parent)
    : QDialog(parent)
    , m_client(follower)
    , m_teleop(new feetech::Teleoperation(follower, this))
{
    setObjectName(QStringLiteral("teleopDialog"));
    setWindowTitle(tr("Teleoperate"));
    setModal(false);
    QSettings settings;

    auto *arms = new QGroupBox(tr("Arms"), this);
    m_leaderPort = new QComboBox(arms);
    m_leaderPort->setObjectName(QStringLiteral("teleopLeaderPort"));
    m_leaderPort->setEditable(true);
    m_leaderPort->setMinimumContentsLength(24);
    m_leaderPort->setToolTip(tr("The leader arm's adapter: a second port, not the one the "
                                "window has open"));
    auto *refresh = new QPushButton(tr("Re&fresh"), arms);
    refresh->setToolTip(tr("List the serial ports again"));
    connect(refresh, &QPushButton::clicked, this, &TeleopDialog::refreshPorts);
    m_inputs.append(refresh);
    auto *portRow = new QHBoxLayout;
    portRow->addWidget(m_leaderPort, 1);
    portRow->addWidget(refresh);
    auto *followerPort = new QLabel(arms);
    followerPort->setObjectName(QStringLiteral("teleopFollowerPort"));
    const auto showFollowerPort = [this, followerPort] {
        followerPort->setText(
            m_client->link()->isConnected()
                ? tr("The arm on %1 (the window's bus)")
                      .arg(QDir::toNativeSeparators(m_client->link()->status().portName))
                : tr("None: connect to the follower arm's bus first"));
    };
    connect(m_client, &feetech::BusClient::statusChanged, followerPort, showFollowerPort);
    showFollowerPort();

    const auto fileRow = [this, arms, &settings](QLineEdit *&edit, const QString &name,
                                                 const QString &key, const QString &title) {
        edit = new QLineEdit(settings.value(key).toString(), arms);
        edit->setObjectName(name);
        edit->setPlaceholderText(tr("A LeRobot calibration file (.json)"));
        auto *browse = new QPushButton(tr("Browse…"), arms);
        m_inputs.append(browse);
        QLineEdit *target = edit;
        connect(browse, &QPushButton::clicked, this,
                [this, target, title] { chooseFile(target, title); });
        auto *row = new QHBoxLayout;
        row->addWidget(edit, 1);
        row->addWidget(browse);
        return row;
    };
    QHBoxLayout *followerFileRow = fileRow(m_followerFile, QStringLiteral("teleopFollowerFile"),
                                           kFollowerFileKey, tr("The follower's calibration file"));
    QHBoxLayout *leaderFileRow = fileRow(m_leaderFile, QStringLiteral("teleopLeaderFile"),
                                         kLeaderFileKey, tr("The leader's calibration file"));

    m_maxSpeed = new QSpinBox(arms);
    m_maxSpeed->setObjectName(QStringLiteral("teleopMaxSpeed"));
    m_maxSpeed->setRange(1, 720);
    m_maxSpeed->setSuffix(tr(" °/s"));
    m_maxSpeed->setValue(
        settings.value(kMaxSpeedKey, int(feetech::TeleopLoop::kDefaultMaxSpeed)).toInt());
    m_maxSpeed->setToolTip(tr("No joint of the follower moves faster, so it eases to the "
                              "leader's pose at the start"));
    m_rate = new QSpinBox(arms);
    m_rate->setObjectName(QStringLiteral("teleopRate"));
    m_rate->setRange(1, 200);
    m_rate->setSuffix(tr(" Hz"));
    m_rate->setValue(settings.value(kRateKey, int(feetech::TeleopLoop::kDefaultRateHz)).toInt());
    m_normMode = new QComboBox(arms);
    m_normMode->setObjectName(QStringLiteral("teleopNormMode"));
    using NormMode = feetech::TeleopMapping::NormMode;
    m_normMode->addItem(tr("Degrees from the middle (LeRobot's use_degrees, its default)"),
                        feetech::TeleopMapping::normModeKey(NormMode::Degrees));
    m_normMode->addItem(tr("Range onto range, −100 to 100 (LeRobot's range_m100_100)"),
                        feetech::TeleopMapping::normModeKey(NormMode::RangeM100_100));
    m_normMode->setCurrentIndex(
        std::max(0, m_normMode->findData(settings.value(kNormModeKey).toString())));
    m_normMode->setToolTip(tr("How a leader's joint position becomes the follower's goal, as "
                              "LeRobot's teleoperation does it: the same angle from the middle "
                              "of each arm's range, or the same share of each range. The gripper "
                              "is always share of range."));
    m_inputs += {m_leaderPort, m_followerFile, m_leaderFile, m_maxSpeed, m_rate, m_normMode};
    m_rate->setToolTip(tr("How often the leader is read; each reading is one write to the "
                          "follower, as fast as the follower's bus takes them"));

    auto *form = new QFormLayout(arms);
    form->addRow(tr("Follower:"), followerPort);
    form->addRow(tr("Follower's calibration:"), followerFileRow);
    form->addRow(tr("Leader port:"), portRow);
    form->addRow(tr("Leader's calibration:"), leaderFileRow);
    form->addRow(tr("Maximum speed:"), m_maxSpeed);
    form->addRow(tr("Rate:"), m_rate);
    form->addRow(tr("Joints map:"), m_normMode);

    m_start = new QPushButton(tr("&Start"), this);
    m_start->setObjectName(QStringLiteral("teleopStart"));
    m_start->setToolTip(tr("Check both arms against their files, hold the follower where it "
                           "stands, then follow the leader"));
    m_stopButton = new QPushButton(tr("S&top"), this);
    m_stopButton->setObjectName(QStringLiteral("teleopStop"));
    m_stopButton->setToolTip(tr("Stop following: the follower holds where it is"));
    m_stopButton->setEnabled(false);
    connect(m_start, &QPushButton::clicked, this, &TeleopDialog::start);
    connect(m_stopButton, &QPushButton::clicked, m_teleop, &feetech::Teleoperation::stop);
    auto *buttonRow = new QHBoxLayout;
    buttonRow->addStretch();
    buttonRow->addWidget(m_start);
    buttonRow->addWidget(m_stopButton);

    auto *joints = new QGroupBox(tr("Joints (LeRobot's units: −100…100, the gripper 0…100)"), this);
    m_jointGrid = new QGridLayout(joints);
    m_jointGrid->addWidget(new QLabel(tr("Joint"), joints), 0, 0);
    m_jointGrid->addWidget(new QLabel(tr("Leader"), joints), 0, 1);
    m_jointGrid->addWidget(new QLabel(tr("Follower's goal"), joints), 0, 2);
    m_jointGrid->setColumnStretch(1, 1);
    m_jointGrid->setColumnStretch(2, 1);
    auto *none = new QLabel(tr("The joints both files name show here once started."), joints);
    none->setObjectName(QStringLiteral("teleopNoJoints"));
    m_jointGrid->addWidget(none, 1, 0, 1, 3);

    m_loopFigures = new QLabel(tr("Loop: not running."), this);
    m_loopFigures->setObjectName(QStringLiteral("teleopLoopFigures"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("teleopStatus"));
    m_status->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(arms);
    layout->addLayout(buttonRow);
    layout->addWidget(joints, 1);
    layout->addWidget(m_loopFigures);
    layout->addWidget(m_status);
    layout->addWidget(buttons);

    m_figuresTimer = new QTimer(this);
    m_figuresTimer->setInterval(kFiguresIntervalMs);
    connect(m_figuresTimer, &QTimer::timeout, this, &TeleopDialog::showLoopFigures);
    connect(m_teleop, &feetech::Teleoperation::stateChanged, this, &TeleopDialog::onStateChanged);
    connect(m_teleop, &feetech::Teleoperation::progress, this,
            [this](const QString &text) { showStatus(text); });
    connect(m_teleop, &feetech::Teleoperation::cycled, this, &TeleopDialog::showPositions);
    connect(m_teleop, &feetech::Teleoperation::ended, this, &TeleopDialog::onEnded);
    refreshPorts();
    const QString remembered = settings.value(kLeaderPortKey).toString();
    if (!remembered.isEmpty() && m_leaderPort->findData(remembered) < 0)
        m_leaderPort->setEditText(remembered);
    else if (!remembered.isEmpty())
        m_leaderPort->setCurrentIndex(m_leaderPort->findData(remembered));
    resize(sizeHint().expandedTo(QSize(560, 0)));
}

void TeleopDialog::setSimulatedLeader(std::function<QString(QString *error)> start,
                                      std::function<QString(QString *error)> calibration)
{
    m_simulatedLeaderCalibration = std::move(calibration);
    const bool offered = !m_simulatedLeader && start;
    m_simulatedLeader = std::move(start);
    refreshPorts();
    // On the demo's simulated arm, its simulated leader is the one to follow.
    if (offered)
        m_leaderPort->setCurrentIndex(
            m_leaderPort->findData(QString::fromLatin1(kSimulatedLeader)));
}

QString TeleopDialog::chosenPort() const
{
    const int listed = m_leaderPort->findText(m_leaderPort->currentText());
    return listed >= 0 ? m_leaderPort->itemData(listed).toString()
                       : m_leaderPort->currentText().trimmed();
}

QProgressBar *TeleopDialog::leaderBar(int joint) const
{
    return joint >= 0 && joint < m_rows.size() ? m_rows.at(joint).leader : nullptr;
}

QProgressBar *TeleopDialog::followerBar(int joint) const
{
    return joint >= 0 && joint < m_rows.size() ? m_rows.at(joint).follower : nullptr;
}

void TeleopDialog::refreshPorts()
{
    const QString typed = chosenPort();
    m_leaderPort->clear();
    if (m_simulatedLeader)
        m_leaderPort->addItem(tr("Simulated SO-101 leader arm"),
                              QString::fromLatin1(kSimulatedLeader));
    const QString followerPort = m_client->link()->status().portName;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        if (info.systemLocation() == followerPort)
            continue; // the follower's: never the leader's
        const QString text = info.description().isEmpty()
            ? info.systemLocation()
            : tr("%1 (%2)").arg(info.systemLocation(), info.description());
        m_leaderPort->addItem(text, info.systemLocation());
    }
    const int known = m_leaderPort->findData(typed);
    if (known >= 0)
        m_leaderPort->setCurrentIndex(known);
    else
        m_leaderPort->setEditText(typed);
}

void TeleopDialog::chooseFile(QLineEdit *edit, const QString &title)
{
    const QString start = edit->text().isEmpty() ? feetech::leRobotCalibrationFolder()
                                                 : QFileInfo(edit->text()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(
        this, title, start, tr("LeRobot calibration files (*.json);;All files (*)"));
    if (!path.isEmpty())
        edit->setText(path);
}

void TeleopDialog::start()
{
    feetech::TeleopSettings run;
    const QString chosen = chosenPort();
    run.leaderPort = chosen;
    if (run.leaderPort == QLatin1String(kSimulatedLeader)) {
        QString error;
        run.leaderPort = m_simulatedLeader ? m_simulatedLeader(&error) : QString();
        if (run.leaderPort.isEmpty()) {
            showStatus(tr("The simulated leader arm could not start: %1").arg(error), true);
            return;
        }
        // The demo's leader has no file of its own until one is made of what it holds.
        if (m_leaderFile->text().trimmed().isEmpty() && m_simulatedLeaderCalibration) {
            const QString made = m_simulatedLeaderCalibration(&error);
            if (made.isEmpty()) {
                showStatus(
                    tr("The simulated leader's calibration file could not be made: %1").arg(error),
                    true);
                return;
            }
            m_leaderFile->setText(QDir::toNativeSeparators(made));
        }
    }
    run.followerCalibration = m_followerFile->text().trimmed();
    run.leaderCalibration = m_leaderFile->text().trimmed();
    run.maxSpeed = m_maxSpeed->value();
    run.rateHz = m_rate->value();
    run.normMode = feetech::TeleopMapping::normModeFromKey(m_normMode->currentData().toString())
                       .value_or(feetech::TeleopMapping::kDefaultNormMode);
    QSettings settings;
    settings.setValue(kNormModeKey, m_normMode->currentData());
    settings.setValue(kLeaderPortKey, chosen);
    settings.setValue(kFollowerFileKey, run.followerCalibration);
    settings.setValue(kLeaderFileKey, run.leaderCalibration);
    settings.setValue(kMaxSpeedKey, run.maxSpeed);
    settings.setValue(kRateKey, run.rateHz);
    if (!m_teleop->start(run)) {
        showStatus(m_teleop->message(), true);
        return;
    }
    showJoints();
}

void TeleopDialog::showJoints()
{
    for (const JointRow &row : std::as_const(m_rows)) {
        delete row.name;
        delete row.leader;
        delete row.follower;
    }
    m_rows.clear();
    if (QWidget *none = findChild<QLabel *>(QStringLiteral("teleopNoJoints")))
        none->hide();
    auto *box = m_jointGrid->parentWidget();
    const QVector<feetech::TeleopJoint> &joints = m_teleop->mapping().joints();
    for (int i = 0; i < joints.size(); ++i) {
        JointRow row;
        row.name = new QLabel(joints.at(i).name, box);
        for (QProgressBar **bar : {&row.leader, &row.follower}) {
            *bar = new QProgressBar(box);
            (*bar)->setRange(joints.at(i).gripper ? 0 : -100 * kBarScale, 100 * kBarScale);
            (*bar)->setValue((*bar)->minimum());
            (*bar)->setFormat(tr("—"));
        }
        row.leader->setObjectName(QStringLiteral("teleopLeader_%1").arg(joints.at(i).name));
        row.follower->setObjectName(QStringLiteral("teleopFollower_%1").arg(joints.at(i).name));
        row.leader->setToolTip(tr("Where the leader's %1 is").arg(joints.at(i).name));
        row.follower->setToolTip(
            tr("The goal last sent to the follower's %1, within its speed limit")
                .arg(joints.at(i).name));
        m_jointGrid->addWidget(row.name, i + 1, 0);
        m_jointGrid->addWidget(row.leader, i + 1, 1);
        m_jointGrid->addWidget(row.follower, i + 1, 2);
        m_rows.append(row);
    }
}

void TeleopDialog::showPositions()
{
    const feetech::TeleopLoop *loop = m_teleop->loop();
    if (!loop)
        return;
    const QVector<double> &leader = loop->leaderNormalised();
    const QVector<double> follower = loop->followerGoalsNormalised();
    for (int i = 0; i < m_rows.size() && i < leader.size() && i < follower.size(); ++i) {
        showNormalised(m_rows.at(i).leader, leader.at(i));
        showNormalised(m_rows.at(i).follower, follower.at(i));
    }
}

void TeleopDialog::showLoopFigures()
{
    const feetech::TeleopLoop *loop = m_teleop->loop();
    if (!loop || loop->cycles() == 0) {
        m_loopFigures->setText(tr("Loop: waiting for the leader's first reading."));
        return;
    }
    m_loopFigures->setText(tr("Loop: %1 cycles a second; leader to follower %2 ms (median "
                              "%3 ms); %n cycle(s) so far",
                              nullptr, int(loop->cycles()))
                               .arg(QLocale().toString(m_teleop->rateHz(), 'f', 1),
                                    QLocale().toString(loop->lastLatencyMs(), 'f', 1),
                                    QLocale().toString(loop->medianLatencyMs(), 'f', 1)));
}

void TeleopDialog::onStateChanged(feetech::Teleoperation::State state)
{
    const bool idle = state == feetech::Teleoperation::State::Idle;
    m_start->setEnabled(idle);
    m_stopButton->setEnabled(state == feetech::Teleoperation::State::Starting
                             || state == feetech::Teleoperation::State::Running);
    for (QWidget *input : std::as_const(m_inputs))
        input->setEnabled(idle);
    if (state == feetech::Teleoperation::State::Running)
        m_figuresTimer->start();
    else
        m_figuresTimer->stop();
}

void TeleopDialog::onEnded(bool held)
{
    showLoopFigures();
    const bool problem = m_teleop->problem() != feetech::Teleoperation::Problem::None;
    showStatus(m_teleop->message(), problem || !held);
    if (const feetech::TeleopLoop *loop = m_teleop->loop(); loop && loop->cycles() > 0)
        m_loopFigures->setText(tr("Loop: stopped after %n cycle(s); leader to follower %1 ms "
                                  "(median)",
                                  nullptr, int(loop->cycles()))
                                   .arg(QLocale().toString(loop->medianLatencyMs(), 'f', 1)));
}

void TeleopDialog::showStatus(const QString &text, bool problem)
{
    m_status->setText(text);
    QPalette tinted = palette();
    if (problem)
        tinted.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Error, tinted));
    m_status->setPalette(tinted);
}

void TeleopDialog::hideEvent(QHideEvent *event)
{
    // Closed while it runs: the loop ends and the follower holds where it stands.
    m_teleop->stop();
    QDialog::hideEvent(event);
}
