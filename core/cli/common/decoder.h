// `servoctl decode`: picks the protocol of a captured byte stream and prints its frames.
#pragma once

#include "framedescription.h"

#include <QByteArray>
#include <QJsonObject>
#include <QVector>

#include <optional>

namespace cli {

enum class Protocol { Ptk, Feetech };

using DecodedFrame = seriallink::DecodedFrame;

// PTK when the stream starts (after any garbage) with AF FA, Feetech with FF FF.
std::optional<Protocol> guessProtocol(const QByteArray &stream);

// Every frame of the stream explained by its protocol (ptk::decodeStream, feetech::decodeStream);
// the fields toJson prints are filled only when asked for.
QVector<DecodedFrame>
decodeStream(Protocol protocol, const QByteArray &stream,
             seriallink::Detail detail = seriallink::Detail::SummaryAndFields);

QJsonObject toJson(const DecodedFrame &frame);

} // namespace cli
