// A transport that is a port: opened by its name, closed, its rate set. A serial port, or the
// simulated servos of this program reached without a pseudo-terminal.
#pragma once

#include "transport.h"

namespace seriallink {

class PortTransport : public Transport
{
    Q_OBJECT

public:
    using Transport::Transport;

    // The transport that opens `portName`: in-process for a port this program offers
    // (InProcessPort), a serial port for anything else.
    static PortTransport *forPort(const QString &portName, QObject *parent = nullptr);

    // On failure *error says why, in words for the user.
    virtual bool open(const QString &portName, qint32 baud, QString *error) = 0;
    virtual void close() = 0;
    virtual bool setBaudRate(qint32 baud) = 0;
    virtual QString portName() const = 0;
};

} // namespace seriallink
