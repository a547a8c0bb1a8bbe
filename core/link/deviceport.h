// The device's side of a port: what a simulated device holds to hear its host and answer it.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

#include <chrono>

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
    // Whether the port takes bytes before they are due (writeAt) and lets the host have them
    // at their time: the wire's time is then kept however late the device's thread next runs.
    virtual bool takesBytesAhead() const { return false; }
    // `bytes` for the host at `due`; a port that cannot take them ahead sends them now.
    virtual void writeAt(const QByteArray &bytes, std::chrono::steady_clock::time_point due)
    {
        Q_UNUSED(due);
        write(bytes);
    }

signals:
    // What the host sent.
    void received(const QByteArray &bytes);
};

} // namespace seriallink
