// Turns process signals (SIGINT, SIGTERM; SIGHUP on Unix) into a Qt signal on the event loop.
#pragma once

#include <QObject>

class QSocketNotifier;
class QTimer;

namespace util {

// Only async-signal-safe work happens in the handler. On Unix it writes the signal number to a
// socket pair, which a QSocketNotifier reads on the event loop; elsewhere (Windows: Ctrl+C) it
// sets a flag that a timer on the event loop looks at every 50 ms.
class UnixSignalWatcher : public QObject
{
    Q_OBJECT

public:
    explicit UnixSignalWatcher(QObject *parent = nullptr);
    ~UnixSignalWatcher() override;

    bool watch(int signalNumber);

signals:
    void received(int signalNumber);

private:
    void readSignals();
    QSocketNotifier *m_notifier = nullptr;
    QTimer *m_poll = nullptr;
};

} // namespace util
