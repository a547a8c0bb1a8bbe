// Reads the client's baud rate from a pty with TCGETS2 (kept apart: <asm/termbits.h> and
// <termios.h> cannot share a translation unit).
#include "ptybaud.h"

#if defined(Q_OS_LINUX)
#include <asm/termbits.h>
#include <sys/ioctl.h>
#endif

namespace seriallink {

qint32 readSlaveBaudRate(int masterFd)
{
#if defined(Q_OS_LINUX)
    struct termios2 settings
    {
    };
    if (::ioctl(masterFd, TCGETS2, &settings) != 0)
        return 0;
    return qint32(settings.c_ospeed);
#else
    Q_UNUSED(masterFd);
    return 0;
#endif
}

} // namespace seriallink
