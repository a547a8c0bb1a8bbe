// The link's end of a port inside this program: bytes to the device's thread and back.
#include "inprocesstransport.h"

#include "inprocessport.h"
#include "precisetimer.h"

#include <QCoreApplication>
#include <QMutex>

#include <algorithm>
#include <optional>

namespace {

struct InProcessTransportTr
{
    Q_DECLARE_TR_FUNCTIONS(InProcessTransport)
};

using Clock = std::chrono::steady_clock;

} // namespace

namespace seriallink {

InProcessTransport::InProcessTransport(QObject *parent)
    : PortTransport(parent)
    , m_arrival(new PreciseTimer(this))
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
        return fail(
            InProcessTransportTr::tr("%1 is not running: its simulated servos have stopped.")
                .arg(portName));
    if (device->m_host)
        return fail(InProcessTransportTr::tr("%1 is already open.").arg(portName));
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
    m_arrival->stop();
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
    const Clock::time_point now = Clock::now();
    const QMutexLocker locked(&InProcessPort::lock());
    QByteArray come;
    while (!m_input.empty() && m_input.front().due <= now) {
        come += m_input.front().bytes;
        m_input.pop_front();
    }
    return come;
}

void InProcessTransport::deliverPendingInput()
{
    const Clock::time_point now = Clock::now();
    QByteArray come;
    std::optional<Clock::time_point> next;
    {
        const QMutexLocker locked(&InProcessPort::lock());
        m_inputAnnounced = false;
        while (!m_input.empty() && m_input.front().due <= now) {
            come += m_input.front().bytes;
            m_input.pop_front();
        }
        if (!m_input.empty())
            next = m_input.front().due;
    }
    if (next) {
        const auto wait = std::chrono::duration_cast<std::chrono::microseconds>(*next - now);
        m_arrival->start(std::max(wait, std::chrono::microseconds(1)),
                         [this] { deliverPendingInput(); });
    }
    if (m_open && !come.isEmpty())
        emit received(come);
}

void InProcessTransport::onDeviceGone(quint64 attachment)
{
    if (!m_open || attachment != m_attachment)
        return; // closed, or opened again, since
    emit failed(
        InProcessTransportTr::tr("%1 went away: its simulated servos have stopped.").arg(m_name),
        true);
}

} // namespace seriallink
