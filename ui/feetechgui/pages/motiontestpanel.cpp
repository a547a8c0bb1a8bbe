// The motion-test panel: step and sweep settings, the warning before a test moves the servo,
// and the step response as numbers and as a plot.
#include "motiontestpanel.h"

#include "palette.h"
#include "registerspinbox.h"
#include "registertable.h"
#include "registerwidgets.h"
#include "widgethelpers.h"

#include <QChart>
#include <QChartView>
#include <QDoubleSpinBox>
#include <QFrame>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <iterator>

using registerwidgets::registerSpinBox;
using registerwidgets::spinBox;
using registerwidgets::valueLabel;
using widgethelpers::actionButton;

namespace {

// Test defaults: a small move around where the horn is, at a gentle speed.
constexpr qint32 kMinimumTestSpan = 20; // steps each side
constexpr qint32 kMaximumTestSpan = 400;
constexpr int kDefaultLegs = 4;
constexpr double kDefaultRecordSeconds = 2.0;
constexpr double kMinimumRecordSeconds = 0.2;
constexpr int kChartMinimumHeight = 210;
constexpr double kMinimumVisibleBand = 0.05; // of the position axis

} // namespace

MotionTestPanel::MotionTestPanel(feetech::MotionTest *test, QWidget *parent)
    : QGroupBox(tr("Step and sweep tests"), parent)
    , m_test(test)
{
    setObjectName(QStringLiteral("testGroup"));
    auto *layout = new QVBoxLayout(this);
    layout->setSpacing(8);

    // What to run: three rows of two settings.
    auto *settings = new QGridLayout;
    settings->setHorizontalSpacing(10);
    m_from = spinBox("testFromSpinBox", this);
    m_from->setSuffix(registerwidgets::stepSuffix());
    m_to = spinBox("testToSpinBox", this);
    m_to->setSuffix(registerwidgets::stepSuffix());
    m_testSpeed = registerSpinBox("testSpeedSpinBox", this);
    m_testSpeed->setToolTip(tr("Goal speed of the test moves (0: the servo's maximum)."));
    m_testAcceleration = registerSpinBox("testAccelerationSpinBox", this);
    m_testAcceleration->setToolTip(tr("Acceleration of the test moves (0: the servo's maximum)."));
    m_recordSeconds = new QDoubleSpinBox(this);
    m_recordSeconds->setObjectName(QStringLiteral("recordSecondsSpinBox"));
    m_recordSeconds->setAlignment(Qt::AlignRight);
    m_recordSeconds->setRange(kMinimumRecordSeconds, feetech::MotionPlan::kMaximumRecordSeconds);
    m_recordSeconds->setDecimals(1);
    m_recordSeconds->setSingleStep(0.5);
    m_recordSeconds->setSuffix(tr(" s"));
    m_recordSeconds->setValue(kDefaultRecordSeconds);
    m_recordSeconds->setToolTip(tr("Step test: how long the response is recorded after the step."));
    m_legs = spinBox("sweepLegsSpinBox", this);
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
        settings->addWidget(new QLabel(cells[i].first, this), row, column);
        settings->addWidget(cells[i].second, row, column + 1);
    }
    settings->setColumnStretch(4, 1); // the fields keep their size; the room goes after them
    layout->addLayout(settings);

    auto *buttons = new QHBoxLayout;
    m_stepButton =
        actionButton(tr("Step test…"), "stepTestButton",
                     tr("Move to From, then step to To and measure the response."), this);
    m_sweepButton = actionButton(tr("Sweep…"), "sweepButton",
                                 tr("Move back and forth between From and To."), this);
    m_stopButton = actionButton(tr("Stop"), "stopTestButton",
                                tr("Stop the running test; the servo holds where it is."), this);
    buttons->addWidget(m_stepButton);
    buttons->addWidget(m_sweepButton);
    buttons->addWidget(m_stopButton);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    m_testProgress = new QLabel(this);
    m_testProgress->setObjectName(QStringLiteral("testProgressLabel"));
    m_testProgress->setWordWrap(true);
    layout->addWidget(m_testProgress);
    for (RegisterSpinBox *box : {m_testSpeed, m_testAcceleration})
        connect(box, &RegisterSpinBox::snapped, m_testProgress, &QLabel::setText);

    // The step response, as numbers and as a plot.
    auto *line = new QFrame(this);
    line->setFrameShape(QFrame::HLine);
    line->setFrameShadow(QFrame::Sunken);
    layout->addWidget(line);
    auto *metrics = new QGridLayout;
    metrics->setHorizontalSpacing(10);
    m_riseTime = valueLabel("riseTimeLabel", this);
    m_riseTime->setToolTip(tr("From 10 % to 90 % of the step."));
    m_overshoot = valueLabel("overshootLabel", this);
    m_overshoot->setToolTip(tr("How far the peak went beyond the target, as a share of the step."));
    m_settlingTime = valueLabel("settlingTimeLabel", this);
    m_settlingTime->setToolTip(
        tr("From the step command until the position stays within the settling band."));
    m_steadyStateError = valueLabel("steadyStateErrorLabel", this);
    m_steadyStateError->setToolTip(
        tr("Target minus the mean position over the last tenth of the recording."));
    m_band = valueLabel("settlingBandLabel", this);
    m_band->setToolTip(tr("2 % of the step, at least 2 steps, either side of the target."));
    const std::pair<QString, QLabel *> results[] = {{tr("Rise time"), m_riseTime},
                                                    {tr("Overshoot"), m_overshoot},
                                                    {tr("Settling time"), m_settlingTime},
                                                    {tr("Steady-state error"), m_steadyStateError},
                                                    {tr("Settling band"), m_band}};
    for (int i = 0; i < int(std::size(results)); ++i) {
        const int row = i / 2;
        const int column = (i % 2) * 2;
        auto *label = new QLabel(results[i].first, this);
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
    if (palette::isDark(palette()))
        chart->setTheme(QChart::ChartThemeDark);
    chart->setMargins(QMargins(2, 2, 2, 2));
    chart->setBackgroundRoundness(0);
    chart->legend()->setAlignment(Qt::AlignTop);
    QFont small = chart->legend()->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    chart->legend()->setFont(small);
    m_response = new QLineSeries(chart);
    m_response->setName(tr("Position (%1)").arg(feetech::unitText(QStringLiteral("step"))));
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
    m_chartView = new QChartView(chart, this);
    m_chartView->setObjectName(QStringLiteral("stepChart"));
    m_chartView->setRenderHint(QPainter::Antialiasing);
    m_chartView->setMinimumHeight(kChartMinimumHeight);
    layout->addWidget(m_chartView, 1);

    connect(m_stepButton, &QPushButton::clicked, this,
            [this] { startTest(feetech::MotionTest::Kind::Step); });
    connect(m_sweepButton, &QPushButton::clicked, this,
            [this] { startTest(feetech::MotionTest::Kind::Sweep); });
    connect(m_stopButton, &QPushButton::clicked, this, &MotionTestPanel::stop);

    connect(m_test, &feetech::MotionTest::progress, m_testProgress, &QLabel::setText);
    connect(m_test, &feetech::MotionTest::stepFinished, this, &MotionTestPanel::onStepFinished);
    connect(m_test, &feetech::MotionTest::sweepFinished, this, &MotionTestPanel::onSweepFinished);
    connect(m_test, &feetech::MotionTest::failed, this, &MotionTestPanel::onTestFailed);
}

// ---- the servo shown

void MotionTestPanel::setServo(int index, const QString &name)
{
    m_index = index;
    m_servoName = name;
}

void MotionTestPanel::configure(const feetech::Register *speed,
                                const feetech::Register *acceleration, int speedValue,
                                int accelerationValue)
{
    m_testSpeed->setRegister(speed, true);
    m_testAcceleration->setRegister(acceleration, true);
    m_testSpeed->setValue(speedValue);
    m_testAcceleration->setValue(accelerationValue);
}

void MotionTestPanel::setPositionRange(int minimum, int maximum)
{
    for (QSpinBox *spin : {m_from, m_to}) {
        if (spin->minimum() != minimum || spin->maximum() != maximum) {
            const QSignalBlocker blocker(spin);
            spin->setRange(minimum, maximum);
        }
    }
}

void MotionTestPanel::proposeAround(int here, int minimum, int maximum)
{
    const qint32 span = std::clamp((maximum - minimum) / 20, kMinimumTestSpan, kMaximumTestSpan);
    const qint32 from = std::max(minimum, here - span);
    m_from->setValue(from);
    m_to->setValue(std::min(maximum, from + 2 * span));
}

void MotionTestPanel::updateEnabled(bool hasGoal, bool hasSpeed, bool hasAcceleration)
{
    const bool running = m_test->isRunning();
    const bool canTest = hasGoal && !running;
    for (QWidget *widget :
         {static_cast<QWidget *>(m_from), static_cast<QWidget *>(m_to),
          static_cast<QWidget *>(m_recordSeconds), static_cast<QWidget *>(m_legs),
          static_cast<QWidget *>(m_stepButton), static_cast<QWidget *>(m_sweepButton)})
        widget->setEnabled(canTest);
    m_testSpeed->setEnabled(canTest && hasSpeed);
    m_testAcceleration->setEnabled(canTest && hasAcceleration);
    m_stopButton->setEnabled(running); // whichever servo is shown
}

void MotionTestPanel::stop()
{
    m_stopRequested = true;
    m_test->cancel();
    m_stopRequested = false;
}

// ---- tests

feetech::MotionPlan MotionTestPanel::testPlan() const
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

bool MotionTestPanel::confirmTest(feetech::MotionTest::Kind kind, const feetech::MotionPlan &plan)
{
    const QString text = kind == feetech::MotionTest::Kind::Step
        ? tr("The horn of %1 will move to %2, then step to %3 and hold there.")
              .arg(m_servoName)
              .arg(plan.from)
              .arg(plan.to)
        : tr("The horn of %1 will move to %2, then sweep %3 times between %2 and %4.")
              .arg(m_servoName)
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

void MotionTestPanel::startTest(feetech::MotionTest::Kind kind)
{
    const feetech::MotionPlan plan = testPlan();
    feetech::MotionTestRefusal refusal;
    if (!m_test->validate(plan, kind, &refusal)) {
        emit statusChanged(refusal.describe(), true);
        return;
    }
    if (m_confirmMoves && !confirmTest(kind, plan))
        return;
    emit statusChanged({}, false);
    // A sweep has its own line on the plot; the step test's numbers stay until the next step.
    if (kind == feetech::MotionTest::Kind::Step)
        clearResults();
    else
        clearPlot();
    const bool started = kind == feetech::MotionTest::Kind::Step
        ? m_test->startStep(plan, &refusal)
        : m_test->startSweep(plan, &refusal);
    if (!started)
        emit statusChanged(refusal.describe(), true);
}

void MotionTestPanel::onStepFinished(const feetech::StepMetrics &metrics)
{
    showStepMetrics(metrics);
    plotRecording(metrics);
    m_testProgress->setText(tr("Step test done: %1 samples over %2 s.")
                                .arg(metrics.sampleCount)
                                .arg(QLocale().toString(m_test->plan().recordSeconds, 'g', 3)));
}

void MotionTestPanel::onSweepFinished(const feetech::SweepSummary &summary)
{
    QString text = tr("Sweep done: %1 of %2 legs reached their goal.")
                       .arg(summary.reachedCount())
                       .arg(summary.legs.size());
    if (const auto mean = summary.meanReachedSeconds())
        text += QLatin1Char(' ')
            + tr("A leg took %1 ms on average.").arg(QLocale().toString(*mean * 1000.0, 'f', 0));
    m_testProgress->setText(text);
    plotSweep();
}

void MotionTestPanel::plotSweep()
{
    const QVector<feetech::TimedValue> &recording = m_test->recording();
    QList<QPointF> points;
    points.reserve(recording.size());
    const feetech::MotionPlan &plan = m_test->plan();
    double low = std::min(plan.from, plan.to);
    double high = std::max(plan.from, plan.to);
    for (const feetech::TimedValue &sample : recording) {
        points.append({sample.seconds * 1000.0, sample.value});
        low = std::min(low, sample.value);
        high = std::max(high, sample.value);
    }
    const double last = points.isEmpty() ? 1000.0 : std::max(1.0, points.last().x());
    m_response->replace(points);
    // The two ends it sweeps between, where a step test shows its target and band.
    m_bandHigh->setName(tr("Sweep ends"));
    m_targetLine->clear();
    m_bandHigh->replace({{0.0, double(plan.to)}, {last, double(plan.to)}});
    m_bandLow->replace({{0.0, double(plan.from)}, {last, double(plan.from)}});
    const double margin = std::max(1.0, (high - low) * 0.05);
    m_timeAxis->setRange(0.0, last);
    m_timeAxis->applyNiceNumbers();
    m_positionAxis->setRange(low - margin, high + margin);
    m_positionAxis->applyNiceNumbers();
}

void MotionTestPanel::clearPlot()
{
    m_response->clear();
    m_targetLine->clear();
    m_bandHigh->clear();
    m_bandLow->clear();
}

void MotionTestPanel::onTestFailed(const QString &message)
{
    m_testProgress->setText(tr("Stopped: %1").arg(message));
    if (!m_stopRequested)
        emit statusChanged(message, true);
}

void MotionTestPanel::clearResults()
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

void MotionTestPanel::showStepMetrics(const feetech::StepMetrics &metrics)
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

void MotionTestPanel::plotRecording(const feetech::StepMetrics &metrics)
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
    m_bandHigh->setName(tr("Settling band"));
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
