// Feetech value encoding: byte order and sign-magnitude (spec/feetech-protocol.md §3).
#include "feetechvalue.h"

namespace feetech {

qint32 maximumMagnitude(const ValueFormat &format)
{
    if (format.signBit)
        return (qint32(1) << *format.signBit) - 1;
    return format.size == 1 ? 0xFF : 0xFFFF;
}

qint32 minimumValue(const ValueFormat &format)
{
    return format.signBit ? -maximumMagnitude(format) : 0;
}

std::optional<quint16> toSignMagnitude(qint32 value, int signBit)
{
    const qint32 limit = (qint32(1) << signBit) - 1;
    const qint32 magnitude = value < 0 ? -value : value;
    if (magnitude > limit)
        return std::nullopt;
    return quint16(value < 0 ? (magnitude | (1 << signBit)) : magnitude);
}

qint32 fromSignMagnitude(quint16 raw, int signBit)
{
    const qint32 magnitude = raw & ((1 << signBit) - 1);
    return (raw & (1 << signBit)) ? -magnitude : magnitude;
}

QByteArray encodeRaw(quint16 raw, int size, ByteOrder order)
{
    QByteArray out;
    if (size == 1) {
        out.append(char(raw & 0xFF));
    } else if (order == ByteOrder::Little) {
        out.append(char(raw & 0xFF));
        out.append(char(raw >> 8));
    } else {
        out.append(char(raw >> 8));
        out.append(char(raw & 0xFF));
    }
    return out;
}

quint16 decodeRaw(QByteArrayView bytes, ByteOrder order)
{
    if (bytes.size() == 1)
        return quint8(bytes[0]);
    const quint8 first = quint8(bytes[0]);
    const quint8 second = quint8(bytes[1]);
    return order == ByteOrder::Little ? quint16(first | (second << 8))
                                      : quint16((first << 8) | second);
}

std::optional<quint16> toRaw(qint32 value, const ValueFormat &format)
{
    if (value < minimumValue(format) || value > maximumMagnitude(format))
        return std::nullopt;
    if (format.signBit)
        return toSignMagnitude(value, *format.signBit);
    return quint16(value);
}

qint32 fromRaw(quint16 raw, const ValueFormat &format)
{
    return format.signBit ? fromSignMagnitude(raw, *format.signBit) : qint32(raw);
}

std::optional<QByteArray> encodeValue(qint32 value, const ValueFormat &format)
{
    const auto raw = toRaw(value, format);
    if (!raw)
        return std::nullopt;
    return encodeRaw(*raw, format.size, format.order);
}

qint32 decodeValue(QByteArrayView bytes, const ValueFormat &format)
{
    return fromRaw(decodeRaw(bytes.first(format.size), format.order), format);
}

} // namespace feetech
