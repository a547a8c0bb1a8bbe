// A port inside this program: the device's end of a link that reaches simulated servos in
// another thread without a pseudo-terminal.
#pragma once

#include "deviceport.h"

class QMutex;

namespace seriallink {

class InProcessTransport;

// Offered under a name that a link opens like a serial port (LinkSession picks an
// InProcessTransport for it). The host's bytes arrive here by queued calls, each with the rate
// the host had set; the device's bytes go to the host's thread with the time they are due
// (writeAt), and the host has them at that time: the device decides when bytes cross the wire,
// as it does behind a pseudo-terminal, but neither a kernel worker nor the device's thread
// has to run again for them to arrive. One host at a time, as a serial port's exclusive lock
// allows. Lives in the device's thread.
class InProcessPort final : public DevicePort
{
    Q_OBJECT

public:
    explicit InProcessPort(QObject *parent = nullptr);
    ~InProcessPort() override;

    // Offers the port under `name`, or "name (2)", "name (3)"... while that one is offered by
    // another. False, and *error, for an empty name. A host that has it open when it closes is
    // told that the port went away.
    bool open(const QString &name, QString *error);
    void close() override;
    bool isOpen() const { return !m_name.isEmpty(); }
    // Whether a host has the port open.
    bool hasHost() const;

    QString portName() const override { return m_name; }
    qint32 hostBaudRate() const override { return m_hostBaud; }
    // Bytes for the host, now or at `due`; lost, as on a wire, while no host has the port open.
    void write(const QByteArray &bytes) override;
    bool takesBytesAhead() const override { return true; }
    void writeAt(const QByteArray &bytes, std::chrono::steady_clock::time_point due) override;

    // Whether this program offers, or offered, a port by that name: such a port is opened in
    // process, and while it is not offered it is a port that went away, not a missing device.
    static bool isKnown(const QString &name);

private:
    friend class InProcessTransport;

    // Both ends' links to each other and the host's waiting input are guarded by one lock.
    static QMutex &lock();
    // The port offered under `name` now; null when none is. Call with the lock held.
    static InProcessPort *offered(const QString &name);
    // A new number for a host's opening: what either end sent under an older one is ignored.
    static quint64 nextAttachment();

    void fromHost(const QByteArray &bytes, qint32 baud, quint64 attachment);

    QString m_name;
    qint32 m_hostBaud = 0;
    InProcessTransport *m_host = nullptr; // under lock()
    quint64 m_attachment = 0; // under lock()
};

} // namespace seriallink
