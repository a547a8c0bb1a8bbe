// What the main window remembers between runs (QSettings): its size and dock layout, and the
// last connection's port, protocol and rate; and the layout it was first built with, for
// View > Reset layout.
#pragma once

#include <QByteArray>
#include <QSize>

class ConnectionBar;
class QMainWindow;

class WindowMemory
{
public:
    // Both outlive it. The window's layout as it is now is what Reset layout goes back to.
    WindowMemory(QMainWindow &window, ConnectionBar &connectionBar);

    // The remembered size, layout and connection settings, put back.
    void restore();
    void rememberLayout();
    void rememberConnection();
    // Back to the layout the window was first built with, which is remembered no longer.
    void resetLayout();

private:
    QMainWindow &m_window;
    ConnectionBar &m_connectionBar;
    QByteArray m_defaultLayout;
    QSize m_defaultSize;
};
