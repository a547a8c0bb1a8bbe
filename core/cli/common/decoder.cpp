// Packet decoder for `servoctl decode`: chooses the protocol and shapes frames for --json.
#include "decoder.h"

#include "feetechdescription.h"
#include "hex.h"
#include "ptkdescription.h"
#include "ptkframe.h"

namespace cli {

std::optional<Protocol> guessProtocol(const QByteArray &stream)
{
    for (int i = 0; i + 1 < stream.size(); ++i) {
        if (quint8(stream[i]) == ptk::kHeader0 && quint8(stream[i + 1]) == ptk::kHeader1)
            return Protocol::Ptk;
        if (quint8(stream[i]) == 0xFF && quint8(stream[i + 1]) == 0xFF)
            return Protocol::Feetech;
    }
    return std::nullopt;
}

QVector<DecodedFrame> decodeStream(Protocol protocol, const QByteArray &stream,
                                   seriallink::Detail detail)
{
    return protocol == Protocol::Ptk ? ptk::decodeStream(stream, detail)
                                     : feetech::decodeStream(stream, detail);
}

QJsonObject toJson(const DecodedFrame &frame)
{
    QJsonObject object = frame.fields;
    object.insert(QStringLiteral("kind"), frame.kind);
    object.insert(QStringLiteral("offset"), frame.offset);
    object.insert(QStringLiteral("hex"), util::toHex(frame.bytes));
    object.insert(QStringLiteral("checksum_valid"), frame.checksumValid);
    object.insert(QStringLiteral("summary"), frame.summary);
    return object;
}

} // namespace cli
