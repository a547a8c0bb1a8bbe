// The link's end of a port inside this program: bytes to the device's thread and back.
#include "inprocesstransport.h"

#include "inprocessport.h"

#include <QCoreApplication>
#include <QMutex>

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(InProcessTransport)
};

} // namespace

namespace seriallink {

InProcessTransport::InProcessTransport(QObject *parent)
    : PortTransport(parent)
{ }

InProcessTransport::~InProcessTransport()
{
    close();
}

bool InProcessTransport::open(const QString &portName, qint32 baud, QString *error)
{
    close();
    const QMutexLocker locked(&InProcessPort::lock());
    InProcessPort *device = InProcessPort::offered(portName);
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (!device)
        return fail(Tr::tr("%1 is not running: its simulated servos have stopped.").arg(portName));
    if (device->m_host)
        return fail(Tr::tr("%1 is already open.").arg(portName));
    m_attachment = InProcessPort::nextAttachment();
    device->m_host = this;
    device->m_attachment = m_attachment;
    m_device = device;
    m_input.clear();
    m_inputAnnounced = false;
    m_name = portName;
    m_baud = baud;
    m_open = true;
    return true;
}

void InProcessTransport::close()
{
    const QMutexLocker locked(&InProcessPort::lock());
    if (m_device && m_device->m_host == this)
        m_device->m_host = nullptr;
    m_device = nullptr;
    m_input.clear();
    m_open = false;
}

bool InProcessTransport::setBaudRate(qint32 baud)
{
    if (baud <= 0)
        return false;
    m_baud = baud;
    return true;
}

void InProcessTransport::write(const QByteArray &bytes)
{
    if (!m_open || bytes.isEmpty())
        return;
    {
        const QMutexLocker locked(&InProcessPort::lock());
        // A device gone meanwhile loses them, as a pulled adapter does; failed says so.
        if (InProcessPort *device = m_device) {
            const qint32 baud = m_baud;
            const quint64 attachment = m_attachment;
            QMetaObject::invokeMethod(
                device,
                [device, bytes, baud, attachment] { device->fromHost(bytes, baud, attachment); },
                Qt::QueuedConnection);
        }
    }
    // As a serial port reports it: from the event loop, never inside the caller's write.
    const qint64 count = bytes.size();
    QMetaObject::invokeMethod(
        this,
        [this, count] {
            if (m_open)
                emit bytesWritten(count);
        },
        Qt::QueuedConnection);
}

QByteArray InProcessTransport::discardInput()
{
    const QMutexLocker locked(&InProcessPort::lock());
    QByteArray waiting;
    waiting.swap(m_input);
    return waiting;
}

void InProcessTransport::deliverPendingInput()
{
    QByteArray bytes;
    {
        const QMutexLocker locked(&InProcessPort::lock());
        bytes.swap(m_input);
        m_inputAnnounced = false;
    }
    if (m_open && !bytes.isEmpty())
        emit received(bytes);
}

void InProcessTransport::onDeviceGone(quint64 attachment)
{
    if (!m_open || attachment != m_attachment)
        return; // closed, or opened again, since
    emit failed(Tr::tr("%1 went away: its simulated servos have stopped.").arg(m_name), true);
}

} // namespace seriallink
