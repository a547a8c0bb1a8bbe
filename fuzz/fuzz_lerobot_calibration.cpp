// Fuzz target: a LeRobot calibration file (what servoctl's and the GUI's calibration load
// read); motors read are within the documented bounds and are written and read back unchanged.
#include "fuzztarget.h"
#include "lerobotcalibration.h"

#include <QSet>

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    util::FileError error;
    const auto motors =
        feetech::leRobotCalibrationFromJson(fuzz::input(data, size), source, &error);
    if (!motors) {
        FUZZ_CHECK(error && error.describe().contains(source));
        return 0;
    }
    FUZZ_CHECK(!motors->isEmpty());
    QSet<int> ids;
    QSet<QString> names;
    for (const feetech::LeRobotMotor &motor : *motors) {
        FUZZ_CHECK(feetech::isLeRobotMotorName(motor.name));
        FUZZ_CHECK(std::abs(motor.homingOffset) <= feetech::kLeRobotMaximumOffset);
        FUZZ_CHECK(motor.rangeMin >= 0 && motor.rangeMin < motor.rangeMax);
        FUZZ_CHECK(motor.rangeMax <= feetech::kLeRobotLargestLimit);
        ids.insert(motor.id);
        names.insert(motor.name);
    }
    FUZZ_CHECK(ids.size() == motors->size());
    FUZZ_CHECK(names.size() == motors->size());

    const QByteArray written = feetech::leRobotCalibrationToJson(*motors);
    const auto reread = feetech::leRobotCalibrationFromJson(written, source, &error);
    FUZZ_CHECK(reread.has_value());
    FUZZ_CHECK(feetech::leRobotCalibrationToJson(*reread) == written);
    return 0;
}
