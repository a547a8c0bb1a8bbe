// The connection bar: port (refreshed on hot-plug), baud, protocol, echo and Connect/Disconnect.
#pragma once

#include "connectioncontroller.h"
#include "requestengine.h"
#include "serialports.h"

#include <QToolBar>

class QComboBox;
class QPushButton;
class QTimer;

class ConnectionBar : public QToolBar
{
    Q_OBJECT

public:
    // The port list's entries for the in-process simulated servos.
    static const QString kSimulatedPtkPort;
    static const QString kSimulatedFeetechPort;
    static const QString kSimulatedArmPort; // an SO-101 arm's six STS3215, set up

    // The bar offers what the connection controller connects with.
    using Protocol = ConnectionController::Protocol;

    explicit ConnectionBar(QWidget *parent = nullptr);

    QString port() const; // a system path, or kSimulatedPtkPort; empty: none chosen
    // The user's choice (the window's memory, the welcome page): kept while ports come and go.
    void setPort(const QString &port);
    // Connect is offered while a port is chosen; the welcome page's follows the same rule.
    bool canConnect() const { return !port().isEmpty(); }
    qint32 baud() const;
    void setBaud(qint32 baud);
    seriallink::EchoMode echoMode() const;
    Protocol protocol() const;
    void setProtocol(Protocol protocol); // also offers that protocol's usual baud rate
    // The baud rate and echo as a probe found them (Auto): shown, for the user to see.
    void showDetected(qint32 baud, seriallink::EchoMode echo);

    // Connected (or trying to be): the button offers Disconnect and the settings are locked.
    void setSessionActive(bool active);

    // Reads the system's ports again, keeping what the user selected or typed.
    void refreshPorts();

signals:
    void connectRequested();
    void disconnectRequested();
    void protocolChanged(ConnectionBar::Protocol protocol);
    // The port chosen changed (empty: none), by the user or as adapters came and went.
    void portChanged(const QString &port);

private:
    // The port list: the system's `ports` (USB adapters first), then the simulated buses.
    // Until the user chooses, the first USB adapter (else the first port, else none) is chosen.
    void showPorts(const QVector<SerialPort> &ports);
    // The system's ports as listed: shown when they changed.
    void takePorts(const QVector<SerialPort> &ports);
    // Selects `port` in the list, or types it when it is not listed.
    void selectPort(const QString &port);
    // Auto finds the rate and the echo itself: their boxes are for the explicit protocols.
    void updateEnabled();
    void onPortEdited();

    QComboBox *m_port = nullptr;
    QComboBox *m_baud = nullptr;
    QComboBox *m_protocol = nullptr;
    QComboBox *m_echo = nullptr;
    QPushButton *m_connect = nullptr;
    QVector<SerialPort> m_knownPorts;
    bool m_portsListed = false; // the system's ports were asked for at least once
    bool m_portChosen = false; // by the user or setPort: listings keep it
    QString m_lastPort; // as portChanged last said
    bool m_active = false;
};
