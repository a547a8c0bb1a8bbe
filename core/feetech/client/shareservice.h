// The GUI thread's side of sharing the bus with another program: start and stop it, its state,
// its counters and alerts, and the servos and feedback the program's traffic shows.
#pragma once

#include "busgate.h"
#include "busshare.h"
#include "refusal.h"
#include "sharealerts.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <QVector>

#include <chrono>

namespace feetech {

class BusClient;

// Belongs to a BusClient (BusClient::share()). The share runs in the link thread
// (Session::share()); this asks it to start and stop through queued calls and never waits for
// the bus. What the program's traffic shows goes where the bus's own does: its frames to the
// packet log (by the session), the servos it talks to into the servo list, and its reads of the
// feedback block to the telemetry hub's subscribers (TelemetryHub), with no reads of ours.
class ShareService : public QObject
{
    Q_OBJECT

public:
    enum class State {
        Off,
        Starting, // asked for; the session has not answered yet
        Sharing,
    };
    // How often the counters are fetched from the link thread while sharing.
    static constexpr std::chrono::milliseconds kCountersInterval {250};

    explicit ShareService(BusClient *client);

    // Where the other program is pointed unless the user says otherwise.
    static QString defaultLinkPath();

    // Asks the session to share the bus as `options` say; startFailed or stateChanged(Sharing)
    // tells how it went. False and *refusal, nothing asked, when the bus is not connected, the
    // share runs already or no path is given.
    bool start(const share::ShareOptions &options, Refusal *refusal = nullptr);
    void stop();
    // Whether the watch reads the program's servos in its idle gaps (off unless asked).
    void setWatch(bool enabled);
    bool isWatching() const { return m_watch; }

    State state() const { return m_state; }
    // Starting or sharing: what would get in the program's way is refused meanwhile.
    bool isActive() const { return m_state != State::Off; }
    QString linkPath() const { return m_linkPath; }
    QString terminalPath() const { return m_terminalPath; }
    QString recordPath() const { return m_recordPath; }
    // The rate the port runs at (the program may set another one on its side).
    qint32 portBaud() const { return m_portBaud; }
    const share::ShareCounters &counters() const { return m_counters; }
    qint64 watchReads() const { return m_watchReads; }
    // Every alert raised since sharing began, oldest first.
    const QVector<share::ShareAlert> &alerts() const { return m_alerts; }

signals:
    void stateChanged(feetech::ShareService::State state);
    void startFailed(const QString &why);
    void countersChanged();
    // An alert was added to alerts().
    void alertRaised(const share::ShareAlert &alert);
    // Something happened to the share: a rate the program set, the adapter lost or back.
    void noted(const QString &text);

private:
    void setState(State state);
    void onStartAnswered(const QString &why, const QString &linkPath, const QString &terminalPath,
                         qint32 baud);
    void onServoSeen(const ServoInfo &servo);
    void fetchCounters();

    BusClient *m_client;
    State m_state = State::Off;
    QString m_linkPath;
    QString m_terminalPath;
    QString m_recordPath;
    qint32 m_portBaud = 0;
    bool m_watch = false;
    share::ShareCounters m_counters;
    qint64 m_watchReads = 0;
    QVector<share::ShareAlert> m_alerts;
    QTimer m_countersTimer;
};

} // namespace feetech
