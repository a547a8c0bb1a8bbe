// Robot > Teleoperate…: a leader arm on a port of its own drives the arm on the window's bus,
// with both calibration files, a speed limit and a rate, Start and Stop, each joint's leader
// and follower side by side, and the loop's rate and latency.
#pragma once

#include "teleoperation.h"

#include <QDialog>

#include <functional>

class QComboBox;
class QGridLayout;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTimer;

namespace feetech {
class BusClient;
}

// Non-modal. Nothing here blocks: the leader's session runs in its own thread, the follower's
// writes go through the window's client. Stop, closing and a lost leader leave the follower
// holding where it stands.
class TeleopDialog : public QDialog
{
    Q_OBJECT

public:
    // The port name the simulated leader arm is listed under.
    static constexpr char kSimulatedLeader[] = "simulated:so101-leader";

    explicit TeleopDialog(feetech::BusClient *follower, QWidget *parent = nullptr);

    // When the window runs on simulated servos: `start` gives the simulated leader arm's port
    // (empty and *error when it cannot start), and the port list offers it. Empty: not offered.
    // `calibration` writes a LeRobot file that the simulated leader holds and gives its path
    // (empty and *error when it cannot): a run with the simulated leader and no leader's file
    // uses it, rather than refuse for a file the demo never had.
    void setSimulatedLeader(std::function<QString(QString *error)> start,
                            std::function<QString(QString *error)> calibration = {});

    feetech::Teleoperation *teleoperation() const { return m_teleop; }
    QComboBox *leaderPortBox() const { return m_leaderPort; }
    QLineEdit *followerFileEdit() const { return m_followerFile; }
    QLineEdit *leaderFileEdit() const { return m_leaderFile; }
    QSpinBox *maxSpeedBox() const { return m_maxSpeed; }
    QSpinBox *rateBox() const { return m_rate; }
    QComboBox *normModeBox() const { return m_normMode; }
    QPushButton *startButton() const { return m_start; }
    QPushButton *stopButton() const { return m_stopButton; }
    QLabel *statusLabel() const { return m_status; }
    QLabel *loopLabel() const { return m_loopFigures; }
    // Joint `joint`'s bars, in LeRobot's normalised units times ten.
    QProgressBar *leaderBar(int joint) const;
    QProgressBar *followerBar(int joint) const;

protected:
    void hideEvent(QHideEvent *event) override;

private:
    struct JointRow
    {
        QLabel *name = nullptr;
        QProgressBar *leader = nullptr;
        QProgressBar *follower = nullptr;
    };

    void refreshPorts();
    // The port the leader box names: an entry's port, or the path typed.
    QString chosenPort() const;
    void chooseFile(QLineEdit *edit, const QString &title);
    void start();
    void showJoints();
    void showPositions();
    void showLoopFigures();
    void onStateChanged(feetech::Teleoperation::State state);
    void onEnded(bool held);
    void showStatus(const QString &text, bool problem = false);

    feetech::BusClient *m_client = nullptr;
    feetech::Teleoperation *m_teleop = nullptr;
    std::function<QString(QString *error)> m_simulatedLeader;
    std::function<QString(QString *error)> m_simulatedLeaderCalibration;
    QComboBox *m_leaderPort = nullptr;
    QLineEdit *m_followerFile = nullptr;
    QLineEdit *m_leaderFile = nullptr;
    QSpinBox *m_maxSpeed = nullptr;
    QSpinBox *m_rate = nullptr;
    QComboBox *m_normMode = nullptr; // how joints map, as LeRobot names it
    QPushButton *m_start = nullptr;
    QPushButton *m_stopButton = nullptr;
    QGridLayout *m_jointGrid = nullptr;
    QVector<JointRow> m_rows;
    QLabel *m_loopFigures = nullptr;
    QLabel *m_status = nullptr;
    QTimer *m_figuresTimer = nullptr;
    QVector<QWidget *> m_inputs; // what a run takes as it was when started
};
