// The demo's simulated servos: each bus started once on a port of its own inside the program, and
// why one does not start, as a refusal's code.
#include "busclient.h"
#include "demoservos.h"
#include "inprocessport.h"
#include "linkmirror.h"
#include "virtualfeetechbus.h"

#include <QSet>
#include <QTemporaryFile>
#include <QtTest>

namespace {

// The simulator's Feetech bus, looked at in its own thread: each servo's ID and model.
QStringList servosOf(sim::SimulatorThread *simulator)
{
    QStringList servos;
    simulator->call([&servos](sim::Simulator &running) {
        const sim::VirtualFeetechBus *bus = running.feetechBus();
        for (int index = 0; bus && index < bus->servoCount(); ++index)
            servos.append(QStringLiteral("%1:%2")
                              .arg(bus->servo(index).id())
                              .arg(bus->servo(index).modelName()));
    });
    return servos;
}

// TMPDIR for as long as it lives, the one before it afterwards.
class TemporaryFolderVariable
{
public:
    explicit TemporaryFolderVariable(const QByteArray &value)
        : m_before(qgetenv("TMPDIR"))
        , m_wasSet(qEnvironmentVariableIsSet("TMPDIR"))
    {
        qputenv("TMPDIR", value);
    }
    ~TemporaryFolderVariable()
    {
        if (m_wasSet)
            qputenv("TMPDIR", m_before);
        else
            qunsetenv("TMPDIR");
    }
    TemporaryFolderVariable(const TemporaryFolderVariable &) = delete;
    TemporaryFolderVariable &operator=(const TemporaryFolderVariable &) = delete;

private:
    QByteArray m_before;
    bool m_wasSet = false;
};

} // namespace

class TestDemoServos : public QObject
{
    Q_OBJECT

private slots:
    // The HLS is the family's generic model, as the model table names it.
    void eachSimulatedBusStartsOnceOnAPortOfItsOwn()
    {
        sim::DemoServos demo;
        QVERIFY(!demo.feetechSimulator());
        sim::SimRefusal why;
        const QString feetech = demo.feetechPort(&why);
        QVERIFY2(!feetech.isEmpty(), qPrintable(why.describe()));
        QCOMPARE(why.code(), sim::SimRefusal::Code::None);
        // Offered inside the program, not as a pseudo-terminal's link.
        QVERIFY(seriallink::InProcessPort::isKnown(feetech));
        QVERIFY(!QFileInfo::exists(feetech));
        QCOMPARE(demo.feetechPort(&why), feetech);
        QVERIFY(demo.feetechSimulator());
        QCOMPARE(servosOf(demo.feetechSimulator()),
                 QStringList({QStringLiteral("1:STS3215"), QStringLiteral("2:STS3215"),
                              QStringLiteral("3:STS3215"), QStringLiteral("4:SCS15"),
                              QStringLiteral("5:HLSxx")}));

        const QString arm = demo.armPort(&why);
        QVERIFY2(!arm.isEmpty(), qPrintable(why.describe()));
        QCOMPARE(demo.armPort(&why), arm);
        QCOMPARE(servosOf(demo.armSimulator()).size(), 6);

        const QString ptk = demo.ptkPort(&why);
        QVERIFY2(!ptk.isEmpty(), qPrintable(why.describe()));
        QCOMPARE(demo.ptkPort(&why), ptk);

        const QStringList ports = {feetech, arm, ptk};
        QCOMPARE(QSet<QString>(ports.begin(), ports.end()).size(), 3);
        QVERIFY(!demo.leaderArmSimulator());
    }

    void theFeetechDemoIsScannedWithoutALinkError()
    {
        // Five servos answer the scan's broadcast PING at once: what the scan listens for is no
        // discarded byte, no timeout, no bad checksum in the status bar.
        sim::DemoServos demo;
        sim::SimRefusal why;
        const QString port = demo.feetechPort(&why);
        QVERIFY2(!port.isEmpty(), qPrintable(why.describe()));
        feetech::BusClient client;
        client.connectTo(port);
        QTRY_VERIFY_WITH_TIMEOUT(client.link()->isConnected(), 10000);
        QSignalSpy finished(&client, &feetech::BusClient::scanFinished);
        feetech::ScanOptions options;
        options.lastId = 10;
        client.scan(options);
        QVERIFY(finished.wait(30000));
        QCOMPARE(client.servos()->count(), 5);
        QTRY_VERIFY(client.link()->counters().repliesOk > 0);
        const seriallink::LinkCounters counters = client.link()->counters();
        QCOMPARE(counters.discardedBytes, 0);
        QCOMPARE(counters.timeouts, 0);
        QCOMPARE(counters.checksumErrors, 0);
        client.disconnectFrom();
    }

    void theLeaderArmsHandSweepsTwoJoints()
    {
        sim::DemoServos demo;
        sim::SimRefusal why;
        QVERIFY2(!demo.leaderArmPort(&why).isEmpty(), qPrintable(why.describe()));
        QCOMPARE(servosOf(demo.leaderArmSimulator()).size(), 6);
        int sweeping = 0;
        demo.leaderArmSimulator()->call([&sweeping](sim::Simulator &running) {
            sweeping = running.feetechBus()->hand().sweepCount();
        });
        QCOMPARE(sweeping, 2);
    }

    void aFolderThatCannotBeMadeIsRefusedAndTriedAgainNextTime()
    {
        // A temporary folder inside a plain file cannot be made.
        QTemporaryFile file;
        QVERIFY(file.open());
        sim::DemoServos demo;
        sim::SimRefusal why;
        {
            const TemporaryFolderVariable inAFile(QFile::encodeName(file.fileName()));
            QVERIFY(demo.feetechPort(&why).isEmpty());
            QCOMPARE(why.code(), sim::SimRefusal::Code::NoDemoFolder);
            QVERIFY(!why.name().isEmpty()); // the system's reason
            QVERIFY(!demo.feetechSimulator());
            why = {};
            QVERIFY(demo.armPort(&why).isEmpty());
            QCOMPARE(why.code(), sim::SimRefusal::Code::NoDemoFolder);
            why = {};
            QVERIFY(demo.ptkPort(&why).isEmpty());
            QCOMPARE(why.code(), sim::SimRefusal::Code::NoDemoFolder);
        }
        why = {};
        QVERIFY2(!demo.feetechPort(&why).isEmpty(), qPrintable(why.describe()));
        QCOMPARE(why.code(), sim::SimRefusal::Code::None);
        QVERIFY(demo.feetechSimulator());
    }

    void aRefusalIsOptional()
    {
        QTemporaryFile file;
        QVERIFY(file.open());
        const TemporaryFolderVariable inAFile(QFile::encodeName(file.fileName()));
        sim::DemoServos demo;
        QVERIFY(demo.leaderArmPort(nullptr).isEmpty());
        QVERIFY(!demo.leaderArmSimulator());
    }
};

QTEST_GUILESS_MAIN(TestDemoServos)
#include "tst_demoservos.moc"
