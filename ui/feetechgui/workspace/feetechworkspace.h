// The Feetech workspace: servo tree, per-servo Settings and Memory table pages, guided flows.
#pragma once

#include "feetechsession.h"

#include <QWidget>

#include <optional>

class ControlPage;
class HealthPage;
class JointTable;
class MonitorPage;
class ParameterPage;
class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSortFilterProxyModel;
class QTabWidget;
class QTableView;
class QTimer;
class QTreeWidget;
class RegisterTableModel;
class RobotActions;
class UnlockedNotice;

namespace feetech {
class BusClient;
class OperationReply;
} // namespace feetech

class FeetechWorkspace : public QWidget
{
    Q_OBJECT

public:
    explicit FeetechWorkspace(feetech::BusClient *client, QWidget *parent = nullptr);

    // The servo the pages show (-1: none).
    int currentIndex() const;
    // The servos selected in the tree (BusClient numbering, tree order); several with
    // Ctrl+click or Shift+click.
    QVector<int> selectedServos() const;
    void selectServo(quint8 id, qint32 baud);
    void setPortName(const QString &name); // the tree's top item

    void openScanDialog();
    void startScan(const feetech::ScanOptions &options);
    const feetech::ScanOptions &scanOptions() const { return m_scanOptions; } // of the last scan
    void apply(); // with a confirmation when the ID or baud rate would change
    void chooseProfileToSave();
    void chooseProfileToLoad();
    bool saveProfile(const QString &path, bool withEdits = true);
    void loadProfile(const QString &path);

    QTreeWidget *servoTree() const { return m_tree; }
    ParameterPage *settingsPage() const { return m_settings; }
    QTableView *memoryTable() const { return m_table; }
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
    void rebuildTree();
    void onSelectionChanged();
    void showServo();
    void readIfNew();
    void updateHeader();
    void updateActions();
    void onOperationFinished(const feetech::OperationResult &result);
    void refreshLive();
    void changeId();
    void changeBaud();
    void calibrateMiddle();
    void factoryReset();
    void run(feetech::OperationReply *(feetech::BusClient::*operation)(int, QString *),
             const QString &what);
    QString servoTitle() const;

    feetech::BusClient *m_client = nullptr;
    feetech::ScanOptions m_scanOptions;
    std::optional<std::pair<quint8, qint32>> m_current; // ID and baud of the servo shown
    QString m_portName;

    QTreeWidget *m_tree = nullptr;
    QPushButton *m_allTorqueOff = nullptr;
    MonitorPage *m_monitor = nullptr;
    ControlPage *m_control = nullptr;
    JointTable *m_joints = nullptr;
    HealthPage *m_health = nullptr;
    QPushButton *m_scan = nullptr;
    QPushButton *m_cancelScan = nullptr;
    QProgressBar *m_scanProgress = nullptr;
    QLabel *m_scanState = nullptr;

    QLabel *m_header = nullptr;
    QLabel *m_memoryEmpty = nullptr; // the Memory table page's hint while no servo is chosen
    UnlockedNotice *m_unlocked = nullptr;
    QPushButton *m_changeId = nullptr;
    QPushButton *m_changeBaud = nullptr;
    QPushButton *m_calibrate = nullptr;
    QPushButton *m_factoryReset = nullptr;
    QPushButton *m_reboot = nullptr;
    QPushButton *m_clearStatus = nullptr;
    QTabWidget *m_tabs = nullptr;
    ParameterPage *m_settings = nullptr;

    RegisterTableModel *m_registers = nullptr;
    QSortFilterProxyModel *m_filter = nullptr;
    QTableView *m_table = nullptr;
    QLineEdit *m_filterEdit = nullptr;
    QCheckBox *m_live = nullptr;
    QPushButton *m_tableRead = nullptr;
    QPushButton *m_tableRevert = nullptr;
    QPushButton *m_tableApply = nullptr;
    QTimer *m_liveTimer = nullptr;
    RobotActions *m_robot = nullptr;
};
