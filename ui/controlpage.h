// The Control page of the Feetech workspace: torque, goal position, operating mode, and the step
// and sweep tests with their response metrics, for the servo selected in the tree.
#pragma once

#include "feetech/motiontest.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QWidget>

#include <deque>
#include <optional>

class QButtonGroup;
class QChartView;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QLineSeries;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;
class QValueAxis;

namespace feetech {
class BusClient;
struct FeedbackSample;
struct OperationResult;
} // namespace feetech

class ControlPage : public QWidget
{
    Q_OBJECT

public:
    explicit ControlPage(feetech::BusClient *client, QWidget *parent = nullptr);
    ~ControlPage() override;

    // The servo the page controls, as BusClient numbers them; -1: none (all disabled, a hint).
    void setServo(int index);
    int servo() const { return m_index; }

    // Whether the tests and mode changes ask first (a warning with Cancel as the default).
    // On by default; tests switch it off.
    void setConfirmMoves(bool confirm) { m_confirmMoves = confirm; }
    bool confirmMoves() const { return m_confirmMoves; }

    feetech::MotionTest *motionTest() const { return m_test; }
    void setMotionTiming(const feetech::MotionTiming &timing);

    // Sends goal `position` (steps) with the speed and acceleration shown, as Move does. False
    // and *error (also shown in the status line) when it is refused: nothing is sent.
    bool moveTo(qint32 position, QString *error = nullptr);

    QString statusText() const; // the status line: the last error or notice

private:
    enum class WriteKind { Torque, Goal, Mode };
    enum class Severity { Info, Warning, Error };
    struct PendingWrite
    {
        WriteKind kind = WriteKind::Goal;
        quint8 id = 0;
        qint32 baud = 0;
    };

    QGroupBox *buildTorqueGroup();
    QGroupBox *buildModeGroup();
    QGroupBox *buildGoalGroup();
    QGroupBox *buildTestGroup();

    void onServosChanged();
    void onServoUpdated(int index);
    void onTelemetry(const QVector<feetech::FeedbackSample> &samples);
    void onOperationFinished(const feetech::OperationResult &result);
    void onAllTorqueOff();
    void onTestRunning(bool running);
    void onStepFinished(const feetech::StepMetrics &metrics);
    void onSweepFinished(const feetech::SweepSummary &summary);
    void onTestFailed(const QString &message);

    void configureForServo(); // ranges, choices and defaults of the servo shown
    void updateRanges();
    void syncFromDevice();
    void updatePresent();
    void updateEnabled();
    void refreshPresent();

    void setTorque(int value);
    void onSliderMoved(int value);
    void changeMode();
    void startTest(feetech::MotionTest::Kind kind);
    feetech::MotionPlan testPlan() const;
    bool confirmTest(feetech::MotionTest::Kind kind, const feetech::MotionPlan &plan);
    bool write(WriteKind kind, const QVector<model::WriteItem> &values);

    void clearResults();
    void showStepMetrics(const feetech::StepMetrics &metrics);
    void plotRecording(const feetech::StepMetrics &metrics);
    void setStatus(const QString &text, Severity severity);

    bool ready() const; // connected, a servo with a known table
    bool testRunsHere() const; // a test moves the servo shown
    QString servoName() const;

    QPointer<feetech::BusClient> m_client; // the main window may delete it before its pages
    feetech::MotionTest *m_test = nullptr;
    int m_index = -1;
    std::optional<std::pair<quint8, qint32>> m_servo; // ID and baud of the servo shown
    bool m_confirmMoves = true;

    // Goal writes from the slider: one in flight, only the newest value waits behind it.
    std::deque<PendingWrite> m_writes;
    bool m_goalInFlight = false;
    QElapsedTimer m_goalSentAt;
    std::optional<qint32> m_queuedGoal;
    bool m_goalInitialised = false; // the goal spin has been set from the servo once
    bool m_modeEdited = false; // the combo shows the user's choice, not the device's
    bool m_stopRequested = false; // the test ends because the user pressed Stop
    std::optional<double> m_presentPosition; // the newest, from telemetry or a register read
    qint64 m_presentReadMs = 0; // the register read m_presentPosition last took in

    QLabel *m_hint = nullptr;
    QWidget *m_body = nullptr;

    QGroupBox *m_torqueGroup = nullptr;
    QButtonGroup *m_torqueButtons = nullptr;
    QPushButton *m_torqueOff = nullptr;
    QPushButton *m_torqueOn = nullptr;
    QPushButton *m_torqueDamping = nullptr;
    QLabel *m_torqueState = nullptr;

    QGroupBox *m_modeGroup = nullptr;
    QComboBox *m_mode = nullptr;
    QPushButton *m_modeApply = nullptr;
    QLabel *m_modeNote = nullptr;

    QGroupBox *m_goalGroup = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_sliderMinimum = nullptr;
    QLabel *m_sliderMaximum = nullptr;
    QSpinBox *m_goal = nullptr;
    QPushButton *m_move = nullptr;
    QLabel *m_present = nullptr;
    QLabel *m_rangeNote = nullptr;
    QSpinBox *m_speed = nullptr;
    QLabel *m_speedUnit = nullptr;
    QSpinBox *m_acceleration = nullptr;
    QLabel *m_accelerationUnit = nullptr;

    QGroupBox *m_testGroup = nullptr;
    QSpinBox *m_from = nullptr;
    QSpinBox *m_to = nullptr;
    QSpinBox *m_testSpeed = nullptr;
    QSpinBox *m_testAcceleration = nullptr;
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

    QLabel *m_status = nullptr;
    QTimer *m_refreshTimer = nullptr;
};
