// What a frame on the wire means, as the packet log and `servoctl decode` show it.
#pragma once

#include "streamframer.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QVector>

#include <functional>

namespace seriallink {

// What a description fills in: the summary alone (the packet log, servoctl decode in words) or
// also the fields (servoctl decode --json). Building the fields costs more than the summary.
enum class Detail { Summary, SummaryAndFields };

struct DecodedFrame
{
    QString kind; // ptk: query, write, request, reply; feetech: instruction, status; or garbage
    QByteArray bytes;
    qint64 offset = 0;
    bool checksumValid = true;
    QString summary; // one line for people
    QJsonObject fields; // the same, for --json
};

// Splits a whole captured stream the way a decoder shows it: a frame with a bad checksum stays
// one frame (so it can be explained), stray and trailing bytes become "garbage" and
// "incomplete" entries. Each frame, valid or not, is explained by describeFrame in stream order,
// so a protocol can carry context (the last query, the servos expected to answer) between calls.
QVector<DecodedFrame>
describeStream(const FrameFormat &format, const QByteArray &stream,
               const std::function<DecodedFrame(const StreamItem &item)> &describeFrame);

// "0x0A": how both protocols' explanations write command bytes and addresses.
QString hexByte(int value);

} // namespace seriallink
