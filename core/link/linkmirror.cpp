// Link mirror: takes a worker's link news on the GUI thread and keeps the latest of each.
#include "linkmirror.h"

#include "linksession.h"

namespace seriallink {

LinkMirror::LinkMirror(QObject *parent)
    : QObject(parent)
{ }

void LinkMirror::follow(LinkSession *link)
{
    connect(link, &LinkSession::statusChanged, this, [this](const ConnectionStatus &status) {
        m_status = status;
        emit statusChanged(status);
    });
    connect(link, &LinkSession::countersChanged, this, [this](const LinkCounters &counters) {
        m_counters = counters;
        emit countersChanged(counters);
    });
    connect(link, &LinkSession::packetLogged, this, &LinkMirror::packetLogged);
}

} // namespace seriallink
