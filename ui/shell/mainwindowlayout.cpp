// The main window's memory: its size and dock layout, the last connection's settings and the
// recent profiles (QSettings), and View > Reset layout.
#include "connectionbar.h"
#include "feetechworkspace.h"
#include "mainwindow.h"
#include "packetlogdock.h"
#include "ptkworkspace.h"
#include "recentfiles.h"

#include <QDir>
#include <QMenu>
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

void MainWindow::restoreRemembered()
{
    const QSettings settings;
    // A saved geometry off every screen now (a monitor unplugged) is moved back by Qt.
    restoreGeometry(settings.value(QLatin1String(kGeometryKey)).toByteArray());
    restoreState(settings.value(QLatin1String(kLayoutKey)).toByteArray());
    const QString protocol = settings.value(QLatin1String(kProtocolKey)).toString();
    for (const auto known : {ConnectionBar::Protocol::Ptk, ConnectionBar::Protocol::Feetech,
                             ConnectionBar::Protocol::Auto}) {
        if (protocol == protocolKey(known))
            m_connectionBar->setProtocol(known); // before the rate: it offers its usual one
    }
    const qint32 baud = settings.value(QLatin1String(kBaudKey)).toInt();
    if (baud > 0)
        m_connectionBar->setBaud(baud);
    const QString port = settings.value(QLatin1String(kPortKey)).toString();
    if (!port.isEmpty())
        m_connectionBar->setPort(port);
}

void MainWindow::rememberLayout()
{
    QSettings settings;
    settings.setValue(QLatin1String(kGeometryKey), saveGeometry());
    settings.setValue(QLatin1String(kLayoutKey), saveState());
}

void MainWindow::rememberConnection()
{
    QSettings settings;
    settings.setValue(QLatin1String(kPortKey), m_connectionBar->port());
    settings.setValue(QLatin1String(kProtocolKey), protocolKey(m_connectionBar->protocol()));
    settings.setValue(QLatin1String(kBaudKey), m_connectionBar->baud());
}

void MainWindow::fillRecentProfiles(QMenu *menu)
{
    menu->clear();
    const QStringList files = recentfiles::list(recentfiles::Kind::Profile);
    for (const QString &path : files) {
        menu->addAction(QDir::toNativeSeparators(path), this, [this, path] {
            recentfiles::add(recentfiles::Kind::Profile, path);
            if (m_feetechActive)
                m_feetechWorkspace->loadProfile(path);
            else
                m_ptkWorkspace->loadProfile(path);
        });
    }
    if (files.isEmpty())
        menu->addAction(tr("No profile opened or saved yet"))->setEnabled(false);
}

void MainWindow::resetLayout()
{
    showNormal();
    restoreState(m_defaultLayout);
    resize(m_defaultSize);
    m_packetLog->show();
    m_connectionBar->show();
    QSettings settings;
    settings.remove(QLatin1String(kGeometryKey));
    settings.remove(QLatin1String(kLayoutKey));
}
