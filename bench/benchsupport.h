// Shared pieces of the benchmark programs: waiting on the event loop and wire-time arithmetic.
#pragma once

#include <QEventLoop>
#include <QTimer>

#include <ctime>

namespace bench {

inline double wireMs(qint64 bytes, qint32 baud)
{
    return double(bytes) * 10e3 / baud; // 8N1: ten bit times a byte
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
