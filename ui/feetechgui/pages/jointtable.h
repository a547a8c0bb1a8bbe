// The joint table: every servo of the bus in one row with its live position, a target and its
// torque state; all targets moved at once, and poses saved and loaded.
#pragma once

#include "goalrange.h"
#include "pose.h"
#include "tablefacts.h"

#include <QSet>
#include <QVector>
#include <QWidget>

#include <optional>

class QLabel;
class QPushButton;
class QTableWidget;
class QTableWidgetItem;

namespace feetech {
class BusClient;
struct FeedbackSample;
struct OperationResult;
} // namespace feetech

class JointTable : public QWidget
{
    Q_OBJECT

public:
    enum Column {
        IdColumn,
        ModelColumn,
        BaudColumn,
        PositionColumn,
        TargetColumn,
        RangeColumn,
        TorqueColumn,
        MovingColumn,
        IdentifyColumn, // a button: wiggle the servo to see which one it is
        ColumnCount
    };

    // How a loaded pose met the servos on the bus.
    struct PoseMatch
    {
        QString name;
        int filled = 0; // rows whose target the pose set
        QVector<feetech::PoseEntry> notOnBus; // entries for servos the table does not have
        QVector<int> rowsWithoutEntry; // rows the pose says nothing about (targets unchanged)
        QVector<int> rowsOutOfRange; // rows filled with a target outside their range
    };

    explicit JointTable(feetech::BusClient *client, QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }
    int rowCount() const { return int(m_rows.size()); }
    int rowOf(quint8 id, qint32 baud) const; // -1 when the servo has no row
    int servoIndex(int row) const; // the BusClient's index of the row's servo, -1 when gone

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

    // The rows' targets as a pose file (rows without a target are left out).
    bool savePose(const QString &path, QString *error = nullptr);
    // Fills the targets of the rows the pose names (by ID and baud rate): nothing moves. The
    // match says which entries and rows did not meet; nothing and *error when the file is
    // not a valid pose (no target changed then).
    std::optional<PoseMatch> loadPose(const QString &path, QString *error = nullptr);

    QString message() const; // the status line under the table

protected:
    // Opening the tab reads every servo: positions, torque and angle limits are then the
    // servos' own, not placeholders.
    void showEvent(QShowEvent *event) override;

private:
    // Torque enable values, all in one place.

    struct Row
    {
        quint8 id = 0;
        qint32 baud = 0;
        std::optional<qint32> target;
        std::optional<feetech::TorqueMode> torqueRequested; // written, not yet read back
        // Which of the two sources of a position is newer when the monitor does not watch
        // the servo: its last telemetry sample or the model's last read.
        qint64 modelReadMs = 0;
        bool sampleNewer = false;
    };
    enum class Tone { Info, Success, Warning, Error };

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
    void onTorqueWritten(quint8 id, qint32 baud, const feetech::OperationResult &result);
    void onItemChanged(QTableWidgetItem *item);
    void setMessage(const QString &text, Tone tone);
    QString servoName(int row) const; // "ID 3 (SCS15)"
    std::optional<qint64> deviceValue(int row, const QString &key) const;
    // The sample the row's position and motion come from, when it is the newer source.
    std::optional<feetech::FeedbackSample> sampleSource(int row) const;
    std::optional<bool> moving(int row) const;

    void onMoveAllClicked();
    void onCaptureClicked();
    void onReadClicked();
    void onSaveClicked();
    void onLoadClicked();

    feetech::BusClient *m_client = nullptr;
    QVector<Row> m_rows;
    QSet<quint64> m_readAsked; // servos (servoKey) read by readWhileShown since the tab opened
    QTableWidget *m_table = nullptr;
    QLabel *m_hint = nullptr;
    QLabel *m_poseLabel = nullptr;
    QLabel *m_message = nullptr;
    QPushButton *m_read = nullptr;
    QPushButton *m_capture = nullptr;
    QPushButton *m_save = nullptr;
    QPushButton *m_load = nullptr;
    QPushButton *m_moveAll = nullptr;
    QString m_poseName;
    int m_movesInFlight = 0; // SYNC WRITEs sent by Move all whose outcome has not come yet
    bool m_updating = false; // the table is being filled by code, not edited by the user
};
