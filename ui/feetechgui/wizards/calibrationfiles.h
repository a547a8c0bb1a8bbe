// Saving the scanned servos' calibration to a LeRobot file, and loading one: the per-joint
// differences first, then verified writes once the user agrees.
#pragma once

#include "lerobotcalibration.h"

#include <QDialog>
#include <QObject>
#include <QVector>

namespace feetech {
class BusClient;
}

class CalibrationSteps;
class QLabel;
class QMenu;
class QAction;
class QProgressBar;
class QPushButton;
class QTableWidget;

// Reads the offsets and limits of the scanned servos that have them (named by the default robot
// template where their IDs match it) and saves them as a LeRobot file.
class CalibrationSaver : public QObject
{
    Q_OBJECT

public:
    explicit CalibrationSaver(feetech::BusClient *client, QObject *parent = nullptr);
    // False and *error (NothingToSave) when nothing was started (no servo to save).
    bool save(const QString &path, util::FileError *error);

signals:
    void finished(bool ok, const QString &message);

private:
    feetech::BusClient *m_client = nullptr;
    CalibrationSteps *m_steps = nullptr;
    QString m_path;
    QString m_failure; // the first servo that could not be read
    QVector<int> m_indexes;
    QStringList m_names;
};

// Shows what a LeRobot file would change on each joint, then writes it (locked, verified).
class LoadCalibrationDialog : public QDialog
{
    Q_OBJECT

public:
    LoadCalibrationDialog(feetech::BusClient *client, const QVector<feetech::LeRobotMotor> &motors,
                          const QString &path, QWidget *parent = nullptr);

    // The rows are filled once every servo of the file has been read.
    bool isReady() const { return m_ready; }
    int changedJoints() const { return int(m_writeRows.size()); }
    void writeChanges(); // what Write does

signals:
    void ready();
    void writingFinished(bool allOk);

private:
    void onRead(bool allOk);
    void setStatus(int row, const QString &text, bool problem);

    feetech::BusClient *m_client = nullptr;
    CalibrationSteps *m_steps = nullptr;
    QVector<feetech::LeRobotMotor> m_motors;
    QVector<int> m_indexes; // per motor: the client's index, -1 when not on the bus
    QVector<int> m_readRows; // the row of each read step
    QStringList m_readFailures; // per row: why its servo could not be read, empty when it was
    QVector<int> m_writeRows; // the rows with changes that may be written
    bool m_ready = false;
    bool m_writing = false;
    QTableWidget *m_table = nullptr;
    QLabel *m_summary = nullptr;
    QProgressBar *m_progress = nullptr;
    QPushButton *m_write = nullptr;
    QPushButton *m_close = nullptr;
};

// The Robot menu's calibration entries: Calibrate arm…, Save calibration…, Load calibration…,
// enabled while a Feetech bus is connected and its scan found servos.
class CalibrationActions : public QObject
{
    Q_OBJECT

public:
    CalibrationActions(QMenu *menu, feetech::BusClient *client, QWidget *window);

    QAction *calibrateAction() const { return m_calibrate; }
    QAction *saveAction() const { return m_save; }
    QAction *loadAction() const { return m_load; }

signals:
    void message(const QString &text);
    void problem(const QString &text);

private:
    void updateEnabled();
    void saveCalibration();
    void loadCalibration();

    feetech::BusClient *m_client = nullptr;
    QWidget *m_window = nullptr;
    QAction *m_calibrate = nullptr;
    QAction *m_save = nullptr;
    QAction *m_load = nullptr;
};
