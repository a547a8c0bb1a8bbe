// The Health page of the Feetech workspace: the bus at a glance (one row per servo, its verdict
// and reasons), the check, the confirmed move test, the report saved as HTML or JSON, and the
// Settings section (the settings check and its fixes).
#pragma once

#include "healthreport.h"
#include "servohealth.h"

#include <QHash>
#include <QPair>
#include <QWidget>

#include <functional>

class QLabel;
class QProgressBar;
class QPushButton;
class QStackedWidget;
class QTableWidget;
class SettingsCheckPanel;

namespace feetech {
class JointNames;
class BusClient;
} // namespace feetech

class HealthPage : public QWidget
{
    Q_OBJECT

public:
    enum Column {
        IdColumn,
        ModelColumn,
        FirmwareColumn,
        VerdictColumn,
        ReasonsColumn,
        VoltageColumn,
        TemperatureColumn,
        LoadColumn,
        CommColumn,
        MoveColumn,
        ColumnCount
    };
    // Asked before a move test with what will move; true lets it run.
    using Confirmation = std::function<bool(const QString &question)>;

    explicit HealthPage(feetech::BusClient *client, QWidget *parent = nullptr);

    // Replaces the Yes/No box (tests answer for the user).
    void setConfirmation(Confirmation confirm) { m_confirm = std::move(confirm); }

    // Checks every servo found; false and *error (also shown on the page) when refused.
    bool check(QString *error = nullptr);
    void cancel();
    // The move test of the servo of the selected row, after the confirmation.
    bool moveTest(QString *error = nullptr);
    // Writes the report of the last check (HTML or JSON, by the suffix); false and *error,
    // also shown on the page, when it cannot be written.
    bool saveReport(const QString &path, QString *error = nullptr);
    void chooseReportFile();

    // The verdicts of the last check, in the table's order.
    QVector<feetech::ServoHealth> results() const;
    QTableWidget *table() const { return m_table; }
    QPushButton *checkButton() const { return m_check; }
    QPushButton *cancelButton() const { return m_cancel; }
    QPushButton *moveTestButton() const { return m_move; }
    QPushButton *saveButton() const { return m_save; }
    QProgressBar *progressBar() const { return m_progress; }
    QLabel *emptyState() const { return m_empty; }
    QLabel *stateLabel() const { return m_state; }
    SettingsCheckPanel *settingsPanel() const { return m_settings; }

signals:
    void problem(const QString &message);
    void message(const QString &message);

private:
    using Key = QPair<quint8, qint32>; // ID and baud
    void rebuildRows();
    // Drops the verdicts and what was said of them: the servos they spoke of are gone.
    void forgetResults();
    // The joints of the arm the servos match that the list lacks, said in a sentence; empty
    // when none is missing or the servos are no known arm.
    QString missingJoints() const;
    void reassess();
    void fillRow(int row, const feetech::ServoHealth &health, const feetech::JointNames &joints);
    void updateActions();
    void showState(const QString &text, bool error);
    int selectedServo() const; // client index of the selected row, -1 for none

    feetech::BusClient *m_client = nullptr;
    Confirmation m_confirm;
    QHash<Key, feetech::HealthReading> m_readings;
    QHash<Key, feetech::MoveTestResult> m_moves;
    QHash<Key, feetech::ServoHealth> m_health;
    QDateTime m_checkedAt;
    bool m_checking = false;
    bool m_moving = false;

    QStackedWidget *m_stack = nullptr;
    QLabel *m_empty = nullptr;
    QTableWidget *m_table = nullptr;
    QPushButton *m_check = nullptr;
    QPushButton *m_cancel = nullptr;
    QPushButton *m_move = nullptr;
    QPushButton *m_save = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_state = nullptr;
    SettingsCheckPanel *m_settings = nullptr;
};
