// The client's baud rate on a pseudo-terminal, read through its master side.
#pragma once

#include <QtGlobal>

namespace seriallink {

// TCGETS2 through the master: Linux answers a pty master's termios requests with the slave's
// settings, which are the ones the client set. Returns 0 when unavailable.
qint32 readSlaveBaudRate(int masterFd);

} // namespace seriallink
