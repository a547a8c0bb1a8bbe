// The joint table: every servo of the bus in one row with its live position, a target and its
// torque state; all targets moved at once, torque switched, servos read and identified.
#pragma once

#include "bustypes.h"
#include "goalrange.h"
#include "posematch.h"
#include "tablefacts.h"

#include <QSet>
#include <QVector>
#include <QWidget>

#include <optional>

class JointTablePoses;
class JointTableView;
class QLabel;
class QPushButton;

namespace feetech {
class BusClient;
struct FeedbackSample;
struct OperationResult;
} // namespace feetech

class JointTable : public QWidget
{
    Q_OBJECT

public:
    enum class Tone { Info, Success, Warning, Error };

    explicit JointTable(feetech::BusClient *client, QWidget *parent = nullptr);

    JointTableView *table() const { return m_table; }
    // Saving the targets as a pose file, and filling them from one.
    JointTablePoses *poses() const { return m_poses; }
    int rowCount() const { return int(m_rows.size()); }
    int rowOf(const feetech::ServoAddress &servo) const; // -1 when the servo has no row
    int servoIndex(int row) const; // the BusClient's index of the row's servo, -1 when gone
    QString servoName(int row) const; // "ID 3 (SCS15)"
    // Every row's servo with its target and the range it may be sent.
    QVector<feetech::JointTarget> joints() const;

    // The row's present position: the monitor's latest sample while it watches the servo,
    // else the last value read (nothing before the first read).
    std::optional<qint32> position(int row) const;
    bool isPositionLive(int row) const;
    // Where the row's servo may be sent (feetech::goalRange); nothing for a servo of unknown
    // model, which cannot be moved.
    std::optional<feetech::PositionRange> targetRange(int row) const;

    // Targets are kept as set, even out of range: such a target is shown in red and Move all
    // refuses it, saying why.
    void setTarget(int row, qint32 target);
    std::optional<qint32> target(int row) const; // nothing until one is set
    // Copies the present positions into the targets; returns how many rows got one.
    int capturePositions();

    // One SYNC WRITE of every row's target per baud rate. Nothing is sent, false and *error
    // say why, when the bus is not connected, a row has no target, a target is out of range or
    // a servo is not in position mode.
    bool moveAll(QString *error = nullptr);
    // Torque enable 1 or 0 through a control write (read back into the model).
    bool setTorque(int row, bool on, QString *error = nullptr);
    // Asks every servo for its registers, so positions, limits and torque are current.
    bool readPositions(QString *error = nullptr);
    // Identifies the row's servo (BusClient::identifyJoint): a slow wiggle, then everything
    // restored. The row's button is disabled, its tooltip saying why, when it cannot be.
    bool identify(int row, QString *error = nullptr);
    QPushButton *identifyButton(int row) const;

    QString message() const; // the status line under the table
    void setMessage(const QString &text, Tone tone);

protected:
    // Opening the tab reads every servo: positions, torque and angle limits are then the
    // servos' own, not placeholders.
    void showEvent(QShowEvent *event) override;

private:
    struct Row
    {
        feetech::ServoAddress servo;
        std::optional<qint32> target;
        std::optional<feetech::TorqueMode> torqueRequested; // written, not yet read back
        // Which of the two sources of a position is newer when the monitor does not watch
        // the servo: its last telemetry sample or the model's last read.
        qint64 modelReadMs = 0;
        bool sampleNewer = false;
    };

    void rebuild();
    // Reads the rows' servos while the table is on screen: every one (`all`), or those never
    // read and not asked yet. Nothing is written, nothing moves.
    void readWhileShown(bool all);
    void refreshRow(int row);
    void refreshPosition(int row);
    void refreshTarget(int row);
    void refreshHint();
    void refreshButtons();
    void refreshIdentifyButtons();
    void onTelemetry(const QVector<feetech::FeedbackSample> &samples);
    void onMoveFinished(const feetech::OperationResult &result);
    void onTorqueWritten(const feetech::ServoAddress &servo,
                         const feetech::OperationResult &result);
    void onTorqueToggled(int row, bool on);
    std::optional<qint64> deviceValue(int row, const QString &key) const;
    // The sample the row's position and motion come from, when it is the newer source.
    std::optional<feetech::FeedbackSample> sampleSource(int row) const;
    std::optional<bool> moving(int row) const;

    void onMoveAllClicked();
    void onCaptureClicked();
    void onReadClicked();

    feetech::BusClient *m_client = nullptr;
    QVector<Row> m_rows;
    QSet<feetech::ServoAddress> m_readAsked; // read by readWhileShown since the tab opened
    JointTableView *m_table = nullptr;
    JointTablePoses *m_poses = nullptr;
    QLabel *m_hint = nullptr;
    QLabel *m_message = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_capture = nullptr;
    QPushButton *m_moveAll = nullptr;
    int m_movesInFlight = 0; // SYNC WRITEs sent by Move all whose outcome has not come yet
};
