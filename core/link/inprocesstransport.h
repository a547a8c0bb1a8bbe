// The link's end of a port inside this program (InProcessPort): the simulated servos reached by
// queued calls between the threads, with no pseudo-terminal.
#pragma once

#include "porttransport.h"

#include <chrono>
#include <deque>

namespace seriallink {

class InProcessPort;
class PreciseTimer;

// To the request engine it is a serial port like any other: the bytes the device sends arrive
// through received, bytesWritten follows a write from the event loop, a device that stops is
// a port that went away (failed, lost) and is found again under its name when it returns.
// Lives in the link's thread.
class InProcessTransport final : public PortTransport
{
    Q_OBJECT

public:
    explicit InProcessTransport(QObject *parent = nullptr);
    ~InProcessTransport() override;

    bool open(const QString &portName, qint32 baud, QString *error) override;
    void close() override;
    // The rate goes with each write: the device hears every byte at the rate it was sent at.
    bool setBaudRate(qint32 baud) override;
    QString portName() const override { return m_name; }

    bool isOpen() const override { return m_open; }
    qint32 baudRate() const override { return m_baud; }
    void write(const QByteArray &bytes) override;
    // What has come, up to now; bytes the device sent ahead arrive at their time.
    QByteArray discardInput() override;
    void deliverPendingInput() override;

private:
    friend class InProcessPort;

    struct Arriving
    {
        std::chrono::steady_clock::time_point due;
        QByteArray bytes;
    };

    void onDeviceGone(quint64 attachment);

    QString m_name;
    qint32 m_baud = 0;
    bool m_open = false;
    PreciseTimer *m_arrival = nullptr; // the next bytes sent ahead are due
    // Under InProcessPort::lock(), shared with the device's thread:
    InProcessPort *m_device = nullptr;
    quint64 m_attachment = 0;
    std::deque<Arriving> m_input; // the device's bytes not yet delivered, in the order due
    bool m_inputAnnounced = false; // a delivery is on its way to this thread
};

} // namespace seriallink
