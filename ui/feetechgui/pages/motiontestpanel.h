// The step and sweep tests of the Control page: their settings, the warning before the servo
// moves, the step response metrics and plot.
#pragma once

#include "motiontest.h"

#include <QGroupBox>

class QChartView;
class QDoubleSpinBox;
class QLabel;
class QLineSeries;
class QPushButton;
class QSpinBox;
class RegisterSpinBox;
class QValueAxis;

namespace feetech {
struct Register;
}

// Runs feetech::MotionTest (owned by the page, which also needs to know when a test moves its
// servo) for the servo the page shows; errors go to the page's status line via statusChanged().
class MotionTestPanel : public QGroupBox
{
    Q_OBJECT

public:
    explicit MotionTestPanel(feetech::MotionTest *test, QWidget *parent = nullptr);

    // Whether a test asks first (a warning with Cancel as the default).
    void setConfirmMoves(bool confirm) { m_confirmMoves = confirm; }

    // The servo the tests move, as BusClient numbers them, and how messages name it.
    void setServo(int index, const QString &name);
    // For a servo just shown: its speed and acceleration registers (null where it has none)
    // and the values the tests start with.
    void configure(const feetech::Register *speed, const feetech::Register *acceleration,
                   int speedValue, int accelerationValue);
    // The goal positions the servo may be sent.
    void setPositionRange(int minimum, int maximum);
    // From and To a small move around `here`, within minimum..maximum.
    void proposeAround(int here, int minimum, int maximum);
    // What the servo shown has: without a goal position register there is nothing to test.
    void updateEnabled(bool hasGoal, bool hasSpeed, bool hasAcceleration);

    void clearResults();
    // Ends a running test as Stop does: the servo holds where it is, and no error is reported.
    void stop();

signals:
    // For the page's status line; an empty text clears it.
    void statusChanged(const QString &text, bool isError);

private:
    // The sweep's positions over time, between its two ends.
    void plotSweep();
    void clearPlot();
    void buildSettings();
    void buildResults();
    void buildChart();

    feetech::MotionPlan testPlan() const;
    bool confirmTest(feetech::MotionTest::Kind kind, const feetech::MotionPlan &plan);
    void startTest(feetech::MotionTest::Kind kind);
    void onStepFinished(const feetech::StepMetrics &metrics);
    void onSweepFinished(const feetech::SweepSummary &summary);
    void onTestFailed(const QString &message);
    void showStepMetrics(const feetech::StepMetrics &metrics);
    void plotRecording(const feetech::StepMetrics &metrics);

    feetech::MotionTest *m_test = nullptr;
    int m_index = -1;
    QString m_servoName;
    bool m_confirmMoves = true;
    bool m_stopRequested = false; // the test ends because the user pressed Stop

    QSpinBox *m_from = nullptr;
    QSpinBox *m_to = nullptr;
    RegisterSpinBox *m_testSpeed = nullptr;
    RegisterSpinBox *m_testAcceleration = nullptr;
    QDoubleSpinBox *m_recordSeconds = nullptr;
    QSpinBox *m_legs = nullptr;
    QPushButton *m_stepButton = nullptr;
    QPushButton *m_sweepButton = nullptr;
    QPushButton *m_stopButton = nullptr;
    QLabel *m_testProgress = nullptr;
    QLabel *m_riseTime = nullptr;
    QLabel *m_overshoot = nullptr;
    QLabel *m_settlingTime = nullptr;
    QLabel *m_steadyStateError = nullptr;
    QLabel *m_band = nullptr;
    QChartView *m_chartView = nullptr;
    QLineSeries *m_response = nullptr;
    QLineSeries *m_targetLine = nullptr;
    QLineSeries *m_bandHigh = nullptr;
    QLineSeries *m_bandLow = nullptr;
    QValueAxis *m_timeAxis = nullptr;
    QValueAxis *m_positionAxis = nullptr;
};
