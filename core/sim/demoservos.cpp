// Demo servos: lazily started in-process simulators behind pseudo-terminals.
#include "sim/demoservos.h"

#include <QCoreApplication>
#include <QDir>

namespace sim {

DemoServos::~DemoServos()
{
    if (m_ptk)
        m_ptk->stop();
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

} // namespace sim
