// The Control page of the Feetech workspace: torque, goal position and operating mode of the
// servo selected in the tree, beside the motion-test panel.
#pragma once

#include "bustypes.h"
#include "motiontest.h"
#include "servocontrolgroups.h"

#include <QPointer>
#include <QWidget>

#include <optional>

class GuardBanner;
class MotionTestPanel;
class QLabel;
class QTimer;

namespace feetech {
class BusClient;
class GoalStreamer;
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
    void setConfirmMoves(bool confirm);
    bool confirmMoves() const { return m_confirmMoves; }

    feetech::MotionTest *motionTest() const { return m_test; }
    void setMotionTiming(const feetech::MotionTiming &timing);

    // Sends goal `position` (steps) with the speed and acceleration shown, as Move does. False
    // and *error (also shown in the status line) when it is refused: nothing is sent.
    bool moveTo(qint32 position, QString *error = nullptr);

    QString statusText() const; // the status line: the last error or notice
    // The guard's banner: what the guard last said about the servo shown.
    GuardBanner *guardBanner() const { return m_guardBanner; }

private:
    enum class WriteKind { Torque, Goal, Mode };
    enum class Severity { Info, Warning, Error };

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
    std::optional<feetech::ServoAddress> m_servo; // the servo shown
    bool m_confirmMoves = true;

    // Goal writes from the slider: one in flight, only the newest value waits behind it.
    feetech::GoalStreamer *m_goals = nullptr;
    int m_torqueWritesInFlight = 0;
    bool m_goalInitialised = false; // the goal spin has been set from the servo once
    bool m_modeEdited = false; // the combo shows the user's choice, not the device's
    std::optional<double> m_presentPosition; // the newest, from telemetry or a register read
    qint64 m_presentReadMs = 0; // the register read m_presentPosition last took in

    QLabel *m_hint = nullptr;
    GuardBanner *m_guardBanner = nullptr;
    QWidget *m_body = nullptr;
    ServoControlGroups m_controls;
    MotionTestPanel *m_testPanel = nullptr;
    QLabel *m_status = nullptr;
    QTimer *m_refreshTimer = nullptr;
};
