// A shared bus's frames as packet log lines: who sent each, and what it means.
#pragma once

#include "linktypes.h"
#include "sharerecording.h"

#include <QByteArray>

namespace share {

// Turns the frames a share passed (live, or read back from a recording) into the packet log's
// entries, in the order they passed: each answer is described after the request it answers,
// the program's and ServoBench's own kept apart, so an own READ between the program's
// transactions does not change what the program's answers mean.
class ShareLogEntries
{
public:
    // `timestampMs` is when it passed, milliseconds since the epoch.
    seriallink::PacketLogEntry entry(const RecordedFrame &frame, qint64 timestampMs);

private:
    QByteArray m_programRequest; // the program's last request
    QByteArray m_ownRequest; // ServoBench's own last request
};

} // namespace share
