// Loading a LeRobot calibration file: the per-joint differences first, then verified writes
// once the user agrees.
#pragma once

#include "lerobotcalibration.h"

#include <QDialog>
#include <QStringList>
#include <QVector>

namespace feetech {
class BusClient;
}

class CalibrationSteps;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

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
