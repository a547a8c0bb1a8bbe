// Fuzz target: a robot template as a user's file is read; a template accepted names known models
// with settings inside their registers' ranges, and is written and read back unchanged.
#include "fuzztarget.h"
#include "modeltable.h"
#include "registertable.h"
#include "robottemplate.h"

#include <QSet>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QString source = QStringLiteral("fuzz.json");
    util::FileError error;
    const auto robot = feetech::robotTemplateFromJson(fuzz::input(data, size), source, &error);
    if (!robot) {
        FUZZ_CHECK(error && error.describe().contains(source));
        return 0;
    }
    QSet<int> ids;
    QSet<QString> names;
    for (const feetech::RobotJoint &joint : robot->joints) {
        ids.insert(joint.id);
        names.insert(joint.name);
        FUZZ_CHECK(joint.id >= 0 && joint.id <= feetech::kMaxServoId);
        FUZZ_CHECK(robot->joint(joint.name) == &joint);
        const auto model = feetech::ModelTable::builtIn().findByName(joint.model);
        FUZZ_CHECK(model.has_value() && model->family.has_value());
        const feetech::RegisterTable &table = feetech::RegisterTable::forFamily(*model->family);
        for (auto it = joint.settings.cbegin(); it != joint.settings.cend(); ++it) {
            const feetech::Register *reg = table.find(it.key());
            FUZZ_CHECK(reg != nullptr && reg->writable());
            FUZZ_CHECK(it.value() >= reg->minimum && it.value() <= reg->maximum);
        }
    }
    FUZZ_CHECK(ids.size() == robot->joints.size());
    FUZZ_CHECK(names.size() == robot->joints.size());

    const QByteArray written = feetech::robotTemplateToJson(*robot);
    const auto reread = feetech::robotTemplateFromJson(written, source, &error);
    FUZZ_CHECK(reread.has_value());
    FUZZ_CHECK(feetech::robotTemplateToJson(*reread) == written);
    return 0;
}
