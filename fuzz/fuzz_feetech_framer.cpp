// Fuzz target: the Feetech stream format through the framer; every frame decodes and re-encodes
// to its own bytes.
#include "feetechpacket.h"
#include "framercheck.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    static const feetech::FrameFormat format;
    fuzz::checkFramer(format, data, size, [](const QByteArray &frame) {
        const auto packet = feetech::decodePacket(frame);
        return packet
            && feetech::encodePacket(packet->id, packet->code, packet->parameters) == frame;
    });
    return 0;
}
