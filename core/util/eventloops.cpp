// Choosing Qt's own event loop over GLib's through the variables Qt reads when a thread starts.
#include "eventloops.h"

#include <QtGlobal>

namespace util {

void preferQtEventLoops(QtEventLoops threads)
{
    // Qt reads QT_NO_GLIB for the main thread and QT_NO_THREADED_GLIB for every other thread,
    // each time one starts.
    const char *variable =
        threads == QtEventLoops::AllThreads ? "QT_NO_GLIB" : "QT_NO_THREADED_GLIB";
    if (!qEnvironmentVariableIsSet(variable))
        qputenv(variable, "1");
}

} // namespace util
