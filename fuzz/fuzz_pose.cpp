// Fuzz target: a pose file; a pose read is written and read back unchanged.
#include "feetechpacket.h"
#include "fuzztarget.h"
#include "pose.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    util::FileError error;
    const auto pose = feetech::poseFromJson(fuzz::input(data, size), &error);
    if (!pose) {
        FUZZ_CHECK(error && !error.describe().isEmpty());
        return 0;
    }
    for (const feetech::PoseEntry &entry : pose->servos) {
        FUZZ_CHECK(entry.id <= feetech::kMaxServoId);
        FUZZ_CHECK(std::abs(entry.position) <= feetech::kPoseMaxMagnitude);
        FUZZ_CHECK(pose->find(entry.address()) == &entry); // no servo twice
    }
    const auto reread = feetech::poseFromJson(feetech::poseToJson(*pose), &error);
    FUZZ_CHECK(reread == pose);
    return 0;
}
