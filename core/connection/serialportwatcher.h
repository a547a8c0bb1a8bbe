// The system's serial ports, listed again when the system says a device came or went, not on a
// timer: each listing walks sysfs (some 2,500 file opens on a desktop).
#pragma once

#include "serialports.h"

#include <QObject>

class QFileSystemWatcher;
class QTimer;

// Device nodes appear in and leave /dev as adapters are plugged and unplugged: a watch on it
// (inotify) is what wakes the watcher; a slow poll covers a system where /dev cannot be watched
// or a change that did not show there.
class SerialPortWatcher : public QObject
{
    Q_OBJECT

public:
    // The watcher every part of the window shares, made on first use in the GUI thread.
    static SerialPortWatcher &shared();

    // `devices`: where device nodes come and go.
    explicit SerialPortWatcher(const QString &devices = QStringLiteral("/dev"),
                               QObject *parent = nullptr);

    // The ports as last listed (listed once when the watcher is made).
    const QVector<SerialPort> &ports() const { return m_ports; }
    // Lists them now; portsChanged when they differ from the last listing.
    void rescan();
    // How many times the ports were listed: what the watcher costs.
    int listings() const { return m_listings; }

signals:
    void portsChanged(const QVector<SerialPort> &ports);

private:
    QFileSystemWatcher *m_devices = nullptr;
    QTimer *m_settle = nullptr; // a plug makes several nodes and links: listed once they are in
    QTimer *m_poll = nullptr;
    QVector<SerialPort> m_ports;
    int m_listings = 0;
};
