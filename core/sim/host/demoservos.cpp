// Demo servos: lazily started in-process simulators behind pseudo-terminals.
#include "demoservos.h"

#include <QCoreApplication>
#include <QDir>

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

bool DemoServos::ensureFolder(QString *error)
{
    if (m_folder)
        return true;
    m_folder = std::make_unique<QTemporaryDir>(QDir::tempPath()
                                               + QStringLiteral("/servobench-demo-XXXXXX"));
    if (m_folder->isValid())
        return true;
    if (error)
        *error = QCoreApplication::translate("DemoServos",
                                             "Cannot create a folder for the simulated servos: %1")
                     .arg(m_folder->errorString());
    m_folder.reset();
    return false;
}

QString DemoServos::ptkPort(QString *error)
{
    if (m_ptk)
        return m_ptk->linkPath();
    if (!ensureFolder(error))
        return QString();
    SimulatorOptions options;
    options.kind = SimulatorOptions::Kind::Ptk;
    options.linkPath = m_folder->filePath(QStringLiteral("ptk-servo"));
    // A single-wire adapter, like PTK's own programmer.
    options.echo = true;
    auto simulator = std::make_unique<SimulatorThread>();
    if (!simulator->start(options, error))
        return QString();
    m_ptk = std::move(simulator);
    return m_ptk->linkPath();
}

QString DemoServos::startFeetech(std::unique_ptr<SimulatorThread> &slot, SimulatorOptions options,
                                 const QString &name, QString *error)
{
    if (slot)
        return slot->linkPath();
    if (!ensureFolder(error))
        return QString();
    options.kind = SimulatorOptions::Kind::Feetech;
    options.linkPath = m_folder->filePath(name);
    // The EEPROM lives in the demo folder for as long as the program runs.
    options.statePath = m_folder->filePath(name + QStringLiteral(".json"));
    auto simulator = std::make_unique<SimulatorThread>();
    if (!simulator->start(options, error))
        return QString();
    slot = std::move(simulator);
    return slot->linkPath();
}

QString DemoServos::feetechPort(QString *error)
{
    // A robot arm's bus: three STS3215 joints, an SCS15 gripper and an HLS wrist, all at the
    // STS default rate.
    SimulatorOptions options;
    options.servos = {{1, QStringLiteral("STS3215"), 1000000},
                      {2, QStringLiteral("STS3215"), 1000000},
                      {3, QStringLiteral("STS3215"), 1000000},
                      {4, QStringLiteral("SCS15"), 1000000},
                      {5, QStringLiteral("HLS"), 1000000}};
    return startFeetech(m_feetech, options, QStringLiteral("feetech-bus"), error);
}

QString DemoServos::armPort(QString *error)
{
    return startArm(m_arm, QStringLiteral("so101"), QStringLiteral("so101-arm"), {}, error);
}

QString DemoServos::leaderArmPort(QString *error)
{
    // A hand that never tires, so the follower has something to follow.
    const QVector<HandSweep> sweeps = {{3, 1500, 2600, 4.0, 0, Hand::Way::Direct},
                                       {4, 1700, 2400, 3.0, 0, Hand::Way::Direct}};
    return startArm(m_leaderArm, QStringLiteral("so101-leader"), QStringLiteral("so101-leader"),
                    sweeps, error);
}

QString DemoServos::startArm(std::unique_ptr<SimulatorThread> &slot, const QString &robot,
                             const QString &name, const QVector<HandSweep> &sweeps, QString *error)
{
    SimulatorOptions options;
    OptionError why;
    options.robot = simulatedRobot(robot, &why);
    if (!options.robot) {
        if (error)
            *error = why.describe();
        return QString();
    }
    options.servos = robotServos(*options.robot);
    options.sweeps = sweeps;
    return startFeetech(slot, options, name, error);
}

} // namespace sim
