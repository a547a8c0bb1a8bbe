// Turns Unix signals (SIGINT, SIGTERM, SIGHUP) into a Qt signal on the event loop.
#pragma once

#include <QObject>

class QSocketNotifier;

namespace util {

// Only async-signal-safe work happens in the handler: it writes the signal number to a socket
// pair, which a QSocketNotifier reads on the event loop.
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
};

} // namespace util
