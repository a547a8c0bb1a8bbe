// The main window's memory in QSettings: geometry and dock layout under window/, the last
// connection's settings under connection/.
#include "windowmemory.h"

#include "connectionbar.h"

#include <QMainWindow>
#include <QSettings>

namespace {

constexpr char kGeometryKey[] = "window/geometry";
constexpr char kLayoutKey[] = "window/layout";
constexpr char kPortKey[] = "connection/port";
constexpr char kProtocolKey[] = "connection/protocol";
constexpr char kBaudKey[] = "connection/baud";

QString protocolKey(ConnectionBar::Protocol protocol)
{
    switch (protocol) {
    case ConnectionBar::Protocol::Ptk:
        return QStringLiteral("ptk");
    case ConnectionBar::Protocol::Feetech:
        return QStringLiteral("feetech");
    case ConnectionBar::Protocol::Auto:
        break;
    }
    return QStringLiteral("auto");
}

} // namespace

WindowMemory::WindowMemory(QMainWindow &window, ConnectionBar &connectionBar)
    : m_window(window)
    , m_connectionBar(connectionBar)
    , m_defaultLayout(window.saveState())
    , m_defaultSize(window.size())
{ }

void WindowMemory::restore()
{
    const QSettings settings;
    // A saved geometry off every screen now (a monitor unplugged) is moved back by Qt.
    m_window.restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray());
    m_window.restoreState(settings.value(QLatin1String(kLayoutKey)).toByteArray());
    const QString protocol = settings.value(QLatin1String(kProtocolKey)).toString();
    for (const auto known : {ConnectionBar::Protocol::Ptk, ConnectionBar::Protocol::Feetech,
                             ConnectionBar::Protocol::Auto}) {
        if (protocol == protocolKey(known))
            m_connectionBar.setProtocol(known); // before the rate: it offers its usual one
    }
    const qint32 baud = settings.value(QLatin1String(kBaudKey)).toInt();
    if (baud > 0)
        m_connectionBar.setBaud(baud);
    const QString port = settings.value(QLatin1String(kPortKey)).toString();
    if (!port.isEmpty())
        m_connectionBar.setPort(port);
}

void WindowMemory::rememberLayout()
{
    QSettings settings;
    settings.setValue(QLatin1String(kGeometryKey), m_window.saveGeometry());
    settings.setValue(QLatin1String(kLayoutKey), m_window.saveState());
}

void WindowMemory::rememberConnection()
{
    QSettings settings;
    settings.setValue(QLatin1String(kPortKey), m_connectionBar.port());
    settings.setValue(QLatin1String(kProtocolKey), protocolKey(m_connectionBar.protocol()));
    settings.setValue(QLatin1String(kBaudKey), m_connectionBar.baud());
}

void WindowMemory::resetLayout()
{
    m_window.showNormal();
    m_window.restoreState(m_defaultLayout);
    m_window.resize(m_defaultSize);
    QSettings settings;
    settings.remove(QLatin1String(kGeometryKey));
    settings.remove(QLatin1String(kLayoutKey));
}
