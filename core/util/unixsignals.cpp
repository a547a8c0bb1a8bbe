// Signal plumbing for servosim and servoctl: a self-pipe on Unix, a polled flag elsewhere.
#include "unixsignals.h"

#include <QSocketNotifier>
#include <QTimer>

#include <csignal>

#ifdef Q_OS_UNIX
#include <sys/socket.h>
#include <unistd.h>
#endif

namespace util {

namespace {

#ifdef Q_OS_UNIX
int g_socketPair[2] = {-1, -1};

void handleSignal(int signalNumber)
{
    const char byte = char(signalNumber);
    [[maybe_unused]] const ssize_t written = ::write(g_socketPair[0], &byte, 1);
}
#else
volatile std::sig_atomic_t g_caught = 0;

void handleSignal(int signalNumber)
{
    g_caught = signalNumber;
    std::signal(signalNumber, handleSignal); // some C runtimes reset the handler
}
#endif

} // namespace

UnixSignalWatcher::UnixSignalWatcher(QObject *parent)
    : QObject(parent)
{
#ifdef Q_OS_UNIX
    if (g_socketPair[0] < 0
        && ::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, g_socketPair) != 0)
        return;
    m_notifier = new QSocketNotifier(g_socketPair[1], QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &UnixSignalWatcher::readSignals);
#else
    m_poll = new QTimer(this);
    m_poll->setInterval(50);
    connect(m_poll, &QTimer::timeout, this, &UnixSignalWatcher::readSignals);
#endif
}

UnixSignalWatcher::~UnixSignalWatcher() = default;

bool UnixSignalWatcher::watch(int signalNumber)
{
#ifdef Q_OS_UNIX
    if (!m_notifier)
        return false;
    struct sigaction action
    {
    };
    action.sa_handler = handleSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    return ::sigaction(signalNumber, &action, nullptr) == 0;
#else
    if (std::signal(signalNumber, handleSignal) == SIG_ERR)
        return false;
    m_poll->start();
    return true;
#endif
}

void UnixSignalWatcher::readSignals()
{
#ifdef Q_OS_UNIX
    char byte = 0;
    if (::read(g_socketPair[1], &byte, 1) == 1)
        emit received(int(byte));
#else
    if (const int caught = g_caught) {
        g_caught = 0;
        emit received(caught);
    }
#endif
}

} // namespace util
