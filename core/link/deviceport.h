// The device's side of a port: what a simulated device holds to hear its host and answer it.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

namespace seriallink {

// A pseudo-terminal (servosim, a shared bus's program side) or a port inside this program (the
// window's demo servos). Lives in the device's thread.
class DevicePort : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    // The name the host opens the port by.
    virtual QString portName() const = 0;
    virtual void close() = 0;
    // The rate the host set on its side for the bytes it sent last (0 when it cannot be known).
    virtual qint32 hostBaudRate() const = 0;
    // To the host, now: whoever calls this keeps the wire's time.
    virtual void write(const QByteArray &bytes) = 0;

signals:
    // What the host sent.
    void received(const QByteArray &bytes);
};

} // namespace seriallink
