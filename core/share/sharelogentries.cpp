// A shared bus's frames as packet log lines: the direction, the sender and the meaning.
#include "sharelogentries.h"

#include "feetechdescription.h"
#include "feetechpacket.h"

#include <QCoreApplication>

namespace share {

namespace {

struct ShareLogEntriesTr
{
    Q_DECLARE_TR_FUNCTIONS(ShareLogEntries)
};

} // namespace

seriallink::PacketLogEntry ShareLogEntries::entry(const RecordedFrame &frame, qint64 timestampMs)
{
    seriallink::PacketLogEntry entry;
    entry.timestampMs = timestampMs;
    entry.bytes = frame.bytes;
    if (frame.direction == FrameDirection::Note) {
        entry.direction = seriallink::Direction::In;
        entry.summary = ShareLogEntriesTr::tr("Shared bus: %1").arg(frame.note);
        return entry;
    }
    const bool request =
        frame.direction == FrameDirection::FromProgram || frame.direction == FrameDirection::Own;
    const bool program = frame.direction == FrameDirection::FromProgram
        || frame.direction == FrameDirection::ToProgram;
    entry.direction = request ? seriallink::Direction::Out : seriallink::Direction::In;
    if (!feetech::decodePacket(frame.bytes)) {
        // Passed on all the same: the program hears exactly what the wire carried.
        entry.direction = seriallink::Direction::Stray;
        entry.error = program
            ? ShareLogEntriesTr::tr("Not a whole frame (passed on to the other program)")
            : ShareLogEntriesTr::tr("Not a whole frame");
        return entry;
    }
    QByteArray &lastRequest = program ? m_programRequest : m_ownRequest;
    const QString meaning =
        feetech::describeFrame(frame.bytes, request ? QByteArray() : lastRequest);
    if (request)
        lastRequest = frame.bytes;
    entry.summary = program ? ShareLogEntriesTr::tr("Other program: %1").arg(meaning)
                            : ShareLogEntriesTr::tr("ServoBench (shared bus): %1").arg(meaning);
    return entry;
}

} // namespace share
