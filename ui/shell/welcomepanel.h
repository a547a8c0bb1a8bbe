// The page shown while nothing is connected: the serial ports with their USB descriptions, the
// simulated servos, and how to wire each servo family.
#pragma once

#include "serialports.h"

#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;
class QTimer;

class WelcomePanel : public QWidget
{
    Q_OBJECT

public:
    explicit WelcomePanel(QWidget *parent = nullptr);

    // Lists the system's serial ports again, USB adapters first (an adapter plugged in or
    // pulled out shows by itself: SerialPortWatcher).
    void refreshPorts();
    QTableWidget *portTable() const { return m_ports; }
    QPushButton *connectButton() const { return m_connect; }

    // The port the connection bar has chosen: its row is selected (none for a simulated one),
    // and Connect is offered exactly when the bar offers it, while a port is chosen.
    void showChosenPort(const QString &port);

signals:
    // A system port's path, or one of ConnectionBar's simulated port names.
    void connectRequested(const QString &port);
    // The user selected a port's row.
    void portChosen(const QString &port);

private:
    QWidget *createPortsBox();
    QWidget *createSimulatedBox();
    QWidget *createWiringBox();
    void connectSelected();
    void selectChosenRow();
    void showPorts(const QVector<SerialPort> &ports);

    QTableWidget *m_ports = nullptr;
    QLabel *m_noPorts = nullptr;
    QPushButton *m_connect = nullptr;
    QVector<SerialPort> m_listed; // the ports shown, to rebuild the table only when they change
    QString m_chosen;
};
