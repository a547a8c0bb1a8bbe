// The port probe against the simulated PTK servo and Feetech bus over a pty: what each rate
// says, echo, silence, and a port that will not open; it never writes to a servo.
#include "feetechbus.h"
#include "simclient.h"

#include "portaccess.h"
#include "portprobe.h"

#include <QFile>
#include <QSerialPort>
#include <QtTest>

#include <unistd.h>

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k500k = 500000;

// Generous waits: a loaded machine makes the simulator slow, and a slow answer is still one.
feetech::ProbeTiming patientProbe()
{
    feetech::ProbeTiming timing;
    timing.ptkWait = std::chrono::milliseconds(500);
    timing.feetechWait = std::chrono::milliseconds(300);
    timing.settle = std::chrono::milliseconds(60);
    return timing;
}

const feetech::RateProbe *rateOf(const feetech::PortProbeReport &report, qint32 baud)
{
    for (const feetech::RateProbe &rate : report.rates) {
        if (rate.baud == baud)
            return &rate;
    }
    return nullptr;
}

} // namespace

class TestPortProbe : public testsupport::FeetechBusTest
{
    Q_OBJECT

    // Probes `port` to the end: the report (empty when it did not end within 20 s).
    feetech::PortProbeReport probe(const QString &port)
    {
        feetech::PortProbe probe(patientProbe());
        QSignalSpy finished(&probe, &feetech::PortProbe::finished);
        probe.start(port);
        if (finished.isEmpty() && !finished.wait(20000))
            return {};
        return finished.first().at(0).value<feetech::PortProbeReport>();
    }

    bool startPtk(bool echo)
    {
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Ptk;
        options.linkPath = m_dir.filePath(QStringLiteral("ptk"));
        options.echo = echo;
        QString error;
        if (!startSimulator(options, &error)) {
            qWarning("%s", qPrintable(error));
            return false;
        }
        return true;
    }

private slots:
    void cleanup() { m_simulator.reset(); }

    void aPtkServoAnswersTheQueryWithoutEcho()
    {
        QVERIFY(startPtk(false));
        const auto report = probe(m_simulator->linkPath());
        QVERIFY(report.opened());
        QVERIFY(report.ptk);
        QVERIFY(!report.echo);
        // A PTK programmer holds one servo: no Feetech rate is asked after it answered.
        QVERIFY(report.rates.isEmpty());
    }

    void aPtkServoBehindAnEchoingAdapterIsFoundWithTheEcho()
    {
        QVERIFY(startPtk(true));
        const auto report = probe(m_simulator->linkPath());
        QVERIFY(report.ptk);
        QVERIFY(report.echo);
        QCOMPARE(report.answeringBauds(), QVector<qint32> {});
    }

    void aFeetechBusAnswersAtItsTwoRatesAndIsSilentElsewhere()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M},
                                            {7, QStringLiteral("STS3215"), k500k}}),
                                &error),
                 qPrintable(error));
        const auto report = probe(m_simulator->linkPath());
        QVERIFY(report.opened());
        QVERIFY(!report.ptk);
        QCOMPARE(report.rates.size(), feetech::baudRates().size());
        QCOMPARE(report.answeringBauds(), (QVector<qint32> {k1M, k500k}));
        QCOMPARE(rateOf(report, k1M)->heard, feetech::RateHeard::Frames);
        QCOMPARE(rateOf(report, k1M)->ids, QVector<quint8> {1});
        QCOMPARE(rateOf(report, k500k)->ids, QVector<quint8> {7});
        QCOMPARE(rateOf(report, 115200)->heard, feetech::RateHeard::Silence);
        QCOMPARE(rateOf(report, 115200)->bytes, 0);
        // Only the PTK query and broadcast PINGs went out: nothing a servo acts on.
        for (const feetech::Packet &packet : testsupport::feetechPacketsReceived(logPath())) {
            QCOMPARE(packet.id, feetech::kBroadcastId);
            QCOMPARE(packet.code, quint8(feetech::Instruction::Ping));
        }
    }

    void servosAnsweringTogetherGiveBytesThatNeverFrame()
    {
        // Two servos at one rate answer a broadcast PING at once; their answers collide.
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M},
                                            {2, QStringLiteral("STS3215"), k1M}}),
                                &error),
                 qPrintable(error));
        const auto report = probe(m_simulator->linkPath());
        QCOMPARE(rateOf(report, k1M)->heard, feetech::RateHeard::Unframed);
        QVERIFY(rateOf(report, k1M)->bytes > 0);
        QCOMPARE(report.answeringBauds(), QVector<qint32> {k1M});
    }

    void aBusWhoseServosHaveNoPowerIsSilentAtEveryRate()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M},
                                            {2, QStringLiteral("STS3215"), k500k}}),
                                &error),
                 qPrintable(error));
        QVERIFY(testsupport::onSimulatedBus(*m_simulator, [](sim::VirtualFeetechBus &bus) {
            return bus.setPowered(0, false) && bus.setPowered(1, false);
        }));
        const auto report = probe(m_simulator->linkPath());
        QVERIFY(report.opened());
        QVERIFY(report.silent());
        QCOMPARE(report.rates.size(), feetech::baudRates().size());
        for (const feetech::RateProbe &rate : report.rates)
            QCOMPARE(rate.heard, feetech::RateHeard::Silence);
    }

    void aMissingPortIsReportedAsMissing()
    {
        const auto report = probe(m_dir.filePath(QStringLiteral("no-such-port")));
        QCOMPARE(report.access.problem, seriallink::PortAccess::Problem::Missing);
    }

    void aPortAnotherProgramHoldsIsBusyAndNamesTheHolder()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M}}), &error),
                 qPrintable(error));
        QSerialPort holder(m_simulator->linkPath());
        QVERIFY(holder.open(QIODevice::ReadWrite));
        const auto report = probe(m_simulator->linkPath());
        QCOMPARE(report.access.problem, seriallink::PortAccess::Problem::Busy);
#ifdef Q_OS_LINUX
        // This test holds it: the holder is this process.
        QVERIFY2(report.access.holder.contains(QString::number(QCoreApplication::applicationPid())),
                 qPrintable(report.access.holder));
#endif
    }

    void aPortWithoutPermissionIsAPermissionProblem()
    {
        if (::geteuid() == 0)
            QSKIP("running as root: every file may be opened, so permission cannot be refused");
        const QString path = writeTestFile(QStringLiteral("locked"), QByteArray());
        QVERIFY(QFile::setPermissions(path, QFileDevice::Permissions()));
        const auto access =
            seriallink::classifyOpenFailure(path, QSerialPort::PermissionError, QString());
        QCOMPARE(access.problem, seriallink::PortAccess::Problem::Permission);
    }

    void cancellingEndsTheProbeWithACancelledReport()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions({{1, QStringLiteral("STS3215"), k1M}}), &error),
                 qPrintable(error));
        feetech::PortProbe probe(patientProbe());
        QSignalSpy finished(&probe, &feetech::PortProbe::finished);
        connect(&probe, &feetech::PortProbe::progress, &probe, [&probe](int done) {
            if (done == 1)
                probe.cancel();
        });
        probe.start(m_simulator->linkPath());
        QVERIFY(finished.wait(20000));
        const auto report = finished.first().at(0).value<feetech::PortProbeReport>();
        QVERIFY(report.cancelled);
        QVERIFY(report.rates.size() < feetech::baudRates().size());
    }
};

QTEST_GUILESS_MAIN(TestPortProbe)
#include "tst_portprobe.moc"
