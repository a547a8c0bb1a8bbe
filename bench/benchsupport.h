// Shared pieces of the benchmark programs: waiting on the event loop and wire-time arithmetic.
#pragma once

#include "sim/simulator.h"

#include <QEventLoop>
#include <QTemporaryDir>
#include <QTimer>

#include <ctime>

namespace bench {

inline double wireMs(qint64 bytes, qint32 baud)
{
    return double(bytes) * 10e3 / baud; // 8N1: ten bit times a byte
}

// A simulated Feetech bus in `dir` with STS3215 servos at IDs 1..count, all at `baud`.
inline sim::SimulatorOptions stsBusOptions(const QTemporaryDir &dir, int count, qint32 baud)
{
    sim::SimulatorOptions options;
    options.kind = sim::SimulatorOptions::Kind::Feetech;
    options.linkPath = dir.filePath(QStringLiteral("bus"));
    for (int id = 1; id <= count; ++id)
        options.servos.append({quint8(id), QStringLiteral("STS3215"), baud});
    return options;
}

// Runs the event loop until finish() is called or the time is up; never busy-waits.
class Waiter
{
public:
    void finish()
    {
        m_done = true;
        m_loop.quit();
    }
    bool wait(int timeoutMs)
    {
        if (!m_done) {
            QTimer::singleShot(timeoutMs, &m_loop, &QEventLoop::quit);
            m_loop.exec();
        }
        return m_done;
    }

private:
    QEventLoop m_loop;
    bool m_done = false;
};

// CPU time (user + system) used so far, in milliseconds.
inline double threadCpuMs()
{
    timespec now {};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1e3 + double(now.tv_nsec) / 1e6;
}

inline double processCpuMs()
{
    timespec now {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return double(now.tv_sec) * 1e3 + double(now.tv_nsec) / 1e6;
}

} // namespace bench
