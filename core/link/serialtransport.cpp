// Serial transport over QSerialPort, and the table of port error messages.
#include "serialtransport.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QPointer>

#ifdef Q_OS_UNIX
#include <poll.h>
#endif

namespace {

struct SerialLinkTr
{
    Q_DECLARE_TR_FUNCTIONS(SerialLink)
};

} // namespace

namespace seriallink {

Q_LOGGING_CATEGORY(lcLink, "servobench.link", QtWarningMsg)

SerialTransport::SerialTransport(QObject *parent)
    : PortTransport(parent)
    , m_port(new QSerialPort(this))
{
    connect(m_port, &QSerialPort::readyRead, this, [this] {
        const QByteArray bytes = m_port->readAll();
        if (bytes.isEmpty())
            return;
        const QPointer<SerialTransport> alive(this); // whoever hears it may close the link
        m_handingOn = true;
        emit received(bytes);
        if (alive)
            m_handingOn = false;
    });
    connect(m_port, &QSerialPort::bytesWritten, this, &Transport::bytesWritten);
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
}

bool SerialTransport::open(const QString &portName, qint32 baud, QString *error)
{
    close();
    m_port->setPortName(portName);
    m_port->setBaudRate(baud);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    // open() reports its own failure through errorOccurred too; that one is answered here.
    const QSignalBlocker quiet(m_port);
    if (!m_port->open(QIODevice::ReadWrite)) {
        if (error)
            *error = portErrorMessage(m_port->error(), portName, m_port->errorString());
        m_port->clearError();
        return false;
    }
    m_port->clear(QSerialPort::AllDirections);
    qCDebug(lcLink) << "opened" << portName << "at" << baud;
    return true;
}

void SerialTransport::close()
{
    if (m_port->isOpen())
        m_port->close();
    m_port->clearError();
}

bool SerialTransport::setBaudRate(qint32 baud)
{
    return m_port->setBaudRate(baud);
}

void SerialTransport::write(const QByteArray &bytes)
{
    // QSerialPort only buffers in write() and sends on the next event-loop pass; flush() sends
    // now, so the servo's turnaround is not held up by that pass (bytesWritten still follows
    // from the event loop, once the bytes have left).
    m_port->write(bytes);
    m_port->flush();
}

QByteArray SerialTransport::discardInput()
{
    // No tcflush here: input the port has already announced would then be gone when its read
    // notification comes, and QSerialPort reports that empty read as a device error (with a
    // stale errno, often as "the device went away"). Bytes still in the kernel arrive with the
    // next read and are discarded there as input that answers nothing.
    return m_port->readAll();
}

void SerialTransport::deliverPendingInput()
{
    // A zero wait only looks: it reads what the port holds and emits readyRead at once. While
    // the port's input is being handed on (an answer that ends its exchange, and the next
    // request sent from there) the port has just been read to the end: a look would find
    // only what came in the microseconds since, as it would a moment after, at the cost of a
    // system call on the way to every request of a stream.
    if (m_port->isOpen() && !m_handingOn)
        m_port->waitForReadyRead(0);
}

void SerialTransport::onError(QSerialPort::SerialPortError error)
{
    if (error == QSerialPort::NoError || error == QSerialPort::TimeoutError)
        return;
    if ((error == QSerialPort::ReadError || error == QSerialPort::ResourceError) && !isHungUp()) {
        // QSerialPort calls a read that finds nothing an error: a ReadError with whatever errno
        // was left from before, or, when the read says EAGAIN, a ResourceError ("the device
        // went away"). That happens when input it was told about was read first (a late reply
        // discarded before the next request, a wait that looked): the port is fine. After a
        // ResourceError QSerialPort stops watching for input; a read starts it again, once it
        // has finished with this one.
        qCDebug(lcLink) << "read found nothing; not an error" << m_port->errorString();
        m_port->clearError();
        if (error == QSerialPort::ResourceError)
            QMetaObject::invokeMethod(this, &SerialTransport::resumeReading, Qt::QueuedConnection);
        return;
    }
    const QString message = portErrorMessage(error, m_port->portName(), m_port->errorString());
    qCDebug(lcLink) << "port error" << error << m_port->errorString() << message;
    m_port->clearError();
    emit failed(message, isLostError(error));
}

void SerialTransport::resumeReading()
{
    if (!m_port->isOpen())
        return;
    const QByteArray bytes = m_port->readAll(); // re-arms QSerialPort's read notification
    if (!bytes.isEmpty())
        emit received(bytes);
}

bool SerialTransport::isHungUp() const
{
    if (!m_port->isOpen())
        return true;
#ifdef Q_OS_UNIX
    // A pulled adapter (or a simulator gone) hangs the descriptor up before QSerialPort says so.
    pollfd descriptor {int(m_port->handle()), POLLIN, 0};
    if (::poll(&descriptor, 1, 0) < 0)
        return true;
    return (descriptor.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
#else
    return false; // Windows reports a removed port through QSerialPort's ResourceError
#endif
}

bool isLostError(QSerialPort::SerialPortError error)
{
    return error == QSerialPort::ResourceError || error == QSerialPort::DeviceNotFoundError
        || error == QSerialPort::ReadError || error == QSerialPort::WriteError;
}

QString portErrorMessage(QSerialPort::SerialPortError error, const QString &portName,
                         const QString &systemMessage)
{
    switch (error) {
    case QSerialPort::NoError:
        return QString();
    case QSerialPort::DeviceNotFoundError:
        return SerialLinkTr::tr("%1 does not exist. Is the adapter plugged in?").arg(portName);
    case QSerialPort::PermissionError:
#ifdef Q_OS_LINUX
        return SerialLinkTr::tr(
                   "Permission denied on %1. Either another program has it open, or you are "
                   "not in the group that may use serial ports: run \"sudo usermod -aG "
                   "dialout $USER\", then log out and back in.")
            .arg(portName);
#else
        return SerialLinkTr::tr("Permission denied on %1: another program may have it open.")
            .arg(portName);
#endif
    case QSerialPort::OpenError:
        return SerialLinkTr::tr("%1 is already open.").arg(portName);
    case QSerialPort::NotOpenError:
        return SerialLinkTr::tr("%1 is not open.").arg(portName);
    case QSerialPort::WriteError:
        return SerialLinkTr::tr("Could not write to %1 (%2).").arg(portName, systemMessage);
    case QSerialPort::ReadError:
        return SerialLinkTr::tr("Could not read from %1 (%2).").arg(portName, systemMessage);
    case QSerialPort::ResourceError:
        return SerialLinkTr::tr("%1 went away: the adapter was unplugged or the device closed.")
            .arg(portName);
    case QSerialPort::UnsupportedOperationError:
        return SerialLinkTr::tr("%1 does not support this setting (%2).")
            .arg(portName, systemMessage);
    case QSerialPort::TimeoutError:
        return SerialLinkTr::tr("%1 timed out.").arg(portName);
    case QSerialPort::UnknownError:
        break;
    }
    return SerialLinkTr::tr("%1: %2").arg(portName, systemMessage);
}

} // namespace seriallink
