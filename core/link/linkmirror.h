// The GUI thread's copy of a link's state and counters, with its packet log passed on.
#pragma once

#include "linktypes.h"

#include <QObject>

namespace seriallink {

class LinkSession;

// Both clients keep one: the main window, the status bar and the packet log wire to it the
// same way whichever family is connected. The client that owns it connects first, so it has
// settled its own state before anyone else hears of a change.
class LinkMirror : public QObject
{
    Q_OBJECT

public:
    explicit LinkMirror(QObject *parent = nullptr);

    // Follows `link`, which lives in a session's worker thread (queued connections).
    void follow(LinkSession *link);

    const ConnectionStatus &status() const { return m_status; }
    const LinkCounters &counters() const { return m_counters; }
    bool isConnected() const { return m_status.state == ConnectionState::Connected; }

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void countersChanged(const seriallink::LinkCounters &counters);
    void packetLogged(const seriallink::PacketLogEntry &entry);

private:
    ConnectionStatus m_status;
    LinkCounters m_counters;
};

} // namespace seriallink
