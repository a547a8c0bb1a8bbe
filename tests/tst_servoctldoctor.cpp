// servoctl detect and doctor against simulated buses over a pty: the JSON, the findings for
// each case the simulator plays, and the exit codes.
#include "feetechbus.h"
#include "servoctlrun.h"

#include "busdoctor.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSerialPort>
#include <QtTest>

using testsupport::runServoctl;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k500k = 500000;

// The findings of a doctor --json run, by code.
QMap<QString, QJsonObject> findingsByCode(const QString &json)
{
    QMap<QString, QJsonObject> findings;
    for (const QJsonValue &finding : QJsonDocument::fromJson(json.toUtf8()).array())
        findings.insert(finding[QStringLiteral("finding")].toString(), finding.toObject());
    return findings;
}

QVector<int> idsOf(const QJsonObject &finding)
{
    QVector<int> ids;
    for (const QJsonValue &id : finding.value(QStringLiteral("ids")).toArray())
        ids.append(id.toInt());
    return ids;
}

} // namespace

class TestServoctlDoctor : public testsupport::FeetechBusTest
{
    Q_OBJECT

    testsupport::ServoctlResult run(const QString &line) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath()}
                           + line.split(u' ', Qt::SkipEmptyParts));
    }

    void startBus(const QVector<sim::FeetechServoSpec> &servos, bool sharedIds = false)
    {
        auto options = busOptions(servos);
        options.allowSharedIds = sharedIds;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
    }

    void startPtk(bool echo)
    {
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Ptk;
        options.linkPath = m_dir.filePath(QStringLiteral("ptk"));
        options.echo = echo;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
    }

    template<typename Work>
    void onBus(Work work)
    {
        QVERIFY(testsupport::onSimulatedBus(*m_simulator, work));
    }

private slots:
    void cleanup() { m_simulator.reset(); }

    void detectJsonNamesTheFeetechBusItsRatesAndServos()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M},
                  {2, QStringLiteral("STS3215"), k1M},
                  {7, QStringLiteral("SCS15"), k500k}});
        const auto result = run(QStringLiteral("detect --json"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject detected = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(detected.keys(),
                 (QStringList {QStringLiteral("bauds"), QStringLiteral("echo"),
                               QStringLiteral("protocol"), QStringLiteral("servos")}));
        QCOMPARE(detected[QStringLiteral("protocol")].toString(), QStringLiteral("feetech"));
        QCOMPARE(detected[QStringLiteral("echo")].toBool(), false);
        QCOMPARE(detected[QStringLiteral("bauds")].toArray(), (QJsonArray {k1M, k500k}));
        const QJsonArray servos = detected[QStringLiteral("servos")].toArray();
        QCOMPARE(servos.size(), 3);
        QCOMPARE(servos.at(0).toObject(),
                 (QJsonObject {{QStringLiteral("id"), 1},
                               {QStringLiteral("baud"), k1M},
                               {QStringLiteral("model"), QStringLiteral("STS3215")}}));
        QCOMPARE(servos.at(2)[QStringLiteral("id")].toInt(), 7);
        QCOMPARE(servos.at(2)[QStringLiteral("baud")].toInt(), k500k);
        QCOMPARE(servos.at(2)[QStringLiteral("model")].toString(), QStringLiteral("SCS15"));
    }

    void detectFindsAFeetechBusBehindAnEchoingAdapter()
    {
        auto options = busOptions({{3, QStringLiteral("STS3215"), k1M}});
        options.echo = true;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        const auto result = run(QStringLiteral("detect --json"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject detected = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(detected[QStringLiteral("echo")].toBool(), true);
        QCOMPARE(detected[QStringLiteral("servos")].toArray().size(), 1);
        QCOMPARE(detected[QStringLiteral("servos")].toArray().at(0)[QStringLiteral("id")].toInt(),
                 3);
    }

    void detectFindsAPtkServo_data()
    {
        QTest::addColumn<bool>("echo");
        QTest::newRow("without echo") << false;
        QTest::newRow("behind an echoing adapter") << true;
    }

    void detectFindsAPtkServo()
    {
        QFETCH(bool, echo);
        startPtk(echo);
        const auto result = run(QStringLiteral("detect --json"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject detected = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(detected[QStringLiteral("protocol")].toString(), QStringLiteral("ptk"));
        QCOMPARE(detected[QStringLiteral("echo")].toBool(), echo);
        QCOMPARE(detected[QStringLiteral("bauds")].toArray(), QJsonArray {115200});
        QCOMPARE(detected[QStringLiteral("servos")].toArray(), QJsonArray());
    }

    void detectOnASilentBusExitsOneWithTheDoctorsFindings()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}});
        onBus([](sim::VirtualFeetechBus &bus) { return bus.setPowered(0, false); });
        const auto result = run(QStringLiteral("detect --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonObject detected = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QVERIFY(detected[QStringLiteral("protocol")].isNull());
        QCOMPARE(detected[QStringLiteral("servos")].toArray(), QJsonArray());
        QVERIFY2(result.err.contains(feetech::doctorcodes::kNoBytes), qPrintable(result.err));
    }

    void doctorOnABusAsExpectedExitsZeroWithNoFinding()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k1M}});
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(QJsonDocument::fromJson(result.out.toUtf8()).array(), QJsonArray());
        const auto text = run(QStringLiteral("doctor --expect 1,2"));
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains(QStringLiteral("expected")), qPrintable(text.out));
    }

    void doctorFindsNoByteWhenNoServoHasPower()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k1M}});
        onBus([](sim::VirtualFeetechBus &bus) {
            return bus.setPowered(0, false) && bus.setPowered(1, false);
        });
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QCOMPARE(findings.keys(), QStringList {feetech::doctorcodes::kNoBytes});
        QVERIFY(findings.first()[QStringLiteral("message")].toString().contains(
            QStringLiteral("power")));
    }

    void doctorListsAServoAtAnUnexpectedRate()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k500k}});
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QVERIFY2(findings.contains(feetech::doctorcodes::kUnexpectedBaud), qPrintable(result.out));
        QCOMPARE(idsOf(findings.value(feetech::doctorcodes::kUnexpectedBaud)), QVector<int> {2});
        QVERIFY(!findings.contains(feetech::doctorcodes::kMissingServos));
    }

    void doctorListsAServoAtAnUnexpectedIdAndOffersTheMissingOne()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}, {9, QStringLiteral("STS3215"), k1M}});
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        const QJsonObject stray = findings.value(feetech::doctorcodes::kUnexpectedId);
        QCOMPARE(idsOf(stray), QVector<int> {9});
        QVERIFY2(stray[QStringLiteral("message")].toString().contains(QStringLiteral("ID 2")),
                 qPrintable(result.out));
    }

    void doctorPointsAtTheCableAfterTheLastServoOfABrokenChain()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M},
                  {2, QStringLiteral("STS3215"), k1M},
                  {3, QStringLiteral("STS3215"), k1M},
                  {4, QStringLiteral("STS3215"), k1M}});
        onBus([](sim::VirtualFeetechBus &bus) { return bus.setChainBreakAfter(1); });
        const auto result = run(QStringLiteral("doctor --json --expect 1-4"));
        QCOMPARE(result.exitCode, 1);
        const QJsonObject broken =
            findingsByCode(result.out).value(feetech::doctorcodes::kChainBreak);
        QCOMPARE(idsOf(broken), (QVector<int> {3, 4}));
        QVERIFY2(
            broken[QStringLiteral("message")].toString().contains(QStringLiteral("after ID 2")),
            qPrintable(result.out));
    }

    void aServoMissingFromTheMiddleIsMissingNotABrokenChain()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}, {3, QStringLiteral("STS3215"), k1M}});
        const auto result = run(QStringLiteral("doctor --json --expect 1,2,3"));
        const auto findings = findingsByCode(result.out);
        QCOMPARE(idsOf(findings.value(feetech::doctorcodes::kMissingServos)), QVector<int> {2});
        QVERIFY(!findings.contains(feetech::doctorcodes::kChainBreak));
    }

    void doctorReportsTheSupplyWhenEveryAnswerCarriesTheVoltageBit_data()
    {
        QTest::addColumn<bool>("echo");
        QTest::newRow("plain adapter") << false;
        QTest::newRow("single-wire adapter") << true;
    }

    void doctorReportsTheSupplyWhenEveryAnswerCarriesTheVoltageBit()
    {
        // A 12 V supply on 7.4 V servos: each answers a PING with the PING's very bytes (error
        // bit 0), and the two answers to the broadcast PING collide, so nothing has shown yet
        // whether the adapter echoes.
        QFETCH(bool, echo);
        auto options =
            busOptions({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k1M}});
        options.echo = echo;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.setSupplyVoltage(12.6);
            return true;
        });
        const auto result = run(QStringLiteral("doctor --json"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QVERIFY2(!findings.contains(feetech::doctorcodes::kNoServoFound), qPrintable(result.out));
        QVERIFY2(findings.contains(feetech::doctorcodes::kVoltage), qPrintable(result.out));
        QVERIFY(findings.value(feetech::doctorcodes::kVoltage)[QStringLiteral("message")]
                    .toString()
                    .contains(QStringLiteral("12.6 V")));
    }

    void doctorFindsAnOverVoltage()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("STS3215"), k1M}});
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.setSupplyVoltage(12.0);
            return true;
        });
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QVERIFY2(findings.contains(feetech::doctorcodes::kVoltage), qPrintable(result.out));
        QVERIFY(findings.value(feetech::doctorcodes::kVoltage)[QStringLiteral("message")]
                    .toString()
                    .contains(QStringLiteral("12.0 V")));
    }

    void voltageLimitsOfZeroAreNoLimits()
    {
        // An HLS servo with both limits 0, its check off, on a 12 V supply: nothing is wrong.
        startBus({{1, QStringLiteral("STS3215"), k1M}, {2, QStringLiteral("HLS"), k1M}});
        onBus([](sim::VirtualFeetechBus &bus) {
            bus.setSupplyVoltage(12.0);
            bus.servo(0).setValue(u"max_voltage", 140);
            bus.servo(1).setValue(u"max_voltage", 0);
            bus.servo(1).setValue(u"min_voltage", 0);
            return true;
        });
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(!findingsByCode(result.out).contains(feetech::doctorcodes::kVoltage),
                 qPrintable(result.out));
    }

    void doctorSuspectsTwoServosAtOneIdFromGarbledReads()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M},
                  {1, QStringLiteral("STS3215"), k1M},
                  {2, QStringLiteral("STS3215"), k1M}},
                 true);
        const auto result = run(QStringLiteral("doctor --json --expect 1,2"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QVERIFY2(findings.contains(feetech::doctorcodes::kSharedId), qPrintable(result.out));
        QCOMPARE(idsOf(findings.value(feetech::doctorcodes::kSharedId)), QVector<int> {1});
    }

    void doctorFindsBytesThatNeverMakeAnAnswer()
    {
        // Every answer arrives with a bit flipped: bytes come at 1 Mbps, never a valid frame.
        auto options = busOptions({{1, QStringLiteral("STS3215"), k1M}});
        options.faults.corrupt = 1.0;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        const auto result = run(QStringLiteral("doctor --json --expect 1"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QVERIFY2(findings.contains(feetech::doctorcodes::kUnframedBytes), qPrintable(result.out));
        QVERIFY(findings.value(feetech::doctorcodes::kUnframedBytes)[QStringLiteral("message")]
                    .toString()
                    .contains(QStringLiteral("1 Mbps")));
        QVERIFY(!findings.contains(feetech::doctorcodes::kNoBytes));
    }

    void doctorOnAPtkServoIsContentUnlessABusWasExpected()
    {
        startPtk(false);
        const auto content = run(QStringLiteral("doctor"));
        QCOMPARE(content.exitCode, 0);
        QVERIFY2(content.out.contains(QStringLiteral("PTK")), qPrintable(content.out));
        const auto expecting = run(QStringLiteral("doctor --json --expect 1-3"));
        QCOMPARE(expecting.exitCode, 1);
        QCOMPARE(findingsByCode(expecting.out).keys(),
                 QStringList {feetech::doctorcodes::kPtkServo});
    }

    void doctorNamesTheProgramHoldingABusyPort()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}});
        QSerialPort holder(m_simulator->linkPath());
        QVERIFY(holder.open(QIODevice::ReadWrite));
        const auto result = run(QStringLiteral("doctor --json"));
        QCOMPARE(result.exitCode, 1);
        const auto findings = findingsByCode(result.out);
        QCOMPARE(findings.keys(), QStringList {feetech::doctorcodes::kPortBusy});
#ifdef Q_OS_LINUX
        QVERIFY2(findings.first()[QStringLiteral("message")].toString().contains(
                     QString::number(QCoreApplication::applicationPid())),
                 qPrintable(result.out));
#endif
    }

    void aPortThatMayNotBeOpenedTellsAboutTheDialoutGroup()
    {
        feetech::BusObservation seen;
        seen.probe.port = QStringLiteral("/dev/ttyUSB0");
        seen.probe.access.problem = seriallink::PortAccess::Problem::Permission;
        const auto findings = feetech::diagnoseBus(seen, {{1, k1M}});
        QCOMPARE(findings.size(), 1);
        QCOMPARE(findings.first().code, feetech::doctorcodes::kPortPermission);
#ifdef Q_OS_LINUX
        QVERIFY(findings.first().message.contains(QStringLiteral("dialout")));
#endif
    }

    void badDoctorAndDetectArgumentsExitTwo()
    {
        startBus({{1, QStringLiteral("STS3215"), k1M}});
        QCOMPARE(run(QStringLiteral("doctor --expect 1,x")).exitCode, 2);
        QCOMPARE(run(QStringLiteral("doctor --expect 1 --baud 12345")).exitCode, 2);
        QCOMPARE(run(QStringLiteral("doctor --baud 1000000")).exitCode, 2);
        QCOMPARE(run(QStringLiteral("detect extra")).exitCode, 2);
        QCOMPARE(run(QStringLiteral("detect --ids 1")).exitCode, 2);
        QCOMPARE(runServoctl({QStringLiteral("detect")}).exitCode, 2);
        // Nothing was sent for any of them.
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestServoctlDoctor)
#include "tst_servoctldoctor.moc"
