// Which event loop a program's threads run: Qt's own rather than GLib's where nothing needs GLib.
#pragma once

namespace util {

enum class QtEventLoops {
    WorkerThreads, // the main thread keeps GLib's (a desktop's dialogs may need it): the GUI
    AllThreads // the command-line programs and the simulator
};

// Call before the application object is made. A thread that talks to a serial port waits on it
// hundreds of times a second, and QSerialPort switches the port's write notifier on and off for
// every frame it sends: GLib's loop wakes itself once more for each switch, Qt's own does not.
// What the user set in the environment (QT_NO_GLIB, QT_NO_THREADED_GLIB) is left alone.
void preferQtEventLoops(QtEventLoops threads);

} // namespace util
