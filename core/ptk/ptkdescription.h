// What PTK frames mean: queries, writes and replies explained for the packet log and decoder.
#pragma once

#include "framedescription.h"

#include <QByteArray>
#include <QString>
#include <QVector>

namespace ptk {

// Every frame, frame with a bad checksum and run of stray bytes of a captured stream, in stream
// order. Replies carry no command byte, so each is attributed to the valid query before it.
QVector<seriallink::DecodedFrame>
decodeStream(const QByteArray &stream,
             seriallink::Detail detail = seriallink::Detail::SummaryAndFields);

// The packet log's one-line summary of a frame the session sent or received. A reply is read next
// to the request it answers (`request`, empty when none is in flight), so its words get names.
QString describeFrame(const QByteArray &frame, const QByteArray &request);

} // namespace ptk
