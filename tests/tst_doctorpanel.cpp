// Auto in the connection bar and the Doctor panel, against simulated buses over a pty: Auto
// opens the right workspace and scans the rates that answered; a short scan opens the Doctor
// panel by itself; a servo at an unexpected ID is moved from the panel.
#include "feetechbus.h"

#include "busclient.h"
#include "busdoctor.h"
#include "connectionbar.h"
#include "connectioncontroller.h"
#include "doctorpanel.h"
#include "feetechworkspace.h"
#include "mainwindow.h"
#include "ptkclient.h"
#include "ptkworkspace.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QStackedWidget>
#include <QTreeWidget>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k500k = 500000;

QStringList codesOf(const QVector<feetech::DoctorFinding> &findings)
{
    QStringList codes;
    for (const feetech::DoctorFinding &finding : findings)
        codes.append(finding.code);
    return codes;
}

} // namespace

class TestDoctorPanel : public testsupport::FeetechBusTest
{
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;

    void openWindow(const QVector<sim::FeetechServoSpec> &servos)
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(servos), &error), qPrintable(error));
        m_window = std::make_unique<MainWindow>();
        m_window->show();
    }

    QWidget *currentWorkspace() const
    {
        return m_window->findChild<QStackedWidget *>()->currentWidget();
    }

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // The window remembers the last connection's protocol: each case starts from Auto.
    void init() { QSettings().clear(); }

    void cleanup()
    {
        m_window.reset();
        m_simulator.reset();
        QSettings().remove(QStringLiteral("doctor"));
    }

    void autoIsTheDefaultProtocol()
    {
        ConnectionBar bar;
        QCOMPARE(bar.protocol(), ConnectionBar::Protocol::Auto);
        // The rate and the echo are found, not chosen: their boxes wait for a protocol.
        QVERIFY(!bar.findChild<QComboBox *>(QStringLiteral("baudCombo"))->isEnabled());
        bar.setProtocol(ConnectionBar::Protocol::Feetech);
        QVERIFY(bar.findChild<QComboBox *>(QStringLiteral("baudCombo"))->isEnabled());
        QCOMPARE(bar.baud(), k1M);
    }

    void autoOpensTheFeetechWorkspaceAndScansTheRatesThatAnswered()
    {
        openWindow({{1, QStringLiteral("STS3215"), k1M}, {4, QStringLiteral("STS3215"), k500k}});
        QSignalSpy scanned(m_window->feetechClient(), &feetech::BusClient::scanFinished);
        m_window->connectToPort(m_simulator->linkPath());
        QVERIFY(m_window->connection()->isDetecting());
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 60000);
        QCOMPARE(currentWorkspace(), m_window->feetechWorkspace());
        QCOMPARE(m_window->feetechWorkspace()->scanOptions().bauds, (QVector<qint32> {k1M, k500k}));
        QCOMPARE(m_window->feetechClient()->servos()->count(), 2);
        QVERIFY(m_window->feetechClient()->servos()->indexOf({4, k500k}) >= 0);
        // The choice stays Auto; the bar shows the rate the port was opened at.
        QCOMPARE(m_window->connectionBar()->protocol(), ConnectionBar::Protocol::Auto);
        QCOMPARE(m_window->connectionBar()->baud(), k1M);
        // A scan that found servos where none were expected yet keeps the doctor closed.
        QVERIFY(!m_window->doctorPanel()->isVisible());
    }

    void autoOpensThePtkWorkspaceForAPtkServoBehindAnEchoingAdapter()
    {
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Ptk;
        options.linkPath = m_dir.filePath(QStringLiteral("ptk"));
        options.echo = true;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        m_window = std::make_unique<MainWindow>();
        m_window->show();
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_COMPARE_WITH_TIMEOUT(m_window->ptkClient()->status().state,
                                  seriallink::ConnectionState::Connected, 30000);
        QCOMPARE(currentWorkspace(), m_window->ptkWorkspace());
        QCOMPARE(m_window->connectionBar()->echoMode(), seriallink::EchoMode::On);
        QCOMPARE(m_window->connectionBar()->baud(), 115200);
        QVERIFY(!m_window->feetechClient()->link()->isConnected());
    }

    void disconnectDuringTheProbeCancelsItAndConnectsNothing()
    {
        openWindow({{1, QStringLiteral("STS3215"), k1M}});
        m_window->connectToPort(m_simulator->linkPath());
        QVERIFY(m_window->connection()->isDetecting());
        auto *button =
            m_window->connectionBar()->findChild<QPushButton *>(QStringLiteral("connectButton"));
        QCOMPARE(button->text(), QStringLiteral("Disconnect"));
        QTest::mouseClick(button, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->connection()->isDetecting(), 30000);
        QCOMPARE(button->text(), QStringLiteral("Connect"));
        QVERIFY(!m_window->feetechClient()->link()->isConnected());
        QVERIFY(!m_window->ptkClient()->isConnected());
        QVERIFY(!m_window->doctorPanel()->isVisible());
    }

    void autoOnASilentPortOpensTheDoctorWithNoBytes()
    {
        openWindow({{1, QStringLiteral("STS3215"), k1M}});
        QVERIFY(testsupport::onSimulatedBus(
            *m_simulator, [](sim::VirtualFeetechBus &bus) { return bus.setPowered(0, false); }));
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->connection()->isDetecting(), 30000);
        QTRY_VERIFY(m_window->doctorPanel()->isVisible());
        QCOMPARE(codesOf(m_window->doctorPanel()->findings()),
                 QStringList {feetech::doctorcodes::kNoBytes});
        QCOMPARE(m_window->doctorPanel()->findingList()->topLevelItemCount(), 1);
        // The row leads with what the code means; the code stays, last and secondary.
        const QTreeWidgetItem *row = m_window->doctorPanel()->findingList()->topLevelItem(0);
        QCOMPARE(row->text(0), feetech::doctorTitle(feetech::doctorcodes::kNoBytes));
        QVERIFY(row->text(0) != feetech::doctorcodes::kNoBytes);
        QVERIFY(row->font(0).bold());
        QCOMPARE(row->text(2), m_window->doctorPanel()->findings().first().message);
        QCOMPARE(row->text(row->columnCount() - 1), feetech::doctorcodes::kNoBytes);
        QVERIFY(row->toolTip(0).contains(feetech::doctorcodes::kNoBytes));
        QVERIFY(!m_window->feetechClient()->link()->isConnected());
        QVERIFY(!m_window->ptkClient()->isConnected());
    }

    void aShortScanOpensTheDoctorPanelByItself()
    {
        openWindow({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k1M}});
        // The bus should hold an SO-101 arm: joints 1 to 6, at 1 Mbps.
        QComboBox *expectation = m_window->doctorPanel()->expectationBox();
        expectation->setCurrentIndex(
            expectation->findText(QStringLiteral("SO-101"), Qt::MatchStartsWith));
        QVERIFY(expectation->currentIndex() > 0);
        m_window->connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_VERIFY(m_window->feetechClient()->link()->isConnected());
        feetech::ScanOptions options;
        options.lastId = 10;
        m_window->feetechWorkspace()->startScan(options);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->doctorPanel()->isVisible(), 30000);
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->doctorPanel()->findings().isEmpty(), 30000);
        const auto findings = m_window->doctorPanel()->findings();
        QCOMPARE(codesOf(findings), QStringList {feetech::doctorcodes::kChainBreak});
        QCOMPARE(findings.first().ids, (QVector<int> {3, 4, 5, 6}));
        QVERIFY(findings.first().message.contains(QStringLiteral("after ID 2")));
        QCOMPARE(m_window->doctorPanel()->findingList()->topLevelItem(0)->text(0),
                 QStringLiteral("The chain is broken"));
    }

    void aServoAtAnUnexpectedIdIsMovedFromThePanel()
    {
        openWindow({{1, QStringLiteral("STS3215"), k1M}, {9, QStringLiteral("STS3215"), k1M}});
        // Last time this port held servos 1 and 2.
        feetech::ServoInfo one;
        one.id = 1;
        one.baud = k1M;
        feetech::ServoInfo two = one;
        two.id = 2;
        feetech::rememberServos(m_simulator->linkPath(), {one, two});
        m_window->connectionBar()->setProtocol(ConnectionBar::Protocol::Feetech);
        m_window->connectToPort(m_simulator->linkPath());
        QTRY_VERIFY(m_window->feetechClient()->link()->isConnected());
        feetech::ScanOptions options;
        options.lastId = 10;
        m_window->feetechWorkspace()->startScan(options);
        DoctorPanel *doctor = m_window->doctorPanel();
        QTRY_VERIFY_WITH_TIMEOUT(!doctor->findings().isEmpty(), 30000);
        QVERIFY(doctor->isVisible());
        const auto findings = doctor->findings();
        const int stray = int(codesOf(findings).indexOf(feetech::doctorcodes::kUnexpectedId));
        QVERIFY2(stray >= 0, qPrintable(codesOf(findings).join(u' ')));
        doctor->findingList()->setCurrentItem(doctor->findingList()->topLevelItem(stray));
        QVERIFY(doctor->moveButton()->isEnabled());
        QVERIFY(doctor->moveButton()->text().contains(QStringLiteral("ID 2")));
        doctor->moveSelected(false);
        // The move is verified by the guided flow, the bus scanned again, and the doctor is
        // satisfied.
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(2, u"id"), 2, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->feetechClient()->servos()->indexOf({2, k1M}) >= 0,
                                 30000);
        const QLabel *summary = doctor->findChild<QLabel *>(QStringLiteral("doctorSummary"));
        QTRY_VERIFY_WITH_TIMEOUT(
            summary->text().contains(QStringLiteral("holds what was expected")), 30000);
        QCOMPARE(doctor->findingList()->topLevelItemCount(), 0);
        QCOMPARE(m_window->feetechClient()->servos()->indexOf({9, k1M}), -1);
    }
};

QTEST_MAIN(TestDoctorPanel)
#include "tst_doctorpanel.moc"
