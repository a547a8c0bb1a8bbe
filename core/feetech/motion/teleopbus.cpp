// One arm's bus for teleoperation: the window's client or an own session, operations in turn.
#include "teleopbus.h"

#include "operationreply.h"

#include <algorithm>

namespace feetech {

TeleopBus::TeleopBus(BusClient *client, QObject *parent)
    : QObject(parent)
    , m_client(client)
    , m_portName(client->link()->status().portName)
{
    connect(client->session(), &Session::memoryRead, this,
            [this](quint8 id, qint32, int address, const QByteArray &bytes) {
                onMemoryRead(id, address, bytes);
            });
}

TeleopBus::TeleopBus(const QString &portName, qint32 baud, QObject *parent)
    : QObject(parent)
    , m_own(std::make_unique<seriallink::SessionThread<Session>>(QStringLiteral("teleop leader")))
    , m_portName(portName)
    , m_baud(baud)
{
    connect(m_own->session(), &Session::memoryRead, this,
            [this](quint8 id, qint32, int address, const QByteArray &bytes) {
                onMemoryRead(id, address, bytes);
            });
    // Only this object submits to its own session: its results come in the order asked.
    connect(m_own->session(), &Session::operationFinished, this,
            [this](const OperationResult &result) {
                if (result.final)
                    finish(nullptr, result);
            });
}

TeleopBus::~TeleopBus() = default;

Session *TeleopBus::session() const
{
    return m_own ? m_own->session() : m_client ? m_client->session() : nullptr;
}

void TeleopBus::open()
{
    if (m_own)
        m_own->run([port = m_portName, baud = m_baud](Session &session) {
            session.open(port, baud, seriallink::EchoMode::Auto);
        });
}

void TeleopBus::run(const BusOperation &operation, quint8 id, qint32 baud, Done done)
{
    if (m_own) {
        m_owed.push_back({id, std::move(done), {}, nullptr});
        m_own->run([operation](Session &session) { session.submit(operation); });
        return;
    }
    if (!m_client || !m_client->link()->isConnected()) {
        OperationResult closed;
        closed.operation = operation.kind;
        closed.message = tr("The follower's bus is not open.");
        closed.failure = OperationFailure::LinkLost;
        done(closed, {});
        return;
    }
    OperationReply *reply = m_client->submit(operation, id, baud, BusClient::Work::Control);
    m_owed.push_back({id, std::move(done), {}, reply});
    connect(reply, &OperationReply::finished, this,
            [this, reply](const OperationResult &result) { finish(reply, result); });
}

void TeleopBus::runInSession(const std::function<void(Session &)> &work)
{
    if (m_own)
        m_own->run(work);
    else if (m_client)
        m_client->runInSession(work);
}

void TeleopBus::forget()
{
    m_owed.clear();
}

void TeleopBus::onMemoryRead(quint8 id, int address, const QByteArray &bytes)
{
    // Only the operation in front reads: the others wait behind it in the same queue.
    if (!m_owed.empty() && m_owed.front().id == id)
        m_owed.front().memory.insert(address, bytes);
}

void TeleopBus::finish(const QObject *reply, const OperationResult &result)
{
    const auto owed = std::find_if(m_owed.begin(), m_owed.end(),
                                   [reply](const Owed &entry) { return entry.reply == reply; });
    if (owed == m_owed.end())
        return;
    const Owed ended = std::move(*owed);
    m_owed.erase(owed);
    if (ended.done)
        ended.done(result, ended.memory);
}

} // namespace feetech
