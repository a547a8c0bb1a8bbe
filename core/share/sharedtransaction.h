// One request of a program on a shared bus with the frames that answered it, as the share saw it.
#pragma once

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace share {

// A register a transaction read or wrote, by key, where the servo's model is known.
struct RegisterAccess
{
    quint8 id = 0;
    QString key;
    qint32 value = 0;
    bool written = false; // the request wrote it; otherwise a reply reported it
};

// The registers as JSON objects: id, key, value, access ("read" or "write").
QJsonArray registersToJson(const QVector<RegisterAccess> &registers);

struct SharedTransaction
{
    qint64 timeUs = 0; // when the request was complete, microseconds since the share began
    QByteArray request;
    QVector<QByteArray> replies; // the status frames that answered it, in order
    int echoBytes = 0; // the adapter's echo of the request, passed on like everything else
    int garbledBytes = 0; // bytes heard while it waited that made no valid frame
    int expectedReplies = -1; // -1: as many as come (a broadcast PING)
    // From the request complete to the last answer complete; nothing when nothing answered.
    std::optional<qint64> roundTripUs;
    bool own = false; // ServoBench's own (the watch's reads, its operations), not the program's
    QVector<RegisterAccess> registers; // what it meant, where the model is known

    quint8 id() const;
    quint8 instruction() const;
    // The error bits of every answer together (the byte after a status frame's length).
    quint8 errorBits() const;
    // Fewer answers came than the request asks for.
    bool unanswered() const;
    // The IDs a SYNC READ asks (its parameters after address and length); the ID otherwise.
    QVector<quint8> askedIds() const;

    // One JSON line: time, ID, instruction, request and reply bytes (hex), error bits, the
    // round trip and the registers read or written, by key.
    QJsonObject toJson() const;
};

} // namespace share

Q_DECLARE_METATYPE(share::SharedTransaction)
