// Control page: the servo shown, its controls kept in step with the device, the writes they make
// (torque, goals from the slider, mode changes after a warning), and the status line.
#include "controlpage.h"

#include "busclient.h"
#include "goalrange.h"
#include "goalstreamer.h"
#include "guardbanner.h"
#include "jointnames.h"
#include "motiontestpanel.h"
#include "palette.h"
#include "registerkeys.h"
#include "registerspinbox.h"
#include "registerwidgets.h"
#include "servoparameters.h"
#include "shareservice.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFrame>
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
    , m_goals(new feetech::GoalStreamer(client, this))
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
    m_guardBanner = new GuardBanner(client, this);
    outer->addWidget(m_guardBanner);

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
    m_controls.setup(this);
    left->addWidget(m_controls.torqueGroup);
    left->addWidget(m_controls.goalGroup);
    left->addWidget(m_controls.modeGroup);
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

    connect(m_controls.torqueButtons, &QButtonGroup::idClicked, this, &ControlPage::setTorque);
    connect(m_controls.mode, &QComboBox::activated, this, [this] {
        const auto device = m_index >= 0 && m_client->servos()->parameters(m_index)
            ? m_client->servos()->parameters(m_index)->deviceValue(kMode)
            : std::nullopt;
        m_modeEdited = !device || m_controls.mode->currentData().toLongLong() != *device;
        updateEnabled();
    });
    connect(m_controls.modeApply, &QPushButton::clicked, this, &ControlPage::changeMode);
    connect(m_controls.slider, &QSlider::valueChanged, this, &ControlPage::onSliderMoved);
    connect(m_controls.move, &QPushButton::clicked, this,
            [this] { moveTo(m_controls.goal->value()); });
    // Queued for the servo shown: a change of servo clears the queue.
    connect(m_goals, &feetech::GoalStreamer::queuedGoalDue, this,
            [this](qint32 goal) { moveTo(goal); });

    connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
            &ControlPage::onServosChanged);
    connect(m_client->servos(), &feetech::ServoList::servoUpdated, this,
            &ControlPage::onServoUpdated);
    connect(m_client->telemetry(), &feetech::TelemetryHub::samplesReceived, this,
            &ControlPage::onTelemetry);
    connect(m_client->telemetry(), &feetech::TelemetryHub::streamingChanged, this,
            &ControlPage::updatePresent);
    connect(m_client->share(), &feetech::ShareService::stateChanged, this, [this] {
        updateEnabled();
        updateRanges();
    });
    connect(m_client, &feetech::BusClient::allTorqueOffRequested, this,
            &ControlPage::onAllTorqueOff);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        if (!m_client->link()->isConnected()) {
            // Nothing comes back from writes the link dropped.
            m_goals->forgetWrites();
            m_torqueWritesInFlight = 0;
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
    if (index < 0 || index >= m_client->servos()->count())
        index = -1;
    const std::optional<feetech::ServoAddress> servo = index >= 0
        ? std::make_optional(m_client->servos()->at(index).info.address())
        : std::nullopt;
    const bool changed = servo != m_servo;
    m_index = index;
    m_servo = servo;
    m_testPanel->setServo(index, servoName());
    m_guardBanner->setServo(index);
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
    return m_client->link()->isConnected() && m_index >= 0 && m_index < m_client->servos()->count()
        && m_client->servos()->at(m_index).info.hasTable() && !m_client->share()->isActive();
}

bool ControlPage::testRunsHere() const
{
    return m_test->isRunning() && m_index >= 0 && m_test->plan().index == m_index;
}

QString ControlPage::servoName() const
{
    if (!m_servo)
        return {};
    // By joint where the arm matches a template ("shoulder_pan (ID 1)"), as the tree says.
    const feetech::JointNames joints = feetech::JointNames::of(*m_client);
    return joints.joint(*m_servo).isEmpty() ? tr("Servo ID %1").arg(m_servo->id)
                                            : joints.label(*m_servo);
}

void ControlPage::onServosChanged()
{
    // The list was rebuilt or reordered: find the servo shown by its address.
    const int index = m_servo ? m_client->servos()->indexOf(*m_servo) : -1;
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
    m_goals->dropQueued();
    if (!ready()) {
        updateEnabled();
        updatePresent();
        return;
    }
    const feetech::RegisterTable &table = m_client->servos()->at(m_index).info.table();
    const model::ParameterModel *parameters = m_client->servos()->parameters(m_index);

    const bool damping = allowsDamping(table);
    m_controls.torqueDamping->setToolTip(
        damping ? tr("Damping: the horn can be turned by hand against a resistance (torque "
                     "enable 2).")
                : tr("%1 servos have no damping mode.").arg(feetech::familyName(table.family())));

    {
        const QSignalBlocker blocker(m_controls.mode);
        m_controls.mode->clear();
        if (const feetech::Register *mode = table.find(kMode)) {
            for (const feetech::Choice &choice : mode->choices)
                m_controls.mode->addItem(feetech::tableText(choice.label), choice.value);
            m_controls.modeNote->setText(
                tr("Stored in EEPROM: the servo keeps it when powered off."));
        } else {
            m_controls.modeNote->setText(tr("%1 servos have no operating mode register: they hold "
                                            "positions.")
                                             .arg(feetech::familyName(table.family())));
        }
    }

    const feetech::Register *speed = table.find(kGoalSpeed);
    const feetech::Register *acceleration = table.find(kAcceleration);
    m_controls.speed->setRegister(speed, true);
    m_controls.acceleration->setRegister(acceleration, true);
    m_controls.valueNote->hide();
    // What the servo is set to, or a gentle third of its range (0 would mean flat out).
    const auto deviceSpeed = parameters->deviceValue(kGoalSpeed);
    const int speedValue = deviceSpeed && *deviceSpeed > 0
        ? toInt(*deviceSpeed)
        : (speed ? std::max(speed->maximum / 3, 1) : 0);
    const auto deviceAcceleration = parameters->deviceValue(kAcceleration);
    const int accelerationValue = deviceAcceleration && *deviceAcceleration > 0
        ? toInt(*deviceAcceleration)
        : (acceleration ? std::max(acceleration->maximum / 5, 1) : 0);
    m_controls.speed->setValue(speedValue);
    m_controls.acceleration->setValue(accelerationValue);
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
        m_controls.rangeNote->clear();
        return;
    }
    if (m_controls.slider->minimum() != range->minimum
        || m_controls.slider->maximum() != range->maximum) {
        const QSignalBlocker blocker(m_controls.slider);
        m_controls.slider->setRange(range->minimum, range->maximum);
        m_controls.slider->setPageStep(std::max(1, (range->maximum - range->minimum) / 20));
        m_controls.slider->setTickInterval(std::max(1, (range->maximum - range->minimum) / 8));
    }
    if (m_controls.goal->minimum() != range->minimum
        || m_controls.goal->maximum() != range->maximum) {
        const QSignalBlocker blocker(m_controls.goal);
        m_controls.goal->setRange(range->minimum, range->maximum);
    }
    m_testPanel->setPositionRange(range->minimum, range->maximum);
    {
        const QSignalBlocker blocker(m_controls.slider);
        m_controls.slider->setValue(m_controls.goal->value());
    }
    m_controls.sliderMinimum->setText(QLocale().toString(range->minimum));
    m_controls.sliderMaximum->setText(QLocale().toString(range->maximum));
    m_controls.rangeNote->setText(
        range->fromAngleLimits
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
    const model::ParameterModel *parameters = m_client->servos()->parameters(m_index);
    const auto torque = parameters->deviceValue(kTorqueEnable);
    const auto mode =
        torque ? m_client->servos()->at(m_index).info.table().torqueMode(*torque) : std::nullopt;
    QAbstractButton *checked = mode ? m_controls.torqueButtons->button(int(*mode)) : nullptr;
    if (checked) {
        checked->setChecked(true);
    } else if (QAbstractButton *current = m_controls.torqueButtons->checkedButton()) {
        // Unknown (not read yet, or a value the buttons do not offer): none is pressed.
        m_controls.torqueButtons->setExclusive(false);
        current->setChecked(false);
        m_controls.torqueButtons->setExclusive(true);
    }
    if (!torque)
        m_controls.torqueState->setText(tr("Torque state not read yet."));
    else if (mode == feetech::TorqueMode::Off)
        m_controls.torqueState->setText(tr("Off: the horn turns freely."));
    else if (mode == feetech::TorqueMode::On)
        m_controls.torqueState->setText(tr("On: the servo holds its goal position."));
    else if (mode == feetech::TorqueMode::Damping)
        m_controls.torqueState->setText(tr("Damping: the horn resists being turned."));
    else
        m_controls.torqueState->setText(tr("Torque enable is %1.").arg(*torque));

    if (!m_modeEdited) {
        const auto mode = parameters->deviceValue(kMode);
        const QSignalBlocker blocker(m_controls.mode);
        m_controls.mode->setCurrentIndex(mode ? m_controls.mode->findData(qint32(*mode)) : -1);
    }

    // The goal starts where the horn is, so Move or a touch of the slider cannot jump it to a
    // stale goal register.
    if (!m_goalInitialised) {
        auto start = parameters->deviceValue(kPresentPosition);
        if (!start)
            start = parameters->deviceValue(kGoalPosition);
        if (start) {
            m_goalInitialised = true;
            const int here =
                std::clamp(toInt(*start), m_controls.goal->minimum(), m_controls.goal->maximum());
            {
                const QSignalBlocker spinBlocker(m_controls.goal);
                const QSignalBlocker sliderBlocker(m_controls.slider);
                m_controls.goal->setValue(here);
                m_controls.slider->setValue(here);
            }
            m_testPanel->proposeAround(here, m_controls.goal->minimum(),
                                       m_controls.goal->maximum());
        }
    }
}

void ControlPage::onTelemetry(const QVector<feetech::FeedbackSample> &samples)
{
    if (!m_servo)
        return;
    std::optional<double> position;
    for (const feetech::FeedbackSample &sample : samples) {
        if (feetech::ServoAddress {sample.id, sample.baud} == *m_servo
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
        const model::ParameterModel *parameters = m_client->servos()->parameters(m_index);
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
    m_controls.present->setText(m_presentPosition ? QString::number(std::lround(*m_presentPosition))
                                        + registerwidgets::stepSuffix()
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
    const feetech::RegisterTable *table =
        ok ? &m_client->servos()->at(m_index).info.table() : nullptr;
    const auto has = [table](const QString &key) {
        return table && table->find(key);
    };

    if (ok) {
        m_hint->hide();
    } else {
        if (m_index < 0)
            m_hint->setText(tr("Select a servo in the tree to control it."));
        else if (!m_client->link()->isConnected())
            m_hint->setText(tr("The bus is not connected: connect and scan to control servos."));
        else if (m_client->share()->isActive())
            m_hint->setText(tr("The bus is shared with another program: ServoBench neither reads "
                               "nor moves this servo meanwhile. Stop sharing (Link › Share this "
                               "bus…) to control it here."));
        else
            m_hint->setText(tr("This servo's model is unknown: ServoBench does not move it."));
        m_hint->show();
    }

    const bool torque = has(kTorqueEnable); // false while shared: `table` is none then
    m_controls.torqueOff->setEnabled(torque);
    m_controls.torqueOn->setEnabled(torque);
    m_controls.torqueDamping->setEnabled(torque && allowsDamping(*table));

    const bool goal = has(kGoalPosition) && !here;
    for (QWidget *widget :
         {static_cast<QWidget *>(m_controls.slider), static_cast<QWidget *>(m_controls.goal),
          static_cast<QWidget *>(m_controls.move)})
        widget->setEnabled(goal);
    m_controls.speed->setEnabled(goal && has(kGoalSpeed));
    m_controls.acceleration->setEnabled(goal && has(kAcceleration));

    const bool mode = has(kMode) && !here;
    m_controls.mode->setEnabled(mode);
    m_controls.modeApply->setEnabled(mode && m_modeEdited && m_controls.mode->currentIndex() >= 0);

    m_testPanel->updateEnabled(has(kGoalPosition), has(kGoalSpeed), has(kAcceleration));
}

void ControlPage::onTestRunning(bool running)
{
    if (running) {
        m_goals->dropQueued(); // the test owns the goal now
    } else if (ready() && m_test->plan().index == m_index) {
        // The goal controls take over from where the test left the goal, so a touch of the
        // slider does not jump the horn back to an old one.
        if (const auto goal = m_client->servos()->parameters(m_index)->deviceValue(kGoalPosition)) {
            const QSignalBlocker spinBlocker(m_controls.goal);
            const QSignalBlocker sliderBlocker(m_controls.slider);
            m_controls.goal->setValue(toInt(*goal));
            m_controls.slider->setValue(m_controls.goal->value());
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

// ---- writes

bool ControlPage::write(WriteKind kind, const QVector<model::WriteItem> &values)
{
    feetech::Refusal refusal;
    feetech::OperationReply *reply = kind == WriteKind::Goal
        ? m_goals->send(m_index, values, &refusal)
        : m_client->writeValues(m_index, values, &refusal);
    if (!reply) {
        setStatus(tr("%1: %2").arg(servoName(), refusal.describe()), Severity::Error);
        return false;
    }
    if (kind == WriteKind::Torque)
        ++m_torqueWritesInFlight;
    connect(reply, &feetech::OperationReply::finished, this,
            [this, kind, id = m_servo->id](const feetech::OperationResult &result) {
                onWriteFinished(kind, id, result);
            });
    return true;
}

void ControlPage::setTorque(int modeId)
{
    const auto value = ready()
        ? m_client->servos()->at(m_index).info.table().torqueValue(feetech::TorqueMode(modeId))
        : std::nullopt;
    if (!value) {
        syncFromDevice();
        return;
    }
    setStatus({}, Severity::Info);
    if (testRunsHere()) {
        // Switching torque under a running test would leave it measuring nonsense.
        m_testPanel->stop();
    }
    if (!write(WriteKind::Torque, {{kTorqueEnable, *value}}))
        syncFromDevice(); // the buttons go back to what the servo has
}

void ControlPage::onSliderMoved(int value)
{
    {
        const QSignalBlocker blocker(m_controls.goal);
        m_controls.goal->setValue(value);
    }
    if (!ready() || testRunsHere())
        return;
    // One goal on the wire at a time; a newer one replaces whatever waits behind it.
    if (!m_goals->queueIfBusy(value))
        moveTo(value);
}

bool ControlPage::moveTo(qint32 position, QString *error)
{
    const auto refuse = [this, error](const QString &why) {
        setStatus(why, Severity::Error);
        if (error)
            *error = why;
        return false;
    };
    if (!ready())
        return refuse(m_index < 0 ? tr("No servo is selected.")
                                  : tr("The servo cannot be moved now: the bus is not "
                                       "connected or its model is unknown."));
    if (testRunsHere())
        return refuse(tr("A test is moving %1: stop it first.").arg(servoName()));
    const auto range = feetech::goalRange(*m_client, m_index);
    if (!range)
        return refuse(tr("%1 has no goal position register.").arg(servoName()));
    if (!range->contains(position))
        return refuse(tr("Goal %1 is outside %2, %3 to %4 steps: nothing was sent.")
                          .arg(position)
                          .arg(range->fromAngleLimits ? tr("the servo's angle limits")
                                                      : tr("the goal position range"))
                          .arg(range->minimum)
                          .arg(range->maximum));

    const feetech::RegisterTable &table = m_client->servos()->at(m_index).info.table();
    QVector<model::WriteItem> values;
    if (table.find(kAcceleration))
        values.append({kAcceleration, m_controls.acceleration->value()});
    if (table.find(kGoalSpeed))
        values.append({kGoalSpeed, m_controls.speed->value()});
    values.append({kGoalPosition, position});
    if (!write(WriteKind::Goal, values)) {
        if (error)
            *error = statusText();
        return false;
    }
    const bool torqueWritePending = m_torqueWritesInFlight > 0;
    const auto torque = m_client->servos()->parameters(m_index)->deviceValue(kTorqueEnable);
    if (!torqueWritePending && torque
        && m_client->servos()->at(m_index).info.table().torqueMode(*torque)
            == feetech::TorqueMode::Off)
        setStatus(tr("Torque is off: %1 keeps the goal but does not move until torque is on.")
                      .arg(servoName()),
                  Severity::Warning);
    else if (m_status->property("severity").toInt() == int(Severity::Error))
        setStatus({}, Severity::Info); // an earlier refusal no longer applies
    {
        const QSignalBlocker spinBlocker(m_controls.goal);
        const QSignalBlocker sliderBlocker(m_controls.slider);
        m_controls.goal->setValue(position);
        m_controls.slider->setValue(position);
    }
    return true;
}

void ControlPage::changeMode()
{
    if (!ready() || m_controls.mode->currentIndex() < 0)
        return;
    const qint64 value = m_controls.mode->currentData().toLongLong();
    const auto device = m_client->servos()->parameters(m_index)->deviceValue(kMode);
    if (device && *device == value) {
        m_modeEdited = false;
        updateEnabled();
        return;
    }
    if (m_confirmMoves) {
        const int deviceIndex = device ? m_controls.mode->findData(qint32(*device)) : -1;
        const QString from =
            deviceIndex >= 0 ? m_controls.mode->itemText(deviceIndex) : tr("unknown");
        QMessageBox box(QMessageBox::Warning, tr("Change the operating mode?"),
                        tr("%1 will change from “%2” to “%3”.")
                            .arg(servoName(), from, m_controls.mode->currentText()),
                        QMessageBox::Ok | QMessageBox::Cancel, this);
        box.setInformativeText(
            tr("The servo will move differently from now on: in speed or PWM mode the goal "
               "registers make it turn continuously instead of holding a position. The mode is "
               "written to EEPROM and kept after power-off."));
        box.button(QMessageBox::Ok)->setText(tr("Change mode"));
        box.setDefaultButton(QMessageBox::Cancel);
        if (box.exec() != QMessageBox::Ok)
            return;
    }
    setStatus({}, Severity::Info);
    write(WriteKind::Mode, {{kMode, value}});
}

void ControlPage::onWriteFinished(WriteKind kind, quint8 id, const feetech::OperationResult &result)
{
    // A link that went down set the count to 0 already. GoalStreamer counts the goals, drops
    // the goal queued behind a failing one and has the one queued behind a good one sent.
    if (kind == WriteKind::Torque)
        m_torqueWritesInFlight = std::max(0, m_torqueWritesInFlight - 1);
    if (kind == WriteKind::Mode)
        m_modeEdited = false;
    // A write the lost link dropped is no failure of the servo's: the page shows the link.
    if (!result.ok && result.failure != feetech::OperationFailure::LinkLost)
        setStatus(tr("Writing to servo ID %1 failed: %2").arg(id).arg(result.message),
                  Severity::Error);
    syncFromDevice();
    updateEnabled();
}

void ControlPage::onAllTorqueOff()
{
    m_goals->dropQueued();
    if (ready())
        m_controls.torqueOff->setChecked(true); // the read-back confirms it
    m_controls.torqueState->setText(tr("Off: All torque off was sent to every servo."));
    // Sent, not yet confirmed: the read-back of each servo says (a servo that no longer
    // answers cannot confirm it, and the window says so then).
    setStatus(tr("All torque off was sent to every servo of the bus; each one's torque is read "
                 "back to confirm it."),
              Severity::Warning);
}
