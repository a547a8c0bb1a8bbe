// Demo servos: lazily started simulators, each offered as a port inside this program.
#include "demoservos.h"

#include <QCoreApplication>
#include <QDir>

namespace {

struct DemoServosTr
{
    Q_DECLARE_TR_FUNCTIONS(DemoServos)
};

} // namespace

namespace sim {

DemoServos::~DemoServos()
{
    if (m_ptk)
        m_ptk->stop();
    if (m_feetech)
        m_feetech->stop();
    if (m_arm)
        m_arm->stop();
    if (m_leaderArm)
        m_leaderArm->stop();
}

bool DemoServos::ensureFolder(SimRefusal *why)
{
    if (m_folder)
        return true;
    m_folder = std::make_unique<QTemporaryDir>(QDir::tempPath()
                                               + QStringLiteral("/servobench-demo-XXXXXX"));
    if (m_folder->isValid())
        return true;
    const QString reason = m_folder->errorString();
    m_folder.reset();
    return !refused(SimRefusal(SimRefusal::Code::NoDemoFolder, 0, 0, reason), why);
}

QString DemoServos::start(std::unique_ptr<SimulatorThread> &slot, const SimulatorOptions &options,
                          SimRefusal *why)
{
    auto simulator = std::make_unique<SimulatorThread>();
    QString reason;
    SimulatorOptions inProcess = options;
    // Reached by queued calls between the link's thread and the simulator's: a pseudo-terminal
    // would put the kernel's worker between them, which a busy window starves of the CPU.
    inProcess.inProcess = true;
    if (!simulator->start(inProcess, &reason)) {
        refused(SimRefusal(SimRefusal::Code::DemoNotStarted, 0, 0, reason), why);
        return QString();
    }
    slot = std::move(simulator);
    return slot->linkPath();
}

QString DemoServos::ptkPort(SimRefusal *why)
{
    if (m_ptk)
        return m_ptk->linkPath();
    if (!ensureFolder(why))
        return QString();
    SimulatorOptions options;
    options.kind = SimulatorOptions::Kind::Ptk;
    options.linkPath = DemoServosTr::tr("Simulated PTK servo");
    // A single-wire adapter, like PTK's own programmer.
    options.echo = true;
    return start(m_ptk, options, why);
}

QString DemoServos::startFeetech(std::unique_ptr<SimulatorThread> &slot, SimulatorOptions options,
                                 const QString &name, const QString &portName, SimRefusal *why)
{
    if (slot)
        return slot->linkPath();
    if (!ensureFolder(why))
        return QString();
    options.kind = SimulatorOptions::Kind::Feetech;
    options.linkPath = portName;
    // The EEPROM lives in the demo folder for as long as the program runs.
    options.statePath = m_folder->filePath(name + QStringLiteral(".json"));
    return start(slot, options, why);
}

QString DemoServos::feetechPort(SimRefusal *why)
{
    // A robot arm's bus: three STS3215 joints, an SCS15 gripper and an HLS wrist, all at the
    // STS default rate.
    SimulatorOptions options;
    options.servos = {{1, QStringLiteral("STS3215"), 1000000},
                      {2, QStringLiteral("STS3215"), 1000000},
                      {3, QStringLiteral("STS3215"), 1000000},
                      {4, QStringLiteral("SCS15"), 1000000},
                      {5, QStringLiteral("HLS"), 1000000}};
    return startFeetech(m_feetech, options, QStringLiteral("feetech-bus"),
                        DemoServosTr::tr("Simulated Feetech bus"), why);
}

QString DemoServos::armPort(SimRefusal *why)
{
    return startArm(m_arm, QStringLiteral("so101"), QStringLiteral("so101-arm"),
                    DemoServosTr::tr("Simulated SO-101 arm"), {}, why);
}

QString DemoServos::leaderArmPort(SimRefusal *why)
{
    // A hand that never tires, so the follower has something to follow.
    const QVector<HandSweep> sweeps = {{3, 1500, 2600, 4.0, 0, Hand::Way::Direct},
                                       {4, 1700, 2400, 3.0, 0, Hand::Way::Direct}};
    return startArm(m_leaderArm, QStringLiteral("so101-leader"), QStringLiteral("so101-leader"),
                    DemoServosTr::tr("Simulated SO-101 leader arm"), sweeps, why);
}

QString DemoServos::startArm(std::unique_ptr<SimulatorThread> &slot, const QString &robot,
                             const QString &name, const QString &portName,
                             const QVector<HandSweep> &sweeps, SimRefusal *why)
{
    if (slot)
        return slot->linkPath();
    SimulatorOptions options;
    OptionError notLoaded;
    options.robot = simulatedRobot(robot, &notLoaded);
    if (!options.robot) {
        refused(SimRefusal(SimRefusal::Code::NoDemoRobot, 0, 0, notLoaded.describe()), why);
        return QString();
    }
    options.servos = robotServos(*options.robot);
    options.sweeps = sweeps;
    return startFeetech(slot, options, name, portName, why);
}

} // namespace sim
