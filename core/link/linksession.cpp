// Link session: opening, closing, a failing port and reopening it, for both servo families.
#include "linksession.h"

#include "inprocessport.h"
#include "inprocesstransport.h"
#include "serialtransport.h"

#include <QCoreApplication>
#include <QDateTime>

namespace {

struct LinkSessionTr
{
    Q_DECLARE_TR_FUNCTIONS(LinkSession)
};

} // namespace

namespace seriallink {

LinkSession::LinkSession(const FrameFormat &format, RequestEngine::Describer describer,
                         QObject *parent)
    : QObject(parent)
    , m_transport(new SerialTransport(this))
    , m_engine(new RequestEngine(*m_transport, format, std::move(describer), this))
    , m_reopenTimer(new QTimer(this))
{
    qRegisterMetaType<seriallink::ConnectionStatus>();
    qRegisterMetaType<seriallink::PacketLogEntry>();
    qRegisterMetaType<seriallink::LinkCounters>();
    connect(m_engine, &RequestEngine::packetLogged, this, &LinkSession::packetLogged);
    connect(m_engine, &RequestEngine::countersChanged, this, &LinkSession::countersChanged);
    // Queued: a port error can be raised inside a call the engine is making to the port.
    connect(m_transport, &Transport::failed, this, &LinkSession::onPortFailed,
            Qt::QueuedConnection);
    connect(m_reopenTimer, &QTimer::timeout, this, &LinkSession::tryReopen);
}

LinkSession::~LinkSession()
{
    // The owner's hooks may already be gone: the owner closes the link in its own destructor.
    m_linkDown = nullptr;
    m_reconnected = nullptr;
    m_reopenTimer->stop();
    m_engine->cancelAll(Failure::Cancelled);
    m_transport->close();
}

bool LinkSession::isOpen() const
{
    return m_transport->isOpen();
}

bool LinkSession::open(const QString &portName, qint32 baud, EchoMode echo)
{
    close();
    m_status.portName = portName;
    m_status.baud = baud;
    m_echo = echo;
    ++m_generation;
    useTransportFor(portName);
    setState(ConnectionState::Connecting);
    QString error;
    if (!m_transport->open(portName, baud, &error)) {
        setState(ConnectionState::Disconnected, error);
        return false;
    }
    m_engine->resetCounters();
    emit countersChanged(m_engine->counters()); // the status bar starts this port from zero
    m_engine->setEchoMode(echo);
    return true;
}

void LinkSession::close()
{
    m_reopenTimer->stop();
    endLink(LinkSessionTr::tr("Disconnected."), Failure::Cancelled);
    if (m_status.state != ConnectionState::Disconnected)
        setState(ConnectionState::Disconnected);
}

void LinkSession::setState(ConnectionState state, const QString &message)
{
    m_status.state = state;
    m_status.message = message;
    emit statusChanged(m_status);
}

bool LinkSession::setBaudRate(qint32 baud)
{
    if (m_transport->baudRate() == baud)
        return true;
    if (!m_transport->setBaudRate(baud))
        return false;
    m_status.baud = baud;
    return true;
}

void LinkSession::logNote(const QString &note, bool error)
{
    PacketLogEntry entry;
    entry.timestampMs = QDateTime::currentMSecsSinceEpoch();
    entry.direction = Direction::In;
    if (error)
        entry.error = note;
    else
        entry.summary = note;
    emit packetLogged(entry);
}

void LinkSession::logEntry(const PacketLogEntry &entry)
{
    emit packetLogged(entry);
}

void LinkSession::useTransportFor(const QString &portName)
{
    const bool inProcess = InProcessPort::isKnown(portName);
    if (inProcess == (qobject_cast<InProcessTransport *>(m_transport) != nullptr))
        return;
    // Closed by now, and the engine talks to the transport itself (a share ends before this).
    PortTransport *fresh = PortTransport::forPort(portName, this);
    m_engine->setTransport(*fresh);
    delete m_transport;
    m_transport = fresh;
    connect(m_transport, &Transport::failed, this, &LinkSession::onPortFailed,
            Qt::QueuedConnection);
}

void LinkSession::endLink(const QString &message, Failure failure)
{
    ++m_generation;
    if (m_linkDown)
        m_linkDown(message, failure);
    m_engine->cancelAll(failure);
    m_transport->close();
}

void LinkSession::onPortFailed(const QString &message, bool lost)
{
    // Queued: by now the user may have closed the port, or it was already handled.
    if (!m_transport->isOpen()
        && (m_status.state == ConnectionState::Disconnected
            || m_status.state == ConnectionState::Lost))
        return;
    endLink(message, Failure::LinkDown);
    if (lost) {
        setState(ConnectionState::Lost,
                 LinkSessionTr::tr("%1 Reconnecting when it comes back.").arg(message));
        m_reopenTimer->start(m_reconnectInterval);
    } else {
        setState(ConnectionState::Disconnected, message);
    }
}

void LinkSession::tryReopen()
{
    if (!m_transport->open(m_status.portName, m_status.baud, nullptr))
        return; // still gone; the timer tries again
    m_reopenTimer->stop();
    ++m_generation;
    // The port may now be behind another adapter: echo is decided afresh.
    m_engine->setEchoMode(m_echo);
    if (m_reconnected)
        m_reconnected();
    else
        setState(ConnectionState::Connected);
}

} // namespace seriallink
