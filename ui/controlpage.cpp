// Control page: torque and goal writes through the bus client, throttled slider goals, and the
// step / sweep tests run by feetech::MotionTest with their metrics and response plot.
#include "controlpage.h"

#include "feetech/busclient.h"
#include "feetech/goalrange.h"
#include "feetech/registerkeys.h"
#include "feetech/servoparameters.h"
#include "widgethelpers.h"

#include <QButtonGroup>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFrame>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

using namespace feetech::registerkeys;
using widgethelpers::actionButton;

namespace {

constexpr int kTorqueOff = 0;
constexpr int kTorqueOn = 1;
constexpr int kTorqueDamping = 2;

// While the page is on screen and the monitor does not stream the servo, its RAM (present
// position, torque state) is read this often.
constexpr int kPresentRefreshMs = 250;
// A goal write with no answer after this long is taken as lost: the slider sends again.
constexpr int kGoalWriteStaleMs = 2000;
// Test defaults: a small move around where the horn is, at a gentle speed.
constexpr qint32 kMinimumTestSpan = 20; // steps each side
constexpr qint32 kMaximumTestSpan = 400;
constexpr int kDefaultLegs = 4;
constexpr double kDefaultRecordSeconds = 2.0;
constexpr double kMinimumRecordSeconds = 0.2;
constexpr int kChartMinimumHeight = 210;
constexpr int kSliderMinimumWidth = 220;
constexpr double kMinimumVisibleBand = 0.05; // of the position axis

bool isDark(const QPalette &palette)
{
    return palette.color(QPalette::Window).lightness() < 128;
}

QColor severityColor(bool dark, bool error)
{
    if (error)
        return dark ? QColor(255, 120, 110) : QColor(190, 30, 30);
    return dark ? QColor(255, 196, 84) : QColor(168, 98, 0);
}

int toInt(qint64 value)
{
    return int(std::clamp<qint64>(value, std::numeric_limits<int>::min(),
                                  std::numeric_limits<int>::max()));
}

// A register's unit as its raw values read: "step/s", or "× 100 step/s²" when scaled.
QString unitText(const feetech::Register *reg)
{
    if (!reg)
        return {};
    if (reg->scale == 1.0)
        return reg->unit;
    return ControlPage::tr("× %1 %2", "scale and unit of a register value")
        .arg(QLocale().toString(reg->scale, 'g', 6), reg->unit)
        .trimmed();
}

// Damping (torque enable 2) only where the table says the servo knows it.
bool allowsDamping(const feetech::Register *reg)
{
    if (!reg)
        return false;
    if (!reg->choices.isEmpty())
        return std::any_of(reg->choices.cbegin(), reg->choices.cend(),
                           [](const feetech::Choice &c) { return c.value == kTorqueDamping; });
    return reg->minimum <= kTorqueDamping && reg->maximum >= kTorqueDamping;
}

QSpinBox *spinBox(const char *name, QWidget *parent)
{
    auto *spin = new QSpinBox(parent);
    spin->setObjectName(QLatin1String(name));
    spin->setAlignment(Qt::AlignRight);
    spin->setAccelerated(true);
    spin->setMinimumWidth(96);
    return spin;
}

QLabel *valueLabel(const char *name, QWidget *parent)
{
    auto *label = new QLabel(QStringLiteral("—"), parent);
    label->setObjectName(QLatin1String(name));
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

// Keeps a spin box's range to a register's (non-negative where a sign means a direction).
void setRegisterRange(QSpinBox *spin, const feetech::Register *reg, bool nonNegative)
{
    const QSignalBlocker blocker(spin);
    if (!reg) {
        spin->setRange(0, 0);
        return;
    }
    spin->setRange(nonNegative ? std::max(0, reg->minimum) : reg->minimum, reg->maximum);
}

} // namespace

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
    columns->addWidget(buildTestGroup(), 1);
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
    connect(m_client, &feetech::BusClient::telemetryReceived, this, &ControlPage::onTelemetry);
    connect(m_client, &feetech::BusClient::monitoringChanged, this, &ControlPage::updatePresent);
    connect(m_client, &feetech::BusClient::operationFinished, this,
            &ControlPage::onOperationFinished);
    connect(m_client, &feetech::BusClient::allTorqueOffRequested, this,
            &ControlPage::onAllTorqueOff);
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        if (!m_client->isConnected()) {
            // Nothing comes back from writes the link dropped.
            m_writes.clear();
            m_goalInFlight = false;
            m_queuedGoal.reset();
        }
        updateEnabled();
        updatePresent();
    });

    connect(m_test, &feetech::MotionTest::runningChanged, this, &ControlPage::onTestRunning);
    connect(m_test, &feetech::MotionTest::progress, m_testProgress, &QLabel::setText);
    connect(m_test, &feetech::MotionTest::stepFinished, this, &ControlPage::onStepFinished);
    connect(m_test, &feetech::MotionTest::sweepFinished, this, &ControlPage::onSweepFinished);
    connect(m_test, &feetech::MotionTest::failed, this, &ControlPage::onTestFailed);

    m_refreshTimer = new QTimer(this);
    m_refreshTimer->setInterval(kPresentRefreshMs);
    connect(m_refreshTimer, &QTimer::timeout, this, &ControlPage::refreshPresent);
    m_refreshTimer->start();

    clearResults();
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

// ---- building

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
    for (const auto &[button, value] :
         {std::pair(m_torqueOff, kTorqueOff), std::pair(m_torqueOn, kTorqueOn),
          std::pair(m_torqueDamping, kTorqueDamping)}) {
        button->setCheckable(true);
        button->setMinimumWidth(88);
        m_torqueButtons->addButton(button, value);
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

QGroupBox *ControlPage::buildTestGroup()
{
    m_testGroup = new QGroupBox(tr("Step and sweep tests"), this);
    m_testGroup->setObjectName(QStringLiteral("testGroup"));
    auto *layout = new QVBoxLayout(m_testGroup);
    layout->setSpacing(8);

    // What to run: three rows of two settings.
    auto *settings = new QGridLayout;
    settings->setHorizontalSpacing(10);
    m_from = spinBox("testFromSpinBox", m_testGroup);
    m_from->setSuffix(tr(" step"));
    m_to = spinBox("testToSpinBox", m_testGroup);
    m_to->setSuffix(tr(" step"));
    m_testSpeed = spinBox("testSpeedSpinBox", m_testGroup);
    m_testSpeed->setToolTip(tr("Goal speed of the test moves (0: the servo's maximum)."));
    m_testAcceleration = spinBox("testAccelerationSpinBox", m_testGroup);
    m_testAcceleration->setToolTip(tr("Acceleration of the test moves (0: the servo's maximum)."));
    m_recordSeconds = new QDoubleSpinBox(m_testGroup);
    m_recordSeconds->setObjectName(QStringLiteral("recordSecondsSpinBox"));
    m_recordSeconds->setAlignment(Qt::AlignRight);
    m_recordSeconds->setRange(kMinimumRecordSeconds, feetech::MotionPlan::kMaximumRecordSeconds);
    m_recordSeconds->setDecimals(1);
    m_recordSeconds->setSingleStep(0.5);
    m_recordSeconds->setSuffix(tr(" s"));
    m_recordSeconds->setValue(kDefaultRecordSeconds);
    m_recordSeconds->setToolTip(tr("Step test: how long the response is recorded after the step."));
    m_legs = spinBox("sweepLegsSpinBox", m_testGroup);
    m_legs->setRange(1, feetech::MotionPlan::kMaximumLegs);
    m_legs->setValue(kDefaultLegs);
    m_legs->setToolTip(tr("Sweep: moves between the two positions, to and back counting as two."));
    const std::pair<QString, QWidget *> cells[] = {{tr("From"), m_from},
                                                   {tr("To"), m_to},
                                                   {tr("Speed"), m_testSpeed},
                                                   {tr("Acceleration"), m_testAcceleration},
                                                   {tr("Record"), m_recordSeconds},
                                                   {tr("Sweep legs"), m_legs}};
    for (int i = 0; i < int(std::size(cells)); ++i) {
        const int row = i / 2;
        const int column = (i % 2) * 2;
        settings->addWidget(new QLabel(cells[i].first, m_testGroup), row, column);
        settings->addWidget(cells[i].second, row, column + 1);
    }
    settings->setColumnStretch(4, 1); // the fields keep their size; the room goes after them
    layout->addLayout(settings);

    auto *buttons = new QHBoxLayout;
    m_stepButton =
        actionButton(tr("Step test…"), "stepTestButton",
                     tr("Move to From, then step to To and measure the response."), m_testGroup);
    m_sweepButton = actionButton(tr("Sweep…"), "sweepButton",
                                 tr("Move back and forth between From and To."), m_testGroup);
    m_stopButton =
        actionButton(tr("Stop"), "stopTestButton",
                     tr("Stop the running test; the servo holds where it is."), m_testGroup);
    buttons->addWidget(m_stepButton);
    buttons->addWidget(m_sweepButton);
    buttons->addWidget(m_stopButton);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_testProgress = new QLabel(m_testGroup);
    m_testProgress->setObjectName(QStringLiteral("testProgressLabel"));
    m_testProgress->setWordWrap(true);
    layout->addWidget(m_testProgress);

    // The step response, as numbers and as a plot.
    auto *line = new QFrame(m_testGroup);
    line->setFrameShape(QFrame::HLine);
    line->setFrameShadow(QFrame::Sunken);
    layout->addWidget(line);
    auto *metrics = new QGridLayout;
    metrics->setHorizontalSpacing(10);
    m_riseTime = valueLabel("riseTimeLabel", m_testGroup);
    m_riseTime->setToolTip(tr("From 10 % to 90 % of the step."));
    m_overshoot = valueLabel("overshootLabel", m_testGroup);
    m_overshoot->setToolTip(tr("How far the peak went beyond the target, as a share of the step."));
    m_settlingTime = valueLabel("settlingTimeLabel", m_testGroup);
    m_settlingTime->setToolTip(
        tr("From the step command until the position stays within the settling band."));
    m_steadyStateError = valueLabel("steadyStateErrorLabel", m_testGroup);
    m_steadyStateError->setToolTip(
        tr("Target minus the mean position over the last tenth of the recording."));
    m_band = valueLabel("settlingBandLabel", m_testGroup);
    m_band->setToolTip(tr("2 % of the step, at least 2 steps, either side of the target."));
    const std::pair<QString, QLabel *> results[] = {{tr("Rise time"), m_riseTime},
                                                    {tr("Overshoot"), m_overshoot},
                                                    {tr("Settling time"), m_settlingTime},
                                                    {tr("Steady-state error"), m_steadyStateError},
                                                    {tr("Settling band"), m_band}};
    for (int i = 0; i < int(std::size(results)); ++i) {
        const int row = i / 2;
        const int column = (i % 2) * 2;
        auto *label = new QLabel(results[i].first, m_testGroup);
        label->setForegroundRole(QPalette::PlaceholderText);
        metrics->addWidget(label, row, column);
        QFont bold = results[i].second->font();
        bold.setBold(true);
        results[i].second->setFont(bold);
        metrics->addWidget(results[i].second, row, column + 1);
    }
    metrics->setColumnStretch(1, 1);
    metrics->setColumnStretch(3, 1);
    layout->addLayout(metrics);

    auto *chart = new QChart;
    if (isDark(palette()))
        chart->setTheme(QChart::ChartThemeDark);
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->setBackgroundRoundness(0);
    chart->legend()->setAlignment(Qt::AlignTop);
    QFont small = chart->legend()->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    chart->legend()->setFont(small);
    m_response = new QLineSeries(chart);
    m_response->setName(tr("Position (step)"));
    m_targetLine = new QLineSeries(chart);
    m_targetLine->setName(tr("Target"));
    m_bandHigh = new QLineSeries(chart);
    m_bandHigh->setName(tr("Settling band"));
    m_bandLow = new QLineSeries(chart);
    for (QLineSeries *series : {m_response, m_targetLine, m_bandHigh, m_bandLow})
        chart->addSeries(series);
    QPen target(QColor(150, 150, 150), 1.5, Qt::DashLine);
    m_targetLine->setPen(target);
    QPen band(QColor(46, 160, 67), 1.0, Qt::DotLine);
    m_bandHigh->setPen(band);
    m_bandLow->setPen(band);
    for (QLegendMarker *marker : chart->legend()->markers(m_bandLow))
        marker->setVisible(false);
    m_timeAxis = new QValueAxis(chart);
    m_timeAxis->setTitleText(tr("Time since the step (ms)"));
    m_timeAxis->setLabelFormat(QStringLiteral("%.0f"));
    // The series' name carries the unit: an axis title would take the labels' room.
    m_positionAxis = new QValueAxis(chart);
    m_positionAxis->setLabelFormat(QStringLiteral("%.0f"));
    chart->addAxis(m_timeAxis, Qt::AlignBottom);
    chart->addAxis(m_positionAxis, Qt::AlignLeft);
    for (QLineSeries *series : {m_response, m_targetLine, m_bandHigh, m_bandLow}) {
        series->attachAxis(m_timeAxis);
        series->attachAxis(m_positionAxis);
    }
    m_chartView = new QChartView(chart, m_testGroup);
    m_chartView->setObjectName(QStringLiteral("stepChart"));
    m_chartView->setRenderHint(QPainter::Antialiasing);
    m_chartView->setMinimumHeight(kChartMinimumHeight);
    layout->addWidget(m_chartView, 1);

    connect(m_stepButton, &QPushButton::clicked, this,
            [this] { startTest(feetech::MotionTest::Kind::Step); });
    connect(m_sweepButton, &QPushButton::clicked, this,
            [this] { startTest(feetech::MotionTest::Kind::Sweep); });
    connect(m_stopButton, &QPushButton::clicked, this, [this] {
        m_stopRequested = true;
        m_test->cancel();
        m_stopRequested = false;
    });
    return m_testGroup;
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
    if (changed) {
        setStatus({}, Severity::Info);
        configureForServo();
        if (!m_test->isRunning())
            clearResults(); // after the new servo's From and To: the empty plot spans them
    } else {
        updateRanges();
        syncFromDevice();
        updateEnabled();
    }
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

    const bool damping = allowsDamping(table.find(kTorqueEnable));
    m_torqueDamping->setToolTip(
        damping ? tr("Damping: the horn can be turned by hand against a resistance (torque "
                     "enable 2).")
                : tr("%1 servos have no damping mode.").arg(feetech::familyName(table.family())));

    {
        const QSignalBlocker blocker(m_mode);
        m_mode->clear();
        if (const feetech::Register *mode = table.find(kMode)) {
            for (const feetech::Choice &choice : mode->choices)
                m_mode->addItem(choice.label, choice.value);
            m_modeNote->setText(tr("Stored in EEPROM: the servo keeps it when powered off."));
        } else {
            m_modeNote->setText(tr("%1 servos have no operating mode register: they hold "
                                   "positions.")
                                    .arg(feetech::familyName(table.family())));
        }
    }

    const feetech::Register *speed = table.find(kGoalSpeed);
    const feetech::Register *acceleration = table.find(kAcceleration);
    for (QSpinBox *spin : {m_speed, m_testSpeed})
        setRegisterRange(spin, speed, true);
    for (QSpinBox *spin : {m_acceleration, m_testAcceleration})
        setRegisterRange(spin, acceleration, true);
    m_speedUnit->setText(unitText(speed));
    m_accelerationUnit->setText(unitText(acceleration));
    m_testSpeed->setSuffix(speed ? QLatin1Char(' ') + unitText(speed) : QString());
    m_testAcceleration->setSuffix(acceleration ? QLatin1Char(' ') + unitText(acceleration)
                                               : QString());
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
    m_testSpeed->setValue(speedValue);
    m_acceleration->setValue(accelerationValue);
    m_testAcceleration->setValue(accelerationValue);

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
    for (QSpinBox *spin : {m_goal, m_from, m_to}) {
        if (spin->minimum() != range->minimum || spin->maximum() != range->maximum) {
            const QSignalBlocker blocker(spin);
            spin->setRange(range->minimum, range->maximum);
        }
    }
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
    QAbstractButton *checked = torque ? m_torqueButtons->button(int(*torque)) : nullptr;
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
    else if (*torque == kTorqueOff)
        m_torqueState->setText(tr("Off: the horn turns freely."));
    else if (*torque == kTorqueOn)
        m_torqueState->setText(tr("On: the servo holds its goal position."));
    else if (*torque == kTorqueDamping)
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
            const qint32 span = std::clamp((m_goal->maximum() - m_goal->minimum()) / 20,
                                           kMinimumTestSpan, kMaximumTestSpan);
            const qint32 from = std::max(m_goal->minimum(), here - span);
            m_from->setValue(from);
            m_to->setValue(std::min(m_goal->maximum(), from + 2 * span));
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
        if (!m_presentPosition && m_client->isMonitored(m_index)) {
            if (const auto sample = m_client->latestSample(m_index))
                m_presentPosition = sample->value(feetech::Quantity::Position);
        }
    }
    m_present->setText(m_presentPosition ? tr("%1 step").arg(std::lround(*m_presentPosition))
                                         : QStringLiteral("—"));
}

void ControlPage::refreshPresent()
{
    if (!isVisible() || !ready() || m_client->isMonitored(m_index) || m_client->isBusy())
        return;
    m_client->refreshRam(m_index);
}

void ControlPage::updateEnabled()
{
    const bool ok = ready();
    const bool running = m_test->isRunning();
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
    m_torqueDamping->setEnabled(torque && allowsDamping(table->find(kTorqueEnable)));

    const bool goal = has(kGoalPosition) && !here;
    for (QWidget *widget : {static_cast<QWidget *>(m_slider), static_cast<QWidget *>(m_goal),
                            static_cast<QWidget *>(m_move)})
        widget->setEnabled(goal);
    m_speed->setEnabled(goal && has(kGoalSpeed));
    m_acceleration->setEnabled(goal && has(kAcceleration));

    const bool mode = has(kMode) && !here;
    m_mode->setEnabled(mode);
    m_modeApply->setEnabled(mode && m_modeEdited && m_mode->currentIndex() >= 0);

    const bool canTest = has(kGoalPosition) && !running;
    for (QWidget *widget :
         {static_cast<QWidget *>(m_from), static_cast<QWidget *>(m_to),
          static_cast<QWidget *>(m_recordSeconds), static_cast<QWidget *>(m_legs),
          static_cast<QWidget *>(m_stepButton), static_cast<QWidget *>(m_sweepButton)})
        widget->setEnabled(canTest);
    m_testSpeed->setEnabled(canTest && has(kGoalSpeed));
    m_testAcceleration->setEnabled(canTest && has(kAcceleration));
    m_stopButton->setEnabled(running); // whichever servo is shown
}

// ---- writes

bool ControlPage::write(WriteKind kind, const QVector<model::WriteItem> &values)
{
    QString error;
    if (!m_client->writeValues(m_index, values, &error)) {
        setStatus(tr("%1: %2").arg(servoName(), error), Severity::Error);
        return false;
    }
    m_writes.push_back({kind, m_servo->first, m_servo->second});
    return true;
}

void ControlPage::setTorque(int value)
{
    if (!ready()) {
        syncFromDevice();
        return;
    }
    setStatus({}, Severity::Info);
    if (testRunsHere()) {
        // Switching torque under a running test would leave it measuring nonsense.
        m_stopRequested = true;
        m_test->cancel();
        m_stopRequested = false;
    }
    if (!write(WriteKind::Torque, {{kTorqueEnable, value}}))
        syncFromDevice(); // the buttons go back to what the servo has
}

void ControlPage::onSliderMoved(int value)
{
    {
        const QSignalBlocker blocker(m_goal);
        m_goal->setValue(value);
    }
    if (!ready() || testRunsHere())
        return;
    // One goal on the wire at a time; a newer one replaces whatever waits behind it.
    if (m_goalInFlight && m_goalSentAt.isValid() && m_goalSentAt.elapsed() < kGoalWriteStaleMs) {
        m_queuedGoal = value;
        return;
    }
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

    const feetech::RegisterTable &table = m_client->servo(m_index).info.table();
    QVector<model::WriteItem> values;
    if (table.find(kAcceleration))
        values.append({kAcceleration, m_acceleration->value()});
    if (table.find(kGoalSpeed))
        values.append({kGoalSpeed, m_speed->value()});
    values.append({kGoalPosition, position});
    if (!write(WriteKind::Goal, values)) {
        if (error)
            *error = statusText();
        return false;
    }
    const bool torqueWritePending =
        std::any_of(m_writes.begin(), m_writes.end(),
                    [](const PendingWrite &w) { return w.kind == WriteKind::Torque; });
    if (!torqueWritePending
        && m_client->parameters(m_index)->deviceValue(kTorqueEnable) == kTorqueOff)
        setStatus(tr("Torque is off: %1 keeps the goal but does not move until torque is on.")
                      .arg(servoName()),
                  Severity::Warning);
    else if (m_status->property("severity").toInt() == int(Severity::Error))
        setStatus({}, Severity::Info); // an earlier refusal no longer applies
    m_goalInFlight = true;
    m_goalSentAt.start();
    m_queuedGoal.reset(); // this one is newer than anything waiting
    {
        const QSignalBlocker spinBlocker(m_goal);
        const QSignalBlocker sliderBlocker(m_slider);
        m_goal->setValue(position);
        m_slider->setValue(position);
    }
    return true;
}

void ControlPage::changeMode()
{
    if (!ready() || m_mode->currentIndex() < 0)
        return;
    const qint64 value = m_mode->currentData().toLongLong();
    const auto device = m_client->parameters(m_index)->deviceValue(kMode);
    if (device && *device == value) {
        m_modeEdited = false;
        updateEnabled();
        return;
    }
    if (m_confirmMoves) {
        const int deviceIndex = device ? m_mode->findData(qint32(*device)) : -1;
        const QString from = deviceIndex >= 0 ? m_mode->itemText(deviceIndex) : tr("unknown");
        QMessageBox box(
            QMessageBox::Warning, tr("Change the operating mode?"),
            tr("%1 will change from “%2” to “%3”.").arg(servoName(), from, m_mode->currentText()),
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

void ControlPage::onOperationFinished(const feetech::OperationResult &result)
{
    if (result.operation != feetech::Operation::Write)
        return;
    const auto mine = std::find_if(m_writes.begin(), m_writes.end(), [&](const PendingWrite &w) {
        return w.id == result.servo.id && w.baud == result.servo.baud;
    });
    if (mine == m_writes.end())
        return; // someone else's write
    const WriteKind kind = mine->kind;
    m_writes.erase(mine);
    if (kind == WriteKind::Goal)
        m_goalInFlight = std::any_of(m_writes.begin(), m_writes.end(), [](const PendingWrite &w) {
            return w.kind == WriteKind::Goal;
        });
    if (kind == WriteKind::Mode)
        m_modeEdited = false;
    if (!result.ok) {
        if (kind == WriteKind::Goal)
            m_queuedGoal.reset(); // do not chase a failing servo with stale goals
        setStatus(tr("Writing to servo ID %1 failed: %2").arg(result.servo.id).arg(result.message),
                  Severity::Error);
    } else if (kind == WriteKind::Goal && m_queuedGoal && !m_goalInFlight) {
        // Queued for the servo shown: a change of servo clears the queue.
        const qint32 next = *m_queuedGoal;
        m_queuedGoal.reset();
        moveTo(next);
    }
    syncFromDevice();
    updateEnabled();
}

void ControlPage::onAllTorqueOff()
{
    m_queuedGoal.reset();
    if (ready())
        m_torqueOff->setChecked(true); // the read-back confirms it
    m_torqueState->setText(tr("Off: All torque off was sent to every servo."));
    setStatus(tr("All torque off: torque is off on every servo of the bus."), Severity::Warning);
}

// ---- tests

feetech::MotionPlan ControlPage::testPlan() const
{
    feetech::MotionPlan plan;
    plan.index = m_index;
    plan.from = m_from->value();
    plan.to = m_to->value();
    plan.goalSpeed = m_testSpeed->value();
    plan.acceleration = m_testAcceleration->value();
    plan.recordSeconds = m_recordSeconds->value();
    plan.legs = m_legs->value();
    return plan;
}

bool ControlPage::confirmTest(feetech::MotionTest::Kind kind, const feetech::MotionPlan &plan)
{
    const QString text = kind == feetech::MotionTest::Kind::Step
        ? tr("The horn of %1 will move to %2, then step to %3 and hold there.")
              .arg(servoName())
              .arg(plan.from)
              .arg(plan.to)
        : tr("The horn of %1 will move to %2, then sweep %3 times between %2 and %4.")
              .arg(servoName())
              .arg(plan.from)
              .arg(plan.legs)
              .arg(plan.to);
    QMessageBox box(QMessageBox::Warning, tr("The servo will move"), text,
                    QMessageBox::Ok | QMessageBox::Cancel, this);
    box.setInformativeText(tr("Keep hands, cables and other parts clear of the horn, and detach "
                              "any load it could damage or be damaged by. Stop or All torque off "
                              "halts it."));
    box.button(QMessageBox::Ok)->setText(tr("Move the servo"));
    box.setDefaultButton(QMessageBox::Cancel);
    return box.exec() == QMessageBox::Ok;
}

void ControlPage::startTest(feetech::MotionTest::Kind kind)
{
    const feetech::MotionPlan plan = testPlan();
    QString error;
    if (!m_test->validate(plan, kind, &error)) {
        setStatus(error, Severity::Error);
        return;
    }
    if (m_confirmMoves && !confirmTest(kind, plan))
        return;
    setStatus({}, Severity::Info);
    clearResults();
    const bool started = kind == feetech::MotionTest::Kind::Step ? m_test->startStep(plan, &error)
                                                                 : m_test->startSweep(plan, &error);
    if (!started)
        setStatus(error, Severity::Error);
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

void ControlPage::onStepFinished(const feetech::StepMetrics &metrics)
{
    showStepMetrics(metrics);
    plotRecording(metrics);
    m_testProgress->setText(tr("Step test done: %1 samples over %2 s.")
                                .arg(metrics.sampleCount)
                                .arg(QLocale().toString(m_test->plan().recordSeconds, 'g', 3)));
}

void ControlPage::onSweepFinished(const feetech::SweepSummary &summary)
{
    QString text = tr("Sweep done: %1 of %2 legs reached their goal.")
                       .arg(summary.reachedCount())
                       .arg(summary.legs.size());
    if (const auto mean = summary.meanReachedSeconds())
        text += QLatin1Char(' ')
            + tr("A leg took %1 ms on average.").arg(QLocale().toString(*mean * 1000.0, 'f', 0));
    m_testProgress->setText(text);
}

void ControlPage::onTestFailed(const QString &message)
{
    m_testProgress->setText(tr("Stopped: %1").arg(message));
    if (!m_stopRequested)
        setStatus(message, Severity::Error);
}

void ControlPage::clearResults()
{
    for (QLabel *label : {m_riseTime, m_overshoot, m_settlingTime, m_steadyStateError, m_band})
        label->setText(QStringLiteral("—"));
    m_response->clear();
    m_targetLine->clear();
    m_bandHigh->clear();
    m_bandLow->clear();
    // An empty plot already spans what a step test would show.
    m_timeAxis->setRange(0, m_recordSeconds->value() * 1000.0);
    m_timeAxis->applyNiceNumbers();
    const int low = std::min(m_from->value(), m_to->value());
    const int high = std::max(m_from->value(), m_to->value());
    const double margin = std::max(10.0, (high - low) * 0.05);
    m_positionAxis->setRange(low - margin, high + margin);
    m_positionAxis->applyNiceNumbers();
    m_testProgress->setText(m_test->isRunning() ? m_testProgress->text()
                                                : tr("No test run yet for this servo."));
}

void ControlPage::showStepMetrics(const feetech::StepMetrics &metrics)
{
    const QLocale locale;
    m_riseTime->setText(metrics.riseTime
                            ? tr("%1 ms").arg(locale.toString(*metrics.riseTime * 1000.0, 'f', 1))
                            : tr("did not reach 90 % of the step"));
    m_overshoot->setText(
        tr("%1 %").arg(locale.toString(metrics.overshootPercent.value_or(0.0), 'f', 1)));
    m_settlingTime->setText(
        metrics.settled && metrics.settlingTime
            ? tr("%1 ms").arg(locale.toString(*metrics.settlingTime * 1000.0, 'f', 1))
            : tr("did not settle within %1 s")
                  .arg(locale.toString(m_test->plan().recordSeconds, 'g', 3)));
    m_steadyStateError->setText(
        metrics.steadyStateError
            ? tr("%1 steps").arg(locale.toString(*metrics.steadyStateError, 'f', 1))
            : QStringLiteral("—"));
    m_band->setText(tr("± %1 steps").arg(locale.toString(metrics.band, 'f', 1)));
}

void ControlPage::plotRecording(const feetech::StepMetrics &metrics)
{
    const QVector<feetech::TimedValue> &recording = m_test->recording();
    QList<QPointF> points;
    points.reserve(recording.size());
    double low = std::min(metrics.start, metrics.target - metrics.band);
    double high = std::max(metrics.start, metrics.target + metrics.band);
    double first = 0.0;
    for (const feetech::TimedValue &sample : recording) {
        points.append({sample.seconds * 1000.0, sample.value});
        low = std::min(low, sample.value);
        high = std::max(high, sample.value);
        first = std::min(first, sample.seconds * 1000.0);
    }
    const double last =
        std::max(m_test->plan().recordSeconds * 1000.0, points.isEmpty() ? 0.0 : points.last().x());
    m_response->replace(points);
    const auto level = [first, last](double value) {
        return QList<QPointF> {{first, value}, {last, value}};
    };
    m_targetLine->replace(level(metrics.target));
    m_bandHigh->replace(level(metrics.target + metrics.band));
    m_bandLow->replace(level(metrics.target - metrics.band));
    // Time from the step command; the sample just before it only shapes the line's start.
    const double margin = std::max(1.0, (high - low) * 0.05);
    m_timeAxis->setRange(0.0, last);
    m_timeAxis->applyNiceNumbers();
    m_positionAxis->setRange(low - margin, high + margin);
    m_positionAxis->applyNiceNumbers();
    // A band thinner than the line itself would only blur the target line.
    const bool bandVisible =
        2.0 * metrics.band >= kMinimumVisibleBand * (m_positionAxis->max() - m_positionAxis->min());
    m_bandHigh->setVisible(bandVisible);
    m_bandLow->setVisible(bandVisible);
    for (QLegendMarker *marker : m_chartView->chart()->legend()->markers(m_bandHigh))
        marker->setVisible(bandVisible);
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
                         severityColor(isDark(palette()), severity == Severity::Error));
        m_status->setPalette(colours);
    }
    m_status->setVisible(!text.isEmpty());
}
