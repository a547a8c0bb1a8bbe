// ConnectionController without widgets, against simulated servos on pseudo-terminals: how a
// request becomes a connection (simulated ports, a protocol chosen by hand, Auto's probe), what
// it asks the window to show, and when the doctor is called.
#include "feetechbus.h"

#include "busdoctor.h"
#include "connectioncontroller.h"
#include "inprocessport.h"
#include "ptkclient.h"

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

class TestConnectionController : public testsupport::FeetechBusTest
{
    Q_OBJECT

    std::unique_ptr<ptk::Client> m_ptk;
    std::unique_ptr<feetech::BusClient> m_feetech;
    std::unique_ptr<ConnectionController> m_controller;

    ConnectionController::Request request(ConnectionController::Protocol protocol,
                                          qint32 baud = 0) const
    {
        ConnectionController::Request wanted;
        wanted.port = m_simulator->linkPath();
        wanted.protocol = protocol;
        wanted.baud = baud;
        return wanted;
    }

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void init()
    {
        QSettings().clear(); // nothing remembered of the servos on a port
        m_ptk = std::make_unique<ptk::Client>();
        m_feetech = std::make_unique<feetech::BusClient>();
        m_controller = std::make_unique<ConnectionController>(m_ptk.get(), m_feetech.get());
        // The scan a window would start from its workspace.
        connect(m_controller.get(), &ConnectionController::scanWanted, m_feetech.get(),
                [this](const feetech::ScanOptions &options) { m_feetech->scan(options); });
    }

    void cleanup()
    {
        // As in the window: the clients close their ports before the demo's servos stop.
        m_feetech.reset();
        m_ptk.reset();
        m_controller.reset();
        m_simulator.reset();
    }

    void aSimulatedPortSpeaksItsOwnProtocol()
    {
        using Protocol = ConnectionController::Protocol;
        QCOMPARE(ConnectionController::simulatedProtocol(
                     QLatin1String(ConnectionController::kSimulatedPtkPort)),
                 std::optional<Protocol>(Protocol::Ptk));
        QCOMPARE(ConnectionController::simulatedProtocol(
                     QLatin1String(ConnectionController::kSimulatedFeetechPort)),
                 std::optional<Protocol>(Protocol::Feetech));
        QCOMPARE(ConnectionController::simulatedProtocol(
                     QLatin1String(ConnectionController::kSimulatedArmPort)),
                 std::optional<Protocol>(Protocol::Feetech));
        QVERIFY(!ConnectionController::simulatedProtocol(QStringLiteral("/dev/ttyUSB0")));
    }

    void withoutAPortNothingIsOpenedAndTheUserIsTold()
    {
        QSignalSpy problem(m_controller.get(), &ConnectionController::problem);
        QSignalSpy active(m_controller.get(), &ConnectionController::sessionActiveChanged);
        m_controller->connectTo({});
        QCOMPARE(problem.size(), 1);
        QCOMPARE(problem.first().first().toString(), QStringLiteral("Choose a serial port first."));
        QVERIFY(active.isEmpty());
        QVERIFY(!m_controller->isDetecting());
    }

    void aProtocolChosenByHandNeedsABaudRate()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M}}), &error),
                 qPrintable(error));
        QSignalSpy problem(m_controller.get(), &ConnectionController::problem);
        m_controller->connectTo(request(ConnectionController::Protocol::Feetech));
        QCOMPARE(problem.size(), 1);
        QCOMPARE(problem.first().first().toString(), QStringLiteral("Enter a baud rate."));
        QCOMPARE(m_feetech->link()->status().state, seriallink::ConnectionState::Disconnected);
        QVERIFY(!m_controller->isDetecting());
    }

    void aFeetechBusChosenByHandOpensAtItsRateUnderTheNameTheUserChose()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M}}), &error),
                 qPrintable(error));
        QSignalSpy named(m_controller.get(), &ConnectionController::feetechPortNamed);
        QSignalSpy simulator(m_controller.get(), &ConnectionController::simulatorChanged);
        m_controller->setFeetechActive(true);
        m_controller->connectTo(request(ConnectionController::Protocol::Feetech, k1M));
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        QCOMPARE(named.size(), 1);
        QCOMPARE(named.first().first().toString(), m_simulator->linkPath());
        // Not the demo's: no Simulator dock.
        QCOMPARE(simulator.size(), 1);
        QCOMPARE(simulator.first().first().value<sim::SimulatorThread *>(), nullptr);
        QVERIFY(!m_controller->probeReport());
        QVERIFY(!m_ptk->isConnected());
        // Disconnect closes the active client.
        m_controller->disconnectFrom();
        QTRY_COMPARE_WITH_TIMEOUT(m_feetech->link()->status().state,
                                  seriallink::ConnectionState::Disconnected, 10000);
    }

    void autoOpensTheFeetechBusAndAsksForAScanOfTheRatesThatAnswered()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M},
                                            {4, QStringLiteral("STS3215"), k500k}}),
                                &error),
                 qPrintable(error));
        QSignalSpy started(m_controller.get(), &ConnectionController::detectionStarted);
        QSignalSpy finished(m_controller.get(), &ConnectionController::detectionFinished);
        QSignalSpy detected(m_controller.get(), &ConnectionController::detected);
        QSignalSpy feetechActive(m_controller.get(), &ConnectionController::feetechActiveChanged);
        QSignalSpy scanWanted(m_controller.get(), &ConnectionController::scanWanted);
        QSignalSpy scanned(m_feetech.get(), &feetech::BusClient::scanFinished);
        m_controller->connectTo(request(ConnectionController::Protocol::Auto));
        QVERIFY(m_controller->isDetecting());
        QVERIFY(m_controller->portProbe());
        QCOMPARE(started.size(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 60000);
        QCOMPARE(finished.size(), 1);
        QVERIFY(!m_controller->isDetecting());
        QCOMPARE(detected.size(), 1);
        QCOMPARE(detected.first().first().toInt(), k1M);
        QCOMPARE(feetechActive.size(), 1);
        QCOMPARE(feetechActive.first().first().toBool(), true);
        QVERIFY(m_controller->isFeetechActive());
        QVERIFY(m_controller->probeReport());
        QCOMPARE(scanWanted.size(), 1);
        const auto options = scanWanted.first().first().value<feetech::ScanOptions>();
        QCOMPARE(options.bauds, (QVector<qint32> {k1M, k500k}));
        QVERIFY(!options.skipSilentRates);
        QCOMPARE(m_feetech->servos()->count(), 2);
        QVERIFY(!m_ptk->isConnected());
    }

    void autoConnectsThePtkClientToAPtkServo()
    {
        QString error;
        QVERIFY2(startSimulator(testsupport::ptkOptions(m_dir, QStringLiteral("ptk")), &error),
                 qPrintable(error));
        QSignalSpy detected(m_controller.get(), &ConnectionController::detected);
        m_controller->setFeetechActive(true);
        m_controller->connectTo(request(ConnectionController::Protocol::Auto));
        QTRY_COMPARE_WITH_TIMEOUT(m_ptk->status().state, seriallink::ConnectionState::Connected,
                                  30000);
        QCOMPARE(detected.size(), 1);
        QCOMPARE(detected.first().first().toInt(), 115200);
        QVERIFY(!m_controller->isFeetechActive());
        QVERIFY(!m_feetech->link()->isConnected());
    }

    void disconnectDuringTheProbeCancelsItAndConnectsNothing()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M}}), &error),
                 qPrintable(error));
        QSignalSpy active(m_controller.get(), &ConnectionController::sessionActiveChanged);
        QSignalSpy message(m_controller.get(), &ConnectionController::message);
        m_controller->connectTo(request(ConnectionController::Protocol::Auto));
        QVERIFY(m_controller->isDetecting());
        m_controller->disconnectFrom();
        QTRY_VERIFY_WITH_TIMEOUT(!m_controller->isDetecting(), 30000);
        QCOMPARE(message.size(), 1);
        QVERIFY(message.first().first().toString().contains(QStringLiteral("cancelled")));
        QCOMPARE(active.size(), 2);
        QCOMPARE(active.last().first().toBool(), false);
        QVERIFY(!m_feetech->link()->isConnected());
        QVERIFY(!m_ptk->isConnected());
    }

    void aSilentPortCallsTheDoctorWithWhatTheProbeHeard()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M}}), &error),
                 qPrintable(error));
        QVERIFY(testsupport::onSimulatedBus(
            *m_simulator, [](sim::VirtualFeetechBus &bus) { return bus.setPowered(0, false); }));
        QSignalSpy findings(m_controller.get(), &ConnectionController::doctorFindings);
        QSignalSpy wanted(m_controller.get(), &ConnectionController::doctorWanted);
        QSignalSpy problem(m_controller.get(), &ConnectionController::problem);
        m_controller->connectTo(request(ConnectionController::Protocol::Auto));
        QTRY_VERIFY_WITH_TIMEOUT(!m_controller->isDetecting(), 30000);
        QCOMPARE(findings.size(), 1);
        QCOMPARE(findings.first().at(0).toString(), m_simulator->linkPath());
        QCOMPARE(codesOf(findings.first().at(1).value<QVector<feetech::DoctorFinding>>()),
                 QStringList {feetech::doctorcodes::kNoBytes});
        QCOMPARE(wanted.size(), 1);
        QCOMPARE(problem.size(), 1);
        QVERIFY(!m_feetech->link()->isConnected());
        QVERIFY(!m_ptk->isConnected());
    }

    void aShortScanCallsTheDoctor()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M},
                                            {2, QStringLiteral("STS3215"), k1M}}),
                                &error),
                 qPrintable(error));
        // The bus should hold joints 1 to 6 at 1 Mbps.
        m_controller->setExpectedServos([](const QString &) {
            QVector<feetech::ExpectedServo> joints;
            for (quint8 id = 1; id <= 6; ++id)
                joints.append({id, k1M});
            return joints;
        });
        feetech::ScanOptions options;
        options.lastId = 10;
        m_controller->setLastScanOptions([options] { return options; });
        QSignalSpy checking(m_controller.get(), &ConnectionController::doctorChecking);
        QSignalSpy wanted(m_controller.get(), &ConnectionController::doctorWanted);
        QSignalSpy findings(m_controller.get(), &ConnectionController::doctorFindings);
        m_controller->setFeetechActive(true);
        m_controller->connectTo(request(ConnectionController::Protocol::Feetech, k1M));
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        m_feetech->scan(options);
        QTRY_COMPARE_WITH_TIMEOUT(findings.size(), 1, 30000);
        QCOMPARE(checking.size(), 1);
        // Once when the scan came back short, once for what the doctor found.
        QCOMPARE(wanted.size(), 2);
        const auto found = findings.first().at(1).value<QVector<feetech::DoctorFinding>>();
        QCOMPARE(codesOf(found), QStringList {feetech::doctorcodes::kChainBreak});
        QCOMPARE(found.first().ids, (QVector<int> {3, 4, 5, 6}));
    }

    void aFullScanIsRememberedAndLeavesAHiddenDoctorAlone()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M},
                                            {2, QStringLiteral("STS3215"), k1M}}),
                                &error),
                 qPrintable(error));
        QSignalSpy checking(m_controller.get(), &ConnectionController::doctorChecking);
        QSignalSpy wanted(m_controller.get(), &ConnectionController::doctorWanted);
        m_controller->connectTo(request(ConnectionController::Protocol::Feetech, k1M));
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        feetech::ScanOptions options;
        options.lastId = 10;
        QSignalSpy scanned(m_feetech.get(), &feetech::BusClient::scanFinished);
        m_feetech->scan(options);
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 30000);
        QCOMPARE(feetech::rememberedServos(m_simulator->linkPath()).size(), 2);
        QVERIFY(checking.isEmpty());
        QVERIFY(wanted.isEmpty());

        // With the doctor shown, a full scan is checked too, and it stays where it is.
        m_controller->setDoctorShown([] { return true; });
        m_feetech->scan(options);
        QTRY_COMPARE_WITH_TIMEOUT(checking.size(), 1, 30000);
        QVERIFY(wanted.isEmpty());
    }

    void theDemoBusStartsItsSimulatorAndIsScannedOnceOpen()
    {
        QSignalSpy simulator(m_controller.get(), &ConnectionController::simulatorChanged);
        QSignalSpy scanWanted(m_controller.get(), &ConnectionController::scanWanted);
        ConnectionController::Request demo;
        demo.port = QLatin1String(ConnectionController::kSimulatedFeetechPort);
        demo.protocol = ConnectionController::Protocol::Auto; // the simulated bus says Feetech
        demo.baud = k1M;
        m_controller->setFeetechActive(true);
        m_controller->connectTo(demo);
        m_controller->scanOnceConnected();
        QVERIFY(!m_controller->isDetecting());
        QCOMPARE(simulator.size(), 1);
        QVERIFY(simulator.first().first().value<sim::SimulatorThread *>());
        QCOMPARE(m_controller->simulator(),
                 simulator.first().first().value<sim::SimulatorThread *>());
        QCOMPARE(m_controller->portShown(), QStringLiteral("simulated Feetech bus"));
        // The simulated bus's port inside the program, reached without a pseudo-terminal.
        QVERIFY(m_controller->portPath() != demo.port);
        QVERIFY(seriallink::InProcessPort::isKnown(m_controller->portPath()));
        QTRY_VERIFY_WITH_TIMEOUT(m_feetech->link()->isConnected(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(scanWanted.size(), 1, 10000);
    }
};

QTEST_GUILESS_MAIN(TestConnectionController)
#include "tst_connectioncontroller.moc"
