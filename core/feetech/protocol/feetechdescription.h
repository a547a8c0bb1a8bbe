// What Feetech packets mean: instructions and status packets explained for the packet log and
// decoder.
#pragma once

#include "framedescription.h"

#include <QByteArray>
#include <QString>
#include <QVector>

namespace feetech {

// Every packet, packet with a bad checksum and run of stray bytes of a captured stream, in stream
// order. Status and instruction packets look alike, so a packet from a servo the previous
// instruction addressed (or any servo after a broadcast PING) is read as its status packet.
QVector<seriallink::DecodedFrame>
decodeStream(const QByteArray &stream,
             seriallink::Detail detail = seriallink::Detail::SummaryAndFields);

// The packet log's one-line summary of a packet the session sent or received. A reply is read
// next to the request that asked for it (a READ's data then gets its address), even one with
// the request's very bytes (a PING answered with the voltage bit); a request, or a frame with no
// request before it, is given an empty `request`.
QString describeFrame(const QByteArray &frame, const QByteArray &request);

} // namespace feetech
