// Test support for GUI tests of the Feetech workspace: a main window on a simulated bus of two
// STS3215 and an SCS15 (IDs 1-3 at 1 Mbps), connected and scanned through the window.
#pragma once

#include "connectionbar.h"
#include "feetechbus.h"
#include "feetechworkspace.h"
#include "mainwindow.h"

#include <QSettings>
#include <QSignalSpy>
#include <QtTest>

#include <memory>

namespace testsupport {

class FeetechWindowTest : public FeetechBusTest
{
protected:
    std::unique_ptr<MainWindow> m_window;

    FeetechWorkspace *workspace() const { return m_window->feetechWorkspace(); }
    feetech::BusClient *client() const { return m_window->feetechClient(); }

    // For init(): the simulated bus and a main window showing, not yet connected.
    void openWindowOnBus()
    {
        QSettings().clear(); // nothing remembered from an earlier test (layout, port, choices)
        QString error;
        const auto servos = servosAt(1000000, {u"STS3215", u"STS3215", u"SCS15"});
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_window = std::make_unique<MainWindow>();
        m_window->show();
    }

    // For cleanup(): the window closes before the bus goes away.
    void closeWindow()
    {
        m_window.reset();
        m_simulator.reset();
    }

    // Connects the window's Feetech workspace and scans IDs 0 to `lastId`: three servos.
    void connectAndScanUpTo(int lastId)
    {
        m_window->connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_VERIFY(client()->link()->isConnected());
        feetech::ScanOptions options;
        options.lastId = lastId;
        QSignalSpy finished(client(), &feetech::BusClient::scanFinished);
        workspace()->startScan(options);
        QVERIFY(finished.wait(20000));
        QCOMPARE(client()->servos()->count(), 3);
    }
};

} // namespace testsupport
