// For bench_startup: reports when the main window is first on screen, and the memory then.
#pragma once

#include <QObject>

class QWidget;

// When the environment variable SERVOBENCH_STARTUP_PROBE is set, watches `window` and, once its
// first expose has been handled (the first frame painted), prints one JSON line to standard
// output and quits the application:
//   {"first_frame_monotonic_ns": N, "resident_mb": R, "peak_resident_mb": P, "platform": "..."}
// The time is CLOCK_MONOTONIC, shared by every process, so the launcher (bench/bench_startup)
// subtracts the moment it started the process. Without the variable nothing is installed.
// Call it right after show(): the first expose arrives from the event loop.
class StartupProbe : public QObject
{
    Q_OBJECT

public:
    static void watchIfAsked(QWidget &window);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    using QObject::QObject;
    void report();

    bool m_reported = false;
};
