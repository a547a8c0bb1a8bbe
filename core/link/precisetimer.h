// A single-shot timer with microsecond resolution, for waits shorter than a millisecond.
#pragma once

#include <QObject>

#include <chrono>
#include <functional>

class QSocketNotifier;
class QTimer;

namespace seriallink {

// QTimer counts whole milliseconds, and a scan's wait for a missing ID at 1 Mbps is a fraction
// of one. On Linux this arms a timerfd the event loop watches like any other descriptor;
// elsewhere it falls back to a QTimer rounded up to the next millisecond. Starting it again
// replaces the pending shot; it lives in (and is used only from) the thread that owns it.
class PreciseTimer : public QObject
{
    Q_OBJECT

public:
    explicit PreciseTimer(QObject *parent = nullptr);
    ~PreciseTimer() override;

    void start(std::chrono::microseconds delay, std::function<void()> fire);
    void stop();

private:
    void expired();

    int m_descriptor = -1;
    QSocketNotifier *m_notifier = nullptr;
    QTimer *m_fallback = nullptr;
    std::function<void()> m_fire;
};

} // namespace seriallink
