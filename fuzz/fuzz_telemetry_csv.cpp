// Fuzz target: a telemetry recording (the CSV TelemetryRecorder writes) as parseTelemetryCsv
// reads it back; every row accepted is a sample of a servo ID with a status byte.
#include "feetechpacket.h"
#include "fuzztarget.h"
#include "telemetry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString text = QString::fromUtf8(fuzz::input(data, size));
    QString error;
    const auto samples = feetech::parseTelemetryCsv(text, &error);
    if (!samples) {
        FUZZ_CHECK(error.startsWith(QStringLiteral("Line ")));
        return 0;
    }
    FUZZ_CHECK(samples->size() < text.count(u'\n') + 1); // the header is no sample
    for (const feetech::CsvSample &sample : *samples) {
        FUZZ_CHECK(sample.id >= 0 && sample.id <= feetech::kMaxServoId);
        FUZZ_CHECK(sample.servoStatus >= 0 && sample.servoStatus <= 255);
    }
    return 0;
}
