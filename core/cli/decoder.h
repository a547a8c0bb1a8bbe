// Splits a captured byte stream into PTK or Feetech frames and explains each one.
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QVector>

#include <optional>

namespace cli {

enum class Protocol { Ptk, Feetech };

struct DecodedFrame
{
    QString kind; // ptk: query, write, request, reply; feetech: instruction, status; or garbage
    QByteArray bytes;
    qint64 offset = 0;
    bool checksumValid = true;
    QString summary; // one line for people
    QJsonObject fields; // the same, for --json
};

// PTK when the stream starts (after any garbage) with AF FA, Feetech with FF FF.
std::optional<Protocol> guessProtocol(const QByteArray &stream);

// Every frame, frame with a bad checksum and run of stray bytes, in stream order. PTK replies
// are attributed to the query before them; Feetech frames from a servo the previous instruction
// addressed are read as status packets.
QVector<DecodedFrame> decodeStream(Protocol protocol, const QByteArray &stream);

QJsonObject toJson(const DecodedFrame &frame);

} // namespace cli
