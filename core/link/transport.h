// The byte pipe the request engine talks through: a serial port here, a scripted fake in tests.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QSerialPort>
#include <QString>

namespace seriallink {

class Transport : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    virtual bool isOpen() const = 0;
    virtual qint32 baudRate() const = 0;
    virtual void write(const QByteArray &bytes) = 0;
    // Takes whatever input is waiting, delivered or not, so that nothing received before a new
    // request can be taken for its answer. Returns the bytes it could still see.
    virtual QByteArray discardInput() = 0;
    // Delivers (through received) input that has arrived but not been announced yet. A timeout
    // asks first: on a busy machine the timer can fire before the read of a reply that is
    // already there.
    virtual void deliverPendingInput() { }

signals:
    void received(const QByteArray &bytes);
    void bytesWritten(qint64 count);
    // The port failed; `lost` when the device itself went away (unplugged, simulator gone).
    void failed(const QString &message, bool lost);
};

// A QSerialPort, created in (and used only from) the thread that creates this object.
class SerialTransport final : public Transport
{
    Q_OBJECT

public:
    explicit SerialTransport(QObject *parent = nullptr);

    // 8N1, no flow control. On failure *error says why, in words for the user.
    bool open(const QString &portName, qint32 baud, QString *error);
    void close();
    bool setBaudRate(qint32 baud);
    QString portName() const { return m_port->portName(); }

    bool isOpen() const override { return m_port->isOpen(); }
    qint32 baudRate() const override { return m_port->baudRate(); }
    void write(const QByteArray &bytes) override;
    QByteArray discardInput() override;
    void deliverPendingInput() override;

private:
    void onError(QSerialPort::SerialPortError error);
    // The device is gone or closed on the far side (a pty whose other end closed, an adapter
    // unplugged): a read error then means the link is lost.
    bool isHungUp() const;
    // Reads what the port holds and watches for input again (after a spurious ResourceError).
    void resumeReading();

    QSerialPort *m_port = nullptr;
};

// One translated sentence per QSerialPort error, naming the port (style: errors in one place).
QString portErrorMessage(QSerialPort::SerialPortError error, const QString &portName,
                         const QString &systemMessage);
// Errors after which the port is gone and should be reopened when it returns.
bool isLostError(QSerialPort::SerialPortError error);

} // namespace seriallink
