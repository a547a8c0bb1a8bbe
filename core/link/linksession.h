// The life of one serial link, shared by both servo families: port, request engine, state, reopen.
#pragma once

#include "linktypes.h"
#include "requestengine.h"

#include <QObject>
#include <QTimer>

#include <chrono>
#include <functional>

namespace seriallink {

class PortTransport;

// Owns the transport and the request engine of a device session and the connection state the
// user sees. A protocol session composes one and says, through two hooks, what ends when the
// link goes down and what starts again when it comes back; everything else about opening,
// closing, a port failing and reopening is the same for every family and lives here.
// Lives in the session's thread; driven only by signals and timers.
class LinkSession : public QObject
{
    Q_OBJECT

public:
    // Called before the port closes (the user closed it, or it failed): end whatever runs and
    // tell whoever waits for it, with `message` and the engine failure `failure`.
    using LinkDownHook = std::function<void(const QString &message, Failure failure)>;
    // Called once a lost port has been opened again; by default the link counts as Connected.
    using ReconnectedHook = std::function<void()>;

    LinkSession(const FrameFormat &format, RequestEngine::Describer describer,
                QObject *parent = nullptr);
    ~LinkSession() override;

    void setLinkDownHook(LinkDownHook hook) { m_linkDown = std::move(hook); }
    void setReconnectedHook(ReconnectedHook hook) { m_reconnected = std::move(hook); }
    // How often a port that went away is looked for again.
    void setReconnectInterval(std::chrono::milliseconds interval)
    {
        m_reconnectInterval = interval;
    }

    // A serial port, or the in-process transport of a port this program offers (the demo's
    // simulated servos): whichever opens the port last opened.
    PortTransport &transport() { return *m_transport; }
    const PortTransport &transport() const { return *m_transport; }
    RequestEngine &engine() { return *m_engine; }
    const RequestEngine &engine() const { return *m_engine; }
    const ConnectionStatus &status() const { return m_status; }
    const LinkCounters &counters() const { return m_engine->counters(); }
    bool isOpen() const;
    // Changes whenever the link ends or starts again: work begun under an older generation
    // belongs to a port that is gone and is ignored when its callbacks arrive.
    quint64 generation() const { return m_generation; }

    // Opens the port (state Connecting). False when it could not be opened: the state is then
    // Disconnected with the reason. A port already open is closed first.
    bool open(const QString &portName, qint32 baud, EchoMode echo);
    // Ends everything (the link-down hook), closes the port, and stops looking for a lost one.
    void close();
    void setState(ConnectionState state, const QString &message = {});
    // The port now runs at `baud` (a Feetech session follows servos across rates); false when
    // the port refuses it.
    bool setBaudRate(qint32 baud);
    // A line of the packet log that is no frame (a servo that stopped answering, say): it goes
    // wherever the link's frames go, so every view of the log shows it.
    void logNote(const QString &note, bool error = false);
    // A line of the packet log made elsewhere on this link (the frames another program sends
    // and hears on a shared bus): it goes wherever the link's own frames go.
    void logEntry(const PacketLogEntry &entry);

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void packetLogged(const seriallink::PacketLogEntry &entry);
    void countersChanged(const seriallink::LinkCounters &counters);

private:
    // A transport that can open `portName`, in place of the one there is if that one cannot.
    void useTransportFor(const QString &portName);
    void endLink(const QString &message, Failure failure);
    void onPortFailed(const QString &message, bool lost);
    void tryReopen();

    PortTransport *m_transport = nullptr;
    RequestEngine *m_engine = nullptr;
    QTimer *m_reopenTimer = nullptr;
    ConnectionStatus m_status;
    EchoMode m_echo = EchoMode::Auto;
    std::chrono::milliseconds m_reconnectInterval {500};
    quint64 m_generation = 0;
    LinkDownHook m_linkDown;
    ReconnectedHook m_reconnected;
};

} // namespace seriallink
