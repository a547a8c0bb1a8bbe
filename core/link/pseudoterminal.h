// A pseudo-terminal whose slave side a client opens like a serial port, through a symlink.
#pragma once

#include "deviceport.h"

#include <QElapsedTimer>
#include <QTimer>

class QSocketNotifier;

namespace seriallink {

// The simulator or a shared bus holds the master side. A client (QSerialPort, a vendor SDK) opens
// the symlink. The slave is not kept open here, so the client's exclusive lock (TIOCEXCL) ends with
// its close and a later client can open it again; while no client has it open, the master reports
// a hang-up, which is handled by polling until a client returns.
class PseudoTerminal final : public DevicePort
{
    Q_OBJECT

public:
    explicit PseudoTerminal(QObject *parent = nullptr);
    ~PseudoTerminal() override;

    // Creates the pty and makes `linkPath` a symlink to its slave (replacing a stale symlink).
    bool open(const QString &linkPath, QString *error);
    void close() override;

    bool isOpen() const { return m_master >= 0; }
    QString slavePath() const { return m_slavePath; }
    QString linkPath() const { return m_linkPath; }
    QString portName() const override { return m_linkPath; }

    // The baud rate the client configured on its side (0 when it cannot be read).
    qint32 hostBaudRate() const override;

    void write(const QByteArray &bytes) override;

private:
    void readAvailable();
    void flushPending();

    int m_master = -1;
    QString m_slavePath;
    QString m_linkPath;
    QSocketNotifier *m_readNotifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr;
    QTimer m_hangupPoll {this}; // a child, so it moves threads with us
    QElapsedTimer m_hungUpSince; // since the last client let go (invalid while one is there)
    QByteArray m_pending; // bytes the pty buffer could not take yet
};

} // namespace seriallink
