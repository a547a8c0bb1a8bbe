// Shared pieces of the benchmark programs: waiting on the event loop, wire-time arithmetic and a
// timed telemetry stream.
#pragma once

#include "feetechsession.h"
#include "simulatorthread.h"

#include <QElapsedTimer>

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

// What one telemetry stream of a set length did.
struct StreamRun
{
    double rateHz = 0; // 0: as fast as the bus allows
    double seconds = 0;
    qint64 samples = 0;
    qint64 cycles = 0;
    qint64 missed = 0;
    qint64 late = 0;
    double cpuMs = 0; // of the thread the session runs in
};

// Streams the servos' feedback at `rateHz` for `seconds` and counts what came.
inline StreamRun streamTelemetry(feetech::Session &session,
                                 const QVector<feetech::ServoInfo> &servos, double rateHz,
                                 int seconds)
{
    StreamRun run;
    run.rateHz = rateHz;
    feetech::TelemetryStats last;
    qint64 samples = 0;
    const auto gotSamples = QObject::connect(
        &session, &feetech::Session::telemetry,
        [&samples](const QVector<feetech::FeedbackSample> &batch) { samples += batch.size(); });
    const auto gotStats = QObject::connect(&session, &feetech::Session::telemetryStats,
                                           [&last](const feetech::TelemetryStats &s) { last = s; });
    feetech::TelemetryOptions options;
    options.servos = servos;
    options.rateHz = rateHz;
    const double cpuBefore = threadCpuMs();
    QElapsedTimer clock;
    clock.start();
    session.startTelemetry(options);
    Waiter().wait(seconds * 1000);
    session.stopTelemetry();
    run.seconds = double(clock.nsecsElapsed()) / 1e9;
    run.cpuMs = threadCpuMs() - cpuBefore;
    run.samples = samples;
    run.cycles = last.cycles;
    run.missed = last.missed;
    run.late = last.late;
    QObject::disconnect(gotSamples);
    QObject::disconnect(gotStats);
    return run;
}

} // namespace bench
