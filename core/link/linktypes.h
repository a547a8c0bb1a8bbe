// Value types that cross from a link's worker thread to the GUI: log entries, counters, state.
#pragma once

#include <QByteArray>
#include <QMetaType>
#include <QString>

namespace seriallink {

// Out: a frame we sent. In: a frame received. Echo: our own bytes coming back from a
// single-wire adapter. Stray: bytes that belonged to no transaction or no valid frame.
enum class Direction { Out, In, Echo, Stray };

struct PacketLogEntry
{
    qint64 timestampMs = 0; // milliseconds since the epoch
    Direction direction = Direction::Out;
    QByteArray bytes;
    QString summary; // decoded meaning, translated
    QString error; // empty when the frame is fine (bad checksum, timeout, unexpected…)
};

struct LinkCounters
{
    qint64 framesSent = 0;
    qint64 repliesOk = 0;
    qint64 checksumErrors = 0;
    qint64 timeouts = 0; // transactions that got no valid reply in time (each try counts)
    qint64 retries = 0;
    qint64 failures = 0; // transactions given up after every retry
    qint64 discardedBytes = 0; // stray input thrown away
    qint64 echoBytes = 0; // our own bytes removed by echo suppression
    qint64 lateReplies = 0; // answers that came after their request had ended, discarded

    bool operator==(const LinkCounters &other) const
    {
        return framesSent == other.framesSent && repliesOk == other.repliesOk
            && checksumErrors == other.checksumErrors && timeouts == other.timeouts
            && retries == other.retries && failures == other.failures
            && discardedBytes == other.discardedBytes && echoBytes == other.echoBytes
            && lateReplies == other.lateReplies;
    }
    bool operator!=(const LinkCounters &other) const { return !(*this == other); }
};

// Disconnected: no port. Connecting: opening. Connected: the device answers. NoReply: the port
// is open but the device stays silent. Lost: the port went away (unplugged); it is reopened as
// soon as it comes back.
enum class ConnectionState { Disconnected, Connecting, Connected, NoReply, Lost };

struct ConnectionStatus
{
    ConnectionState state = ConnectionState::Disconnected;
    QString portName;
    qint32 baud = 0;
    QString message; // translated explanation of the state (why it failed, what to do)
};

} // namespace seriallink

Q_DECLARE_METATYPE(seriallink::PacketLogEntry)
Q_DECLARE_METATYPE(seriallink::LinkCounters)
Q_DECLARE_METATYPE(seriallink::ConnectionStatus)
