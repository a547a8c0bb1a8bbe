// Control page: the servo shown, its controls kept in step with the device, and the status line;
// the groups and the writes are in controlpagegroups.cpp and controlpagewrites.cpp.
#include "controlpage.h"

#include "busclient.h"
#include "goalrange.h"
#include "motiontestpanel.h"
#include "palette.h"
#include "registerkeys.h"
#include "registerwidgets.h"
#include "servoparameters.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFrame>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace feetech::registerkeys;
using registerwidgets::setRegisterRange;
using registerwidgets::unitText;

namespace {

// While the page is on screen and the monitor does not stream the servo, its RAM (present
// position, torque state) is read this often.
constexpr int kPresentRefreshMs = 250;

} // namespace

int ControlPage::toInt(qint64 value)
{
    return int(std::clamp<qint64>(value, std::numeric_limits<int>::min(),
                                  std::numeric_limits<int>::max()));
}

// Damping only where the table says the servo knows it.
bool ControlPage::allowsDamping(const feetech::RegisterTable &table)
{
    return table.find(kTorqueEnable) && table.torqueValue(feetech::TorqueMode::Damping);
}

ControlPage::ControlPage(feetech::BusClient *client, QWidget *parent)
    : QWidget(parent)
    , m_client(client)
    , m_test(new feetech::MotionTest(client, {}, this))
{
    setObjectName(QStringLiteral("controlPage"));

    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->setSpacing(0);

    m_hint = new QLabel(this);
    m_hint->setObjectName(QStringLiteral("controlHint"));
    m_hint->setWordWrap(true);
    m_hint->setMargin(10);
    m_hint->setForegroundRole(QPalette::PlaceholderText);
    outer->addWidget(m_hint);
    outer->addWidget(buildGuardBanner());

    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("controlScrollArea"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_body = new QWidget(scroll);
    auto *body = new QVBoxLayout(m_body);
    body->setContentsMargins(8, 8, 8, 8);
    body->setSpacing(10);

    // Two columns: the servo's own controls on the left, the tests and their results (which
    // want the room for a plot) on the right.
    auto *columns = new QHBoxLayout;
    columns->setSpacing(10);
    auto *left = new QVBoxLayout;
    left->setSpacing(10);
    left->addWidget(buildTorqueGroup());
    left->addWidget(buildGoalGroup());
    left->addWidget(buildModeGroup());
    left->addStretch(1);
    columns->addLayout(left, 0);
    m_testPanel = new MotionTestPanel(m_test, this);
    connect(m_testPanel, &MotionTestPanel::statusChanged, this,
            [this](const QString &text, bool isError) {
                setStatus(text, isError ? Severity::Error : Severity::Info);
            });
    columns->addWidget(m_testPanel, 1);
    body->addLayout(columns, 1);
    scroll->setWidget(m_body);
    outer->addWidget(scroll, 1);

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));
    m_status->setWordWrap(true);
    m_status->setContentsMargins(10, 4, 10, 6);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    outer->addWidget(m_status);

    connect(m_client, &feetech::BusClient::servosChanged, this, &ControlPage::onServosChanged);
    connect(m_client, &feetech::BusClient::servoUpdated, this, &ControlPage::onServoUpdated);
    connect(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived, this,
            &ControlPage::onTelemetry);
    connect(m_client->telemetry(), &feetech::TelemetryHub::streamingChanged, this,
            &ControlPage::updatePresent);
    connect(m_client, &feetech::BusClient::allTorqueOffRequested, this,
            &ControlPage::onAllTorqueOff);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        if (!m_client->isConnected()) {
            // Nothing comes back from writes the link dropped.
            m_goalsInFlight = 0;
            m_torqueWritesInFlight = 0;
            m_queuedGoal.reset();
        }
        updateEnabled();
        updatePresent();
    });

    connect(m_test, &feetech::MotionTest::runningChanged, this, &ControlPage::onTestRunning);

    m_refreshTimer = new QTimer(this);
    m_refreshTimer->setInterval(kPresentRefreshMs);
    connect(m_refreshTimer, &QTimer::timeout, this, &ControlPage::refreshPresent);
    m_refreshTimer->start();

    m_testPanel->clearResults();
    configureForServo();
}

ControlPage::~ControlPage()
{
    // A test still running puts the monitor back as it found it; the signals that causes must
    // not reach this page while it is half destroyed.
    if (m_client)
        disconnect(m_client, nullptr, this, nullptr);
    delete m_test;
}

// ---- the servo shown

void ControlPage::setServo(int index)
{
    if (index < 0 || index >= m_client->servoCount())
        index = -1;
    const std::optional<std::pair<quint8, qint32>> servo = index >= 0
        ? std::make_optional(
            std::make_pair(m_client->servo(index).info.id, m_client->servo(index).info.baud))
        : std::nullopt;
    const bool changed = servo != m_servo;
    m_index = index;
    m_servo = servo;
    m_testPanel->setServo(index, servoName());
    showGuard();
    if (changed) {
        setStatus({}, Severity::Info);
        configureForServo();
        if (!m_test->isRunning())
            m_testPanel->clearResults(); // after the new servo's From and To: the plot spans them
    } else {
        updateRanges();
        syncFromDevice();
        updateEnabled();
    }
}

void ControlPage::setConfirmMoves(bool confirm)
{
    m_confirmMoves = confirm;
    m_testPanel->setConfirmMoves(confirm);
}

void ControlPage::setMotionTiming(const feetech::MotionTiming &timing)
{
    m_test->setTiming(timing);
}

QString ControlPage::statusText() const
{
    return m_status->text();
}

bool ControlPage::ready() const
{
    return m_client->isConnected() && m_index >= 0 && m_index < m_client->servoCount()
        && m_client->servo(m_index).info.hasTable();
}

bool ControlPage::testRunsHere() const
{
    return m_test->isRunning() && m_index >= 0 && m_test->plan().index == m_index;
}

QString ControlPage::servoName() const
{
    return m_servo ? tr("Servo ID %1").arg(m_servo->first) : QString();
}

void ControlPage::onServosChanged()
{
    // The list was rebuilt or reordered: find the servo shown by its address.
    const int index = m_servo ? m_client->indexOf(m_servo->first, m_servo->second) : -1;
    if (index != m_index) {
        m_index = index;
        if (index < 0)
            m_servo.reset();
        m_testPanel->setServo(index, servoName());
        configureForServo();
    }
}

void ControlPage::configureForServo()
{
    m_presentPosition.reset();
    m_presentReadMs = 0;
    m_goalInitialised = false;
    m_modeEdited = false;
    m_queuedGoal.reset();
    if (!ready()) {
        updateEnabled();
        updatePresent();
        return;
    }
    const feetech::RegisterTable &table = m_client->servo(m_index).info.table();
    const model::ParameterModel *parameters = m_client->parameters(m_index);

    const bool damping = allowsDamping(table);
    m_torqueDamping->setToolTip(
        damping ? tr("Damping: the horn can be turned by hand against a resistance (torque "
                     "enable 2).")
                : tr("%1 servos have no damping mode.").arg(feetech::familyName(table.family())));

    {
        const QSignalBlocker blocker(m_mode);
        m_mode->clear();
        if (const feetech::Register *mode = table.find(kMode)) {
            for (const feetech::Choice &choice : mode->choices)
                m_mode->addItem(feetech::tableText(choice.label), choice.value);
            m_modeNote->setText(tr("Stored in EEPROM: the servo keeps it when powered off."));
        } else {
            m_modeNote->setText(tr("%1 servos have no operating mode register: they hold "
                                   "positions.")
                                    .arg(feetech::familyName(table.family())));
        }
    }

    const feetech::Register *speed = table.find(kGoalSpeed);
    const feetech::Register *acceleration = table.find(kAcceleration);
    setRegisterRange(m_speed, speed, true);
    setRegisterRange(m_acceleration, acceleration, true);
    m_speedUnit->setText(unitText(speed));
    m_accelerationUnit->setText(unitText(acceleration));
    // What the servo is set to, or a gentle third of its range (0 would mean flat out).
    const auto deviceSpeed = parameters->deviceValue(kGoalSpeed);
    const int speedValue = deviceSpeed && *deviceSpeed > 0
        ? toInt(*deviceSpeed)
        : (speed ? std::max(speed->maximum / 3, 1) : 0);
    const auto deviceAcceleration = parameters->deviceValue(kAcceleration);
    const int accelerationValue = deviceAcceleration && *deviceAcceleration > 0
        ? toInt(*deviceAcceleration)
        : (acceleration ? std::max(acceleration->maximum / 5, 1) : 0);
    m_speed->setValue(speedValue);
    m_acceleration->setValue(accelerationValue);
    m_testPanel->configure(speed, acceleration, speedValue, accelerationValue);

    updateRanges();
    syncFromDevice();
    updatePresent();
    updateEnabled();
}

void ControlPage::updateRanges()
{
    const auto range = ready() ? feetech::goalRange(*m_client, m_index) : std::nullopt;
    if (!range) {
        m_rangeNote->clear();
        return;
    }
    if (m_slider->minimum() != range->minimum || m_slider->maximum() != range->maximum) {
        const QSignalBlocker blocker(m_slider);
        m_slider->setRange(range->minimum, range->maximum);
        m_slider->setPageStep(std::max(1, (range->maximum - range->minimum) / 20));
        m_slider->setTickInterval(std::max(1, (range->maximum - range->minimum) / 8));
    }
    if (m_goal->minimum() != range->minimum || m_goal->maximum() != range->maximum) {
        const QSignalBlocker blocker(m_goal);
        m_goal->setRange(range->minimum, range->maximum);
    }
    m_testPanel->setPositionRange(range->minimum, range->maximum);
    {
        const QSignalBlocker blocker(m_slider);
        m_slider->setValue(m_goal->value());
    }
    m_sliderMinimum->setText(QLocale().toString(range->minimum));
    m_sliderMaximum->setText(QLocale().toString(range->maximum));
    m_rangeNote->setText(range->fromAngleLimits
                             ? tr("Goals are limited to the servo's angle limits, %1 to %2 steps.")
                                   .arg(range->minimum)
                                   .arg(range->maximum)
                             : tr("The servo has no angle limits (multi-turn) or they are not read "
                                  "yet: goals are limited to the register's range, %1 to %2.")
                                   .arg(range->minimum)
                                   .arg(range->maximum));
}

void ControlPage::onServoUpdated(int index)
{
    if (index != m_index || !ready())
        return;
    updateRanges();
    syncFromDevice();
    updatePresent();
    updateEnabled();
}

void ControlPage::syncFromDevice()
{
    if (!ready())
        return;
    const model::ParameterModel *parameters = m_client->parameters(m_index);
    const auto torque = parameters->deviceValue(kTorqueEnable);
    const auto mode =
        torque ? m_client->servo(m_index).info.table().torqueMode(*torque) : std::nullopt;
    QAbstractButton *checked = mode ? m_torqueButtons->button(int(*mode)) : nullptr;
    if (checked) {
        checked->setChecked(true);
    } else if (QAbstractButton *current = m_torqueButtons->checkedButton()) {
        // Unknown (not read yet, or a value the buttons do not offer): none is pressed.
        m_torqueButtons->setExclusive(false);
        current->setChecked(false);
        m_torqueButtons->setExclusive(true);
    }
    if (!torque)
        m_torqueState->setText(tr("Torque state not read yet."));
    else if (mode == feetech::TorqueMode::Off)
        m_torqueState->setText(tr("Off: the horn turns freely."));
    else if (mode == feetech::TorqueMode::On)
        m_torqueState->setText(tr("On: the servo holds its goal position."));
    else if (mode == feetech::TorqueMode::Damping)
        m_torqueState->setText(tr("Damping: the horn resists being turned."));
    else
        m_torqueState->setText(tr("Torque enable is %1.").arg(*torque));

    if (!m_modeEdited) {
        const auto mode = parameters->deviceValue(kMode);
        const QSignalBlocker blocker(m_mode);
        m_mode->setCurrentIndex(mode ? m_mode->findData(qint32(*mode)) : -1);
    }

    // The goal starts where the horn is, so Move or a touch of the slider cannot jump it to a
    // stale goal register.
    if (!m_goalInitialised) {
        auto start = parameters->deviceValue(kPresentPosition);
        if (!start)
            start = parameters->deviceValue(kGoalPosition);
        if (start) {
            m_goalInitialised = true;
            const int here = std::clamp(toInt(*start), m_goal->minimum(), m_goal->maximum());
            {
                const QSignalBlocker spinBlocker(m_goal);
                const QSignalBlocker sliderBlocker(m_slider);
                m_goal->setValue(here);
                m_slider->setValue(here);
            }
            m_testPanel->proposeAround(here, m_goal->minimum(), m_goal->maximum());
        }
    }
}

void ControlPage::onTelemetry(const QVector<feetech::FeedbackSample> &samples)
{
    if (!m_servo)
        return;
    std::optional<double> position;
    for (const feetech::FeedbackSample &sample : samples) {
        if (sample.id == m_servo->first && sample.baud == m_servo->second
            && sample.value(feetech::Quantity::Position))
            position = sample.value(feetech::Quantity::Position);
    }
    if (position) {
        m_presentPosition = position;
        updatePresent();
    }
}

void ControlPage::updatePresent()
{
    if (!ready()) {
        m_presentPosition.reset();
        m_presentReadMs = 0;
    } else {
        // Whichever came last: a telemetry sample, or a read of the register (the stream may
        // have stopped since its last sample, or never have carried this servo).
        const model::ParameterModel *parameters = m_client->parameters(m_index);
        const qint64 readMs = parameters->lastReadMs(kPresentPosition);
        if (readMs != m_presentReadMs) {
            m_presentReadMs = readMs;
            if (const auto value = parameters->deviceValue(kPresentPosition))
                m_presentPosition = double(*value);
        }
        if (!m_presentPosition && m_client->telemetry()->isStreamed(m_index)) {
            if (const auto sample = m_client->telemetry()->latestSample(m_index))
                m_presentPosition = sample->value(feetech::Quantity::Position);
        }
    }
    m_present->setText(m_presentPosition ? tr("%1 step").arg(std::lround(*m_presentPosition))
                                         : QStringLiteral("—"));
}

void ControlPage::refreshPresent()
{
    if (!isVisible() || !ready() || m_client->telemetry()->isStreamed(m_index)
        || m_client->isBusy())
        return;
    m_client->refreshRam(m_index);
}

void ControlPage::updateEnabled()
{
    const bool ok = ready();
    const bool here = testRunsHere();
    const feetech::RegisterTable *table = ok ? &m_client->servo(m_index).info.table() : nullptr;
    const auto has = [table](const QString &key) {
        return table && table->find(key);
    };

    if (ok) {
        m_hint->hide();
    } else {
        if (m_index < 0)
            m_hint->setText(tr("Select a servo in the tree to control it."));
        else if (!m_client->isConnected())
            m_hint->setText(tr("The bus is not connected: connect and scan to control servos."));
        else
            m_hint->setText(tr("This servo's model is unknown: ServoBench does not move it."));
        m_hint->show();
    }

    const bool torque = has(kTorqueEnable);
    m_torqueOff->setEnabled(torque);
    m_torqueOn->setEnabled(torque);
    m_torqueDamping->setEnabled(torque && allowsDamping(*table));

    const bool goal = has(kGoalPosition) && !here;
    for (QWidget *widget : {static_cast<QWidget *>(m_slider), static_cast<QWidget *>(m_goal),
                            static_cast<QWidget *>(m_move)})
        widget->setEnabled(goal);
    m_speed->setEnabled(goal && has(kGoalSpeed));
    m_acceleration->setEnabled(goal && has(kAcceleration));

    const bool mode = has(kMode) && !here;
    m_mode->setEnabled(mode);
    m_modeApply->setEnabled(mode && m_modeEdited && m_mode->currentIndex() >= 0);

    m_testPanel->updateEnabled(has(kGoalPosition), has(kGoalSpeed), has(kAcceleration));
}

void ControlPage::onTestRunning(bool running)
{
    if (running) {
        m_queuedGoal.reset(); // the test owns the goal now
    } else if (ready() && m_test->plan().index == m_index) {
        // The goal controls take over from where the test left the goal, so a touch of the
        // slider does not jump the horn back to an old one.
        if (const auto goal = m_client->parameters(m_index)->deviceValue(kGoalPosition)) {
            const QSignalBlocker spinBlocker(m_goal);
            const QSignalBlocker sliderBlocker(m_slider);
            m_goal->setValue(toInt(*goal));
            m_slider->setValue(m_goal->value());
        }
    }
    updateEnabled();
}

void ControlPage::setStatus(const QString &text, Severity severity)
{
    m_status->setText(text);
    m_status->setProperty("severity", int(severity));
    if (severity == Severity::Info) {
        m_status->setPalette(QPalette());
    } else {
        QPalette colours = m_status->palette();
        colours.setColor(QPalette::WindowText,
                         palette::toneColor(severity == Severity::Error ? palette::Tone::Error
                                                                        : palette::Tone::Warning,
                                            palette()));
        m_status->setPalette(colours);
    }
    m_status->setVisible(!text.isEmpty());
}
