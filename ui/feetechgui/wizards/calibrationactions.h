// The Robot menu's calibration entries: the calibration wizard, saving and loading LeRobot files.
#pragma once

#include <QObject>

namespace feetech {
class BusClient;
}

class QAction;
class QMenu;
class QWidget;

// Calibrate arm…, Save calibration…, Load calibration…: enabled while a Feetech bus is connected
// and its scan found servos.
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
