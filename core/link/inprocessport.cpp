// A port inside this program: the names offered, and the device's end of the bytes.
#include "inprocessport.h"

#include "inprocesstransport.h"

#include <QCoreApplication>
#include <QHash>
#include <QMutex>
#include <QSet>

#include <algorithm>

namespace {

struct InProcessPortTr
{
    Q_DECLARE_TR_FUNCTIONS(InProcessPort)
};

// The ports this program offers, by name, and every name it has offered.
struct Registry
{
    QMutex lock;
    QHash<QString, seriallink::InProcessPort *> offered;
    QSet<QString> known;
    quint64 attachments = 0;
};

Registry &registry()
{
    static Registry instance;
    return instance;
}

} // namespace

namespace seriallink {

InProcessPort::InProcessPort(QObject *parent)
    : DevicePort(parent)
{ }

InProcessPort::~InProcessPort()
{
    close();
}

QMutex &InProcessPort::lock()
{
    return registry().lock;
}

InProcessPort *InProcessPort::offered(const QString &name)
{
    return registry().offered.value(name);
}

quint64 InProcessPort::nextAttachment()
{
    return ++registry().attachments;
}

bool InProcessPort::isKnown(const QString &name)
{
    const QMutexLocker locked(&lock());
    return registry().known.contains(name);
}

bool InProcessPort::open(const QString &name, QString *error)
{
    close();
    if (name.isEmpty()) {
        if (error)
            *error = InProcessPortTr::tr("A simulated port needs a name.");
        return false;
    }
    const QMutexLocker locked(&lock());
    QString free = name;
    for (int number = 2; registry().offered.contains(free); ++number)
        free = InProcessPortTr::tr("%1 (%2)").arg(name).arg(number);
    registry().offered.insert(free, this);
    registry().known.insert(free);
    m_name = free;
    return true;
}

void InProcessPort::close()
{
    const QMutexLocker locked(&lock());
    if (m_name.isEmpty())
        return;
    registry().offered.remove(m_name);
    m_name.clear();
    if (InProcessTransport *host = m_host) {
        // The host hears it as a serial port hears an adapter pulled out.
        host->m_device = nullptr;
        const quint64 attachment = m_attachment;
        QMetaObject::invokeMethod(
            host, [host, attachment] { host->onDeviceGone(attachment); }, Qt::QueuedConnection);
    }
    m_host = nullptr;
}

bool InProcessPort::hasHost() const
{
    const QMutexLocker locked(&lock());
    return m_host != nullptr;
}

void InProcessPort::write(const QByteArray &bytes)
{
    writeAt(bytes, std::chrono::steady_clock::now());
}

void InProcessPort::writeAt(const QByteArray &bytes, std::chrono::steady_clock::time_point due)
{
    if (bytes.isEmpty())
        return;
    const QMutexLocker locked(&lock());
    InProcessTransport *host = m_host;
    if (!host)
        return;
    // Kept in the order they are due (an echo may be handed over after an answer due later).
    auto &input = host->m_input;
    const auto at =
        std::upper_bound(input.begin(), input.end(), due,
                         [](auto time, const auto &arriving) { return time < arriving.due; });
    input.insert(at, {due, bytes});
    // One call on its way is enough: it takes everything due by then and waits for the rest.
    if (host->m_inputAnnounced)
        return;
    host->m_inputAnnounced = true;
    QMetaObject::invokeMethod(host, &InProcessTransport::deliverPendingInput, Qt::QueuedConnection);
}

void InProcessPort::fromHost(const QByteArray &bytes, qint32 baud, quint64 attachment)
{
    {
        const QMutexLocker locked(&lock());
        if (attachment != m_attachment || !m_host)
            return; // sent by a host that has closed the port since
    }
    m_hostBaud = baud;
    emit received(bytes);
}

} // namespace seriallink
