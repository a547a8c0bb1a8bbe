// Link > Share this bus…: the path another program opens, start and stop, watch, recording, and
// what passes (counters and alerts) while it shares.
#pragma once

#include <QDialog>

class QCheckBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace feetech {
class BusClient;
}

namespace share {
struct ShareAlert;
}

// Not modal: the window goes on working while the other program uses the bus. Everything goes
// through the client's ShareService; closing the dialog leaves the share running.
class ShareDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ShareDialog(feetech::BusClient *client, QWidget *parent = nullptr);

    QLineEdit *pathEdit() const { return m_path; }
    QLineEdit *recordEdit() const { return m_record; }
    QCheckBox *watchBox() const { return m_watch; }
    QPushButton *startStopButton() const { return m_startStop; }
    QPushButton *copyButton() const { return m_copy; }
    QLabel *stateLabel() const { return m_state; }
    QLabel *noteLabel() const { return m_note; }
    QLabel *countersLabel() const { return m_counters; }
    QListWidget *alertList() const { return m_alerts; }

private:
    void startOrStop();
    void copyPath();
    void chooseRecording();
    void showState();
    void showCounters();
    void addAlert(const share::ShareAlert &alert);
    void showProblem(const QString &text);

    feetech::BusClient *m_client;
    QLineEdit *m_path = nullptr;
    QPushButton *m_copy = nullptr;
    QLineEdit *m_record = nullptr;
    QPushButton *m_chooseRecord = nullptr;
    QCheckBox *m_watch = nullptr;
    QPushButton *m_startStop = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_note = nullptr; // the last thing that happened to the share (a rate set, the adapter)
    QLabel *m_counters = nullptr;
    QListWidget *m_alerts = nullptr;
};
