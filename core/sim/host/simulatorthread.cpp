// A simulator's thread: started with it, the simulator stopped in it before it ends.
#include "simulatorthread.h"

namespace sim {

SimulatorThread::~SimulatorThread()
{
    stop();
}

bool SimulatorThread::start(const SimulatorOptions &options, QString *error)
{
    stop();
    m_simulator = Simulator::create(options, error);
    if (!m_simulator)
        return false;
    m_thread.setObjectName(QStringLiteral("simulator"));
    m_simulator->moveToThread(&m_thread);
    m_thread.start();
    bool started = false;
    QString startError;
    QMetaObject::invokeMethod(
        m_simulator.get(), [&] { started = m_simulator->start(&startError); },
        Qt::BlockingQueuedConnection);
    if (!started) {
        if (error)
            *error = startError;
        stop();
        return false;
    }
    m_linkPath = m_simulator->linkPath();
    return true;
}

void SimulatorThread::stop()
{
    if (!m_simulator)
        return;
    if (m_thread.isRunning()) {
        QMetaObject::invokeMethod(
            m_simulator.get(), [this] { m_simulator->stop(); }, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }
    m_simulator.reset();
    m_linkPath.clear();
}

void SimulatorThread::call(const std::function<void(Simulator &)> &work)
{
    if (!m_simulator)
        return;
    QMetaObject::invokeMethod(
        m_simulator.get(), [&] { work(*m_simulator); }, Qt::BlockingQueuedConnection);
}

} // namespace sim
