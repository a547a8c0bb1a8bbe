// Fuzz target: the settings file batch programming and `servoctl feetech load` read (a profile
// or a robot template); whatever it gives a servo is a writable register of that servo, in
// range, and a batch never copies a profile's offset.
#include "fuzztarget.h"
#include "modeltable.h"
#include "registertable.h"
#include "settingsfile.h"

namespace {

feetech::ServoInfo servoOf(const QString &modelName, quint8 id)
{
    feetech::ServoInfo servo;
    servo.id = id;
    servo.baud = 1000000;
    servo.model = *feetech::ModelTable::builtIn().findByName(modelName);
    servo.modelMajor = quint8(servo.model.major);
    servo.modelMinor = quint8(servo.model.minor);
    return servo;
}

void checkValues(const feetech::ServoInfo &servo,
                 const std::optional<QVector<model::WriteItem>> &values, const QString &error)
{
    if (!values) {
        FUZZ_CHECK(!error.isEmpty());
        return;
    }
    for (const model::WriteItem &item : *values) {
        const feetech::Register *reg = servo.table().find(item.key);
        FUZZ_CHECK(reg != nullptr);
        FUZZ_CHECK(reg->writable());
        FUZZ_CHECK(item.value >= reg->minimum && item.value <= reg->maximum);
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    util::FileError error;
    const auto file = feetech::SettingsFile::fromJson(fuzz::input(data, size), source, &error);
    if (!file) {
        FUZZ_CHECK(error && error.describe().contains(source));
        return 0;
    }
    FUZZ_CHECK(file->isTemplate() == file->robot().has_value());
    // One servo of each family, and each joint's own servo.
    QVector<feetech::ServoInfo> servos;
    for (const char *model : {"STS3215", "SCS009", "SM30BL", "HLSxx"})
        servos.append(servoOf(QLatin1String(model), 1));
    if (file->isTemplate()) {
        for (const feetech::RobotJoint &joint : file->robot()->joints)
            servos.append(servoOf(joint.model, quint8(joint.id)));
    }
    for (const feetech::ServoInfo &servo : servos) {
        QString why;
        checkValues(servo, file->valuesFor(servo, &why), why);
        QStringList leftOut;
        const auto batch = file->batchValuesFor(servo, &leftOut, &why);
        checkValues(servo, batch, why);
        if (batch && !file->isTemplate()) {
            for (const model::WriteItem &item : *batch)
                FUZZ_CHECK(item.key != QLatin1String("position_offset"));
        }
    }
    return 0;
}
