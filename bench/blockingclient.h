// A Feetech client that talks the way the vendors' SDKs and LeRobot do: blocking reads and writes
// on a serial device, one request at a time, in a thread of its own.
#pragma once

#include <QByteArray>
#include <QString>
#include <QVector>

#include <chrono>
#include <optional>

namespace bench {

// Plain POSIX calls, nothing of ServoBench's link: what another program does on the port a
// share offers it (or on the simulator's port directly, for comparison).
class BlockingClient
{
public:
    BlockingClient() = default;
    ~BlockingClient();
    BlockingClient(const BlockingClient &) = delete;
    BlockingClient &operator=(const BlockingClient &) = delete;

    // Opens the device raw at `baud` (exclusive, as pyserial does); false and why in error().
    bool open(const QString &path, qint32 baud);
    void close();
    bool isOpen() const { return m_fd >= 0; }
    // Sets the rate, as a program switching its port does.
    bool setBaudRate(qint32 baud);
    QString error() const { return m_error; }

    // Sends a request, then collects status frames until `answers` have come or `timeout` has
    // passed since the last byte; every frame heard, in order (an echo is skipped).
    QVector<QByteArray>
    exchange(const QByteArray &request, int answers,
             std::chrono::milliseconds timeout = std::chrono::milliseconds(250));
    // One answer's frame from `id`, or nothing.
    std::optional<QByteArray>
    ask(const QByteArray &request, quint8 id,
        std::chrono::milliseconds timeout = std::chrono::milliseconds(250));
    // Frames heard that answered nothing asked (bytes the client did not expect).
    int unexpectedFrames() const { return m_unexpected; }

private:
    int m_fd = -1;
    QString m_error;
    QByteArray m_buffer;
    int m_unexpected = 0;
};

} // namespace bench
