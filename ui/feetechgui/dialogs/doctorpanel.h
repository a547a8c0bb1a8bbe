// The Doctor panel: what is wrong with the Feetech bus, what to do, and the moves it offers.
#pragma once

#include "busdoctor.h"

#include <QDockWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTreeWidget;

namespace feetech {
class BusClient;
struct OperationResult;
} // namespace feetech

// Lists the doctor's findings (code, message, IDs), chooses what the bus should hold (the
// servos found the last time on the port, or a robot template), re-scans, and moves a servo
// found at an unexpected ID or rate through the guided ID and baud changes.
class DoctorPanel : public QDockWidget
{
    Q_OBJECT

public:
    explicit DoctorPanel(feetech::BusClient *client, QWidget *parent = nullptr);

    // What the bus on `port` should hold: the template chosen, else the servos found last
    // time on that port (none the first time).
    QVector<feetech::ExpectedServo> expected(const QString &port) const;

    void showChecking(const QString &port);
    void showFindings(const QString &port, const QVector<feetech::DoctorFinding> &findings);
    const QVector<feetech::DoctorFinding> &findings() const { return m_findings; }

    QTreeWidget *findingList() const { return m_list; }
    QPushButton *rescanButton() const { return m_rescan; }
    QPushButton *moveButton() const { return m_move; }
    QComboBox *expectationBox() const { return m_expectation; }
    // Moves the servo of the selected finding (after a confirmation): its new ID, then its
    // new rate, each verified by the guided flow; then asks for a re-scan.
    void moveSelected(bool confirm = true);

signals:
    void rescanRequested();
    void problem(const QString &message);
    void message(const QString &message);

private:
    void updateMove();
    void onOperationFinished(const feetech::OperationResult &result);
    void changeBaudIfAsked();

    feetech::BusClient *m_client = nullptr;
    QLabel *m_summary = nullptr;
    QComboBox *m_expectation = nullptr;
    QTreeWidget *m_list = nullptr;
    QPushButton *m_rescan = nullptr;
    QPushButton *m_move = nullptr;
    QVector<feetech::DoctorFinding> m_findings;
    std::optional<feetech::ServoMove> m_moving; // a move under way
};
