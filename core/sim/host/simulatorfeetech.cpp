// The simulator's Feetech side: building the bus from --servo specs and its --state file, a
// --robot arm set up from its template, and the hand's --hand sweeps.
#include "simulatorfeetech.h"
#include "servosimtr.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QHash>

namespace sim {

namespace {

// Where an SO-100/SO-101 arm's horns rest when it lies folded, in present positions; a joint
// the table does not name rests at the middle.
int restPosition(const QString &joint)
{
    static const QHash<QString, int> kRest {
        {QStringLiteral("shoulder_pan"), 2048}, {QStringLiteral("shoulder_lift"), 890},
        {QStringLiteral("elbow_flex"), 3070},   {QStringLiteral("wrist_flex"), 2830},
        {QStringLiteral("wrist_roll"), 2048},   {QStringLiteral("gripper"), 2030}};
    return kRest.value(joint, 2048);
}

// The first servos are the robot's joints: each gets the template's settings as a set-up would
// have written them, and its horn at rest.
void setUpRobot(VirtualFeetechBus &bus, const feetech::RobotTemplate &robot, bool eepromLoaded)
{
    for (int i = 0; i < robot.joints.size() && i < bus.servoCount(); ++i) {
        const feetech::RobotJoint &joint = robot.joints.at(i);
        VirtualFeetechServo &servo = bus.servo(i);
        if (!eepromLoaded) {
            for (auto setting = joint.settings.cbegin(); setting != joint.settings.cend();
                 ++setting)
                servo.storeValue(setting.key(), setting.value());
            for (auto bits = joint.clearedBits.cbegin(); bits != joint.clearedBits.cend(); ++bits)
                servo.storeValue(bits.key(),
                                 qint32(quint32(servo.value(bits.key())) & ~bits.value()));
        }
        servo.setPhysicalPosition(restPosition(joint.name) + servo.value(u"position_offset"));
    }
}

} // namespace

std::unique_ptr<VirtualFeetechBus> createFeetechBus(const SimulatorOptions &options, QString *error)
{
    const auto sharing = options.allowSharedIds ? VirtualFeetechBus::SharedIds::Allow
                                                : VirtualFeetechBus::SharedIds::Refuse;
    SimRefusal why;
    auto bus = VirtualFeetechBus::create(options.servos, &why, sharing);
    if (!bus) {
        if (error) {
            *error = why.describe();
            if (!options.allowSharedIds
                && VirtualFeetechBus::validate(options.servos, nullptr,
                                               VirtualFeetechBus::SharedIds::Allow))
                *error += ServosimTr::tr(
                    " (--allow-shared-ids lets them share it, their replies colliding)");
        }
        return nullptr;
    }
    bool loaded = false;
    if (!options.statePath.isEmpty()) {
        // A missing file is a first run; anything else must load cleanly.
        if (QFileInfo::exists(options.statePath)) {
            if (!bus->loadState(options.statePath, &why)) {
                if (error)
                    *error = why.describe();
                return nullptr;
            }
            loaded = true;
        }
    }
    // Watched before the set-up, so that a first run's set-up arm reaches the file.
    if (!options.statePath.isEmpty())
        bus->setStatePath(options.statePath);
    if (options.robot)
        setUpRobot(*bus, *options.robot, loaded);
    for (const HandSweep &sweep : options.sweeps) {
        SimRefusal refusal;
        if (!bus->hand().sweep(sweep.id, sweep.from, sweep.to, sweep.seconds, sweep.cycles,
                               sweep.way, &refusal)) {
            if (error)
                *error =
                    ServosimTr::tr("--hand for ID %1: %2").arg(sweep.id).arg(refusal.describe());
            return nullptr;
        }
    }
    return bus;
}

} // namespace sim
