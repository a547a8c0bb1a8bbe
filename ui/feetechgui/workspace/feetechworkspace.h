// The Feetech workspace: servo tree, per-servo pages, the operations on the servo shown.
#pragma once

#include "feetechsession.h"

#include <QWidget>

#include <optional>

class ControlPage;
class HealthPage;
class JointTable;
class MemoryTablePage;
class MonitorPage;
class ParameterPage;
class QLabel;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTimer;
class RobotActions;
class ServoTree;
class UnlockedNotice;

namespace feetech {
class BusClient;
class ServoCommands;
class Refusal;
class OperationReply;
} // namespace feetech

class FeetechWorkspace : public QWidget
{
    Q_OBJECT

public:
    explicit FeetechWorkspace(feetech::BusClient *client, QWidget *parent = nullptr);

    // The servo the pages show (-1: none).
    int currentIndex() const;
    void selectServo(const feetech::ServoAddress &servo);
    void setPortName(const QString &name); // the tree's top item

    void openScanDialog();
    void startScan(const feetech::ScanOptions &options);
    const feetech::ScanOptions &scanOptions() const { return m_scanOptions; } // of the last scan
    void apply(); // with a confirmation when the ID or baud rate would change
    void chooseProfileToSave();
    void chooseProfileToLoad();
    bool saveProfile(const QString &path, bool withEdits = true);
    void loadProfile(const QString &path);

    ServoTree *servoTree() const { return m_tree; }
    ParameterPage *settingsPage() const { return m_settings; }
    MemoryTablePage *memoryPage() const { return m_memory; }
    QTabWidget *tabs() const { return m_tabs; }
    MonitorPage *monitorPage() const { return m_monitor; }
    ControlPage *controlPage() const { return m_control; }
    JointTable *jointTable() const { return m_joints; }
    HealthPage *healthPage() const { return m_health; }
    QPushButton *allTorqueOffButton() const { return m_allTorqueOff; }
    RobotActions *robotActions() const { return m_robot; }
    UnlockedNotice *unlockedNotice() const { return m_unlocked; }

signals:
    void problem(const QString &message);
    void message(const QString &message);

private:
    // The scan's line: what the last scan found while it holds, else what to do next.
    void showScanHint();
    void rebuildTree();
    void showChosenServo(const feetech::ServoAddress &servo);
    void showServo();
    void readIfNew();
    void updateHeader();
    void updateActions();
    void onOperationFinished(const feetech::OperationResult &result);
    // Whether an operation writes a servo and reads back what it wrote: its success is a
    // verified change, which the page keeps saying until the next one.
    static bool changesServo(feetech::Operation operation);
    void refreshLive();
    void changeId();
    void changeBaud();
    void calibrateMiddle();
    void factoryReset();
    void run(feetech::OperationReply *(feetech::ServoCommands::*operation)(int, feetech::Refusal *),
             const QString &what);
    QString servoTitle() const;

    feetech::BusClient *m_client = nullptr;
    feetech::ScanOptions m_scanOptions;
    std::optional<feetech::ServoAddress> m_current; // the servo shown

    ServoTree *m_tree = nullptr;
    QPushButton *m_allTorqueOff = nullptr;
    MonitorPage *m_monitor = nullptr;
    ControlPage *m_control = nullptr;
    JointTable *m_joints = nullptr;
    HealthPage *m_health = nullptr;
    QPushButton *m_scan = nullptr;
    QPushButton *m_cancelScan = nullptr;
    QProgressBar *m_scanProgress = nullptr;
    QLabel *m_scanState = nullptr;
    QString m_scanOutcome; // what the last scan found, while its servos are listed and reachable

    QLabel *m_header = nullptr;
    QLabel *m_verified = nullptr; // the last verified change of the servo shown
    feetech::ServoAddress m_verifiedServo; // the servo it speaks of, as reached after it
    UnlockedNotice *m_unlocked = nullptr;
    QPushButton *m_changeId = nullptr;
    QPushButton *m_changeBaud = nullptr;
    QPushButton *m_calibrate = nullptr;
    QPushButton *m_factoryReset = nullptr;
    QPushButton *m_reboot = nullptr;
    QPushButton *m_clearStatus = nullptr;
    QTabWidget *m_tabs = nullptr;
    ParameterPage *m_settings = nullptr;

    MemoryTablePage *m_memory = nullptr;
    QTimer *m_liveTimer = nullptr;
    RobotActions *m_robot = nullptr;
};
