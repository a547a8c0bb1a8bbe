// Fuzz target: the PTK stream format through the framer; every frame is a request or a reply
// that re-encodes to its own bytes.
#include "framercheck.h"
#include "ptkframe.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    static const ptk::FrameFormat format;
    fuzz::checkFramer(format, data, size, [](const QByteArray &frame) {
        if (frame.size() == ptk::kRequestSize) {
            const auto request = ptk::decodeRequest(frame);
            return request && ptk::encodeRequest(*request) == frame;
        }
        const auto reply = ptk::decodeReply(frame);
        return reply && ptk::encodeReply(*reply) == frame;
    });
    return 0;
}
