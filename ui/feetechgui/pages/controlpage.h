// The Control page of the Feetech workspace: torque, goal position and operating mode of the
// servo selected in the tree, beside the motion-test panel.
#pragma once

#include "motiontest.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QWidget>

#include <deque>
#include <optional>

class MotionTestPanel;
class QButtonGroup;
class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;

namespace feetech {
class BusClient;
struct FeedbackSample;
struct GuardEvent;
struct OperationResult;
struct Register;
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
    void setConfirmMoves(bool confirm);
    bool confirmMoves() const { return m_confirmMoves; }

    feetech::MotionTest *motionTest() const { return m_test; }
    void setMotionTiming(const feetech::MotionTiming &timing);

    // Sends goal `position` (steps) with the speed and acceleration shown, as Move does. False
    // and *error (also shown in the status line) when it is refused: nothing is sent.
    bool moveTo(qint32 position, QString *error = nullptr);

    QString statusText() const; // the status line: the last error or notice
    // The guard's banner: what the guard last said about the servo shown (empty: nothing).
    QString guardText() const;

private:
    // Torque enable values, all in one place.

    enum class WriteKind { Torque, Goal, Mode };
    enum class Severity { Info, Warning, Error };

    QGroupBox *buildTorqueGroup();
    QGroupBox *buildModeGroup();
    QGroupBox *buildGoalGroup();
    // The guard's banner and its actions (controlpageguard.cpp).
    QWidget *buildGuardBanner();
    void onGuardEvent(const feetech::GuardEvent &event);
    void showGuard(); // the banner for the servo shown
    void openGuardSettings();
    void openRecovery();

    void onServosChanged();
    void onServoUpdated(int index);
    void onTelemetry(const QVector<feetech::FeedbackSample> &samples);
    void onWriteFinished(WriteKind kind, quint8 id, const feetech::OperationResult &result);
    void onAllTorqueOff();
    void onTestRunning(bool running);

    void configureForServo(); // ranges, choices and defaults of the servo shown
    void updateRanges();
    void syncFromDevice();
    void updatePresent();
    void updateEnabled();
    void refreshPresent();

    void setTorque(int modeId); // a feetech::TorqueMode, the id of the button pressed
    void onSliderMoved(int value);
    void changeMode();
    bool write(WriteKind kind, const QVector<model::WriteItem> &values);

    void setStatus(const QString &text, Severity severity);

    static int toInt(qint64 value); // clamped
    // Damping (torque enable 2) only where the table says the servo knows it.
    static bool allowsDamping(const feetech::RegisterTable &table);

    bool ready() const; // connected, a servo with a known table
    bool testRunsHere() const; // a test moves the servo shown
    QString servoName() const;

    QPointer<feetech::BusClient> m_client; // the main window may delete it before its pages
    feetech::MotionTest *m_test = nullptr;
    int m_index = -1;
    std::optional<std::pair<quint8, qint32>> m_servo; // ID and baud of the servo shown
    bool m_confirmMoves = true;

    // Goal writes from the slider: one in flight, only the newest value waits behind it.
    int m_goalsInFlight = 0;
    int m_torqueWritesInFlight = 0;
    QElapsedTimer m_goalSentAt;
    std::optional<qint32> m_queuedGoal;
    bool m_goalInitialised = false; // the goal spin has been set from the servo once
    bool m_modeEdited = false; // the combo shows the user's choice, not the device's
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

    MotionTestPanel *m_testPanel = nullptr;

    QWidget *m_guardBanner = nullptr;
    QLabel *m_guardText = nullptr;
    QPushButton *m_guardRecover = nullptr;
    QPushButton *m_guardSettings = nullptr;

    QLabel *m_status = nullptr;
    QTimer *m_refreshTimer = nullptr;
};
