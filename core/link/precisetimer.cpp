// Microsecond single-shot timer: a timerfd watched by the event loop, a QTimer elsewhere.
#include "precisetimer.h"

#include <QSocketNotifier>
#include <QTimer>

#ifdef Q_OS_LINUX
#include <sys/timerfd.h>
#include <unistd.h>
#endif

#include <algorithm>

namespace seriallink {

PreciseTimer::PreciseTimer(QObject *parent)
    : QObject(parent)
{
#ifdef Q_OS_LINUX
    m_descriptor = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_descriptor >= 0) {
        m_notifier = new QSocketNotifier(m_descriptor, QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, [this] {
            quint64 expirations = 0;
            if (::read(m_descriptor, &expirations, sizeof expirations) == sizeof expirations)
                expired();
        });
        return;
    }
#endif
    m_fallback = new QTimer(this);
    m_fallback->setSingleShot(true);
    m_fallback->setTimerType(Qt::PreciseTimer);
    connect(m_fallback, &QTimer::timeout, this, &PreciseTimer::expired);
}

PreciseTimer::~PreciseTimer()
{
#ifdef Q_OS_LINUX
    delete m_notifier;
    if (m_descriptor >= 0)
        ::close(m_descriptor);
#endif
}

void PreciseTimer::start(std::chrono::microseconds delay, std::function<void()> fire)
{
    m_fire = std::move(fire);
    // Zero would disarm a timerfd: the shortest wait is one microsecond.
    const qint64 us = std::max<qint64>(1, delay.count());
#ifdef Q_OS_LINUX
    if (m_descriptor >= 0) {
        itimerspec spec {};
        spec.it_value.tv_sec = time_t(us / 1'000'000);
        spec.it_value.tv_nsec = long(us % 1'000'000) * 1000;
        ::timerfd_settime(m_descriptor, 0, &spec, nullptr);
        return;
    }
#endif
    m_fallback->start(int((us + 999) / 1000));
}

void PreciseTimer::stop()
{
    m_fire = nullptr;
#ifdef Q_OS_LINUX
    if (m_descriptor >= 0) {
        const itimerspec disarmed {};
        ::timerfd_settime(m_descriptor, 0, &disarmed, nullptr);
        return;
    }
#endif
    m_fallback->stop();
}

void PreciseTimer::expired()
{
    // Taken first: the callback may start the timer again.
    std::function<void()> fire = std::move(m_fire);
    m_fire = nullptr;
    if (fire)
        fire();
}

} // namespace seriallink
