// The system's serial ports, listed again when /dev changes (and on a slow poll besides).
#include "serialportwatcher.h"

#include <QCoreApplication>
#include <QFileSystemWatcher>
#include <QPointer>
#include <QTimer>

namespace {

// Long enough for a plugged adapter's node and its /dev/serial links to be made.
constexpr int kSettleMs = 300;
// Where /dev is watched, a safety net only; where it is not, what finds a plugged adapter.
constexpr int kWatchedPollMs = 30000;
constexpr int kUnwatchedPollMs = 3000;

} // namespace

SerialPortWatcher &SerialPortWatcher::shared()
{
    static QPointer<SerialPortWatcher> watcher;
    if (!watcher)
        watcher = new SerialPortWatcher(QStringLiteral("/dev"), QCoreApplication::instance());
    return *watcher;
}

SerialPortWatcher::SerialPortWatcher(const QString &devices, QObject *parent)
    : QObject(parent)
    , m_devices(new QFileSystemWatcher(this))
    , m_settle(new QTimer(this))
    , m_poll(new QTimer(this))
{
    m_settle->setSingleShot(true);
    m_settle->setInterval(kSettleMs);
    connect(m_settle, &QTimer::timeout, this, &SerialPortWatcher::rescan);
    const bool watched = m_devices->addPath(devices);
    connect(m_devices, &QFileSystemWatcher::directoryChanged, m_settle,
            qOverload<>(&QTimer::start));
    m_poll->setInterval(watched ? kWatchedPollMs : kUnwatchedPollMs);
    connect(m_poll, &QTimer::timeout, this, &SerialPortWatcher::rescan);
    m_poll->start();
    m_ports = availableSerialPorts();
    ++m_listings;
}

void SerialPortWatcher::rescan()
{
    QVector<SerialPort> ports = availableSerialPorts();
    ++m_listings;
    if (ports == m_ports)
        return;
    m_ports = std::move(ports);
    emit portsChanged(m_ports);
}
