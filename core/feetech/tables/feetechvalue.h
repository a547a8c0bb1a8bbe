// Register value encoding per family: byte order of 2-byte registers and sign-magnitude values.
#pragma once

#include <QByteArray>
#include <QByteArrayView>

#include <optional>

namespace feetech {

// SCS stores 2-byte registers high byte first; STS, SMS and HLS low byte first (spec §3).
enum class ByteOrder { Little, Big };

struct ValueFormat
{
    int size = 1; // 1 or 2 bytes
    ByteOrder order = ByteOrder::Little;
    std::optional<int> signBit; // sign-magnitude with this sign bit; unsigned when absent
};

// Largest magnitude a register of this format can hold.
qint32 maximumMagnitude(const ValueFormat &format);
qint32 minimumValue(const ValueFormat &format);

// Sign-magnitude, not two's complement: -5 with sign bit 11 is 0x0805.
std::optional<quint16> toSignMagnitude(qint32 value, int signBit);
qint32 fromSignMagnitude(quint16 raw, int signBit);

// Raw (unsigned, undecoded) register contents <-> bytes in the family's order.
QByteArray encodeRaw(quint16 raw, int size, ByteOrder order);
quint16 decodeRaw(QByteArrayView bytes, ByteOrder order);

// A value in register units <-> bytes; nothing when the value does not fit the format.
std::optional<quint16> toRaw(qint32 value, const ValueFormat &format);
qint32 fromRaw(quint16 raw, const ValueFormat &format);
std::optional<QByteArray> encodeValue(qint32 value, const ValueFormat &format);
qint32 decodeValue(QByteArrayView bytes, const ValueFormat &format);

} // namespace feetech
