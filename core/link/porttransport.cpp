// Which transport opens a port: the in-process one for this program's own simulated ports.
#include "porttransport.h"

#include "inprocessport.h"
#include "inprocesstransport.h"
#include "serialtransport.h"

namespace seriallink {

PortTransport *PortTransport::forPort(const QString &portName, QObject *parent)
{
    if (InProcessPort::isKnown(portName))
        return new InProcessTransport(parent);
    return new SerialTransport(parent);
}

} // namespace seriallink
