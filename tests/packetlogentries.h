// Test helper: numbered packet log entries, alternating out and in, optionally with an error.
#pragma once

#include "linktypes.h"

#include <QString>

namespace testsupport {

inline seriallink::PacketLogEntry logEntry(int n, const QString &error = {})
{
    seriallink::PacketLogEntry entry;
    entry.timestampMs = 1700000000000 + n;
    entry.direction = n % 2 ? seriallink::Direction::In : seriallink::Direction::Out;
    entry.bytes = QByteArray::fromHex("affa000a380000000042");
    entry.bytes[5] = char(n);
    entry.summary = QStringLiteral("frame %1").arg(n);
    entry.error = error;
    return entry;
}

} // namespace testsupport
