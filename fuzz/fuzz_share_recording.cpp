// Fuzz target: a recording of a shared bus as servoctl decode --log reads it back; every frame
// accepted has a time, a direction and bytes (a note, its text).
#include "fuzztarget.h"
#include "sharerecording.h"

#include <QTemporaryFile>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    QTemporaryFile file;
    if (!file.open())
        return 0;
    file.write(fuzz::input(data, size));
    file.close();
    util::FileError error;
    const auto frames = share::ShareRecording::load(file.fileName(), &error);
    if (!frames) {
        FUZZ_CHECK(error && !error.describe().isEmpty());
        return 0;
    }
    FUZZ_CHECK(!error);
    for (const share::RecordedFrame &frame : *frames) {
        FUZZ_CHECK(frame.timeUs >= 0);
        FUZZ_CHECK(frame.direction == share::FrameDirection::Note || !frame.bytes.isEmpty());
    }
    return 0;
}
