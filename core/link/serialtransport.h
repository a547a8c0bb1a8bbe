// A serial port as the link's transport, and the table of port error messages.
#pragma once

#include "porttransport.h"

#include <QSerialPort>

namespace seriallink {

// A QSerialPort, created in (and used only from) the thread that creates this object.
class SerialTransport final : public PortTransport
{
    Q_OBJECT

public:
    explicit SerialTransport(QObject *parent = nullptr);

    // 8N1, no flow control.
    bool open(const QString &portName, qint32 baud, QString *error) override;
    void close() override;
    bool setBaudRate(qint32 baud) override;
    QString portName() const override { return m_port->portName(); }

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
    bool m_handingOn = false; // emitting received() with all the port held
};

// One translated sentence per QSerialPort error, naming the port (style: errors in one place).
QString portErrorMessage(QSerialPort::SerialPortError error, const QString &portName,
                         const QString &systemMessage);
// Errors after which the port is gone and should be reopened when it returns.
bool isLostError(QSerialPort::SerialPortError error);

} // namespace seriallink
