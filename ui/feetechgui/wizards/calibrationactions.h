// The Robot menu's calibration entries: the calibration wizard, saving and loading LeRobot files.
#pragma once

#include <QObject>
#include <QPointer>

namespace feetech {
class BusClient;
}

class CalibrationWizard;
class QAction;
class QDialog;
class QMenu;
class QWidget;

// Calibrate arm…, Save calibration…, Load calibration…: enabled while a Feetech bus is connected
// and its scan found servos. The wizard is modeless (the Simulator dock turns the demo's joints
// while it records), one at a time, and not beside a motor set-up, which changes IDs.
class CalibrationActions : public QObject
{
    Q_OBJECT

public:
    CalibrationActions(QMenu *menu, feetech::BusClient *client, QWidget *window);

    QAction *calibrateAction() const { return m_calibrate; }
    QAction *saveAction() const { return m_save; }
    QAction *loadAction() const { return m_load; }
    // Opens the wizard, or brings the open one forward; refused (problem) beside a motor set-up.
    void openWizard();

signals:
    void message(const QString &text);
    void problem(const QString &text);
    // The wizard is about to be shown.
    void wizardOpening(QDialog *wizard);

private:
    void updateEnabled();
    void saveCalibration();
    void loadCalibration();

    feetech::BusClient *m_client = nullptr;
    QWidget *m_window = nullptr;
    QPointer<CalibrationWizard> m_wizard;
    QAction *m_calibrate = nullptr;
    QAction *m_save = nullptr;
    QAction *m_load = nullptr;
};
