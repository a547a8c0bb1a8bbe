// The health check over the simulated bus: verdicts for a healthy, an over-voltage and a hot
// servo, a firmware mismatch, communication counted on a faulty line, the move test's metrics
// and restore, reads only without it; and the report saved as HTML and JSON.
#include "busoperations.h"
#include "feetechbus.h"
#include "healthmovetest.h"
#include "healthreport.h"
#include "servohealth.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QtTest>

using feetech::HealthReading;
using feetech::ServoHealth;
using feetech::ServoInfo;
using feetech::Verdict;

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kGoalAddress = 42;
constexpr int kTorqueAddress = 40;

bool hasFinding(const ServoHealth &health, const QString &code)
{
    return std::any_of(health.findings.begin(), health.findings.end(),
                       [&code](const feetech::HealthFinding &f) { return f.code == code; });
}

QString codes(const ServoHealth &health)
{
    QStringList all;
    for (const feetech::HealthFinding &finding : health.findings)
        all.append(finding.code);
    return all.join(QStringLiteral(", "));
}

} // namespace

class TestHealthCheck : public testsupport::FeetechSessionTest
{
    Q_OBJECT

private:
    void startBus(const sim::SimulatorOptions &options)
    {
        QString error;
        QVERIFY2(startSession(options, &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, seriallink::ConnectionState::Connected,
                                  10000);
        m_found.clear();
        feetech::ScanOptions scan;
        scan.lastId = 3;
        QSignalSpy finished(m_session.get(), &feetech::Session::scanFinished);
        m_session->submit(feetech::operations::scan(scan));
        QVERIFY(!finished.isEmpty() || finished.wait(30000));
    }

    // The verdicts of every servo found, firmware compared across them.
    QVector<ServoHealth> check()
    {
        QVector<HealthReading> readings;
        auto connection = connect(m_session.get(), &feetech::Session::operationProgress, this,
                                  [&readings](const feetech::OperationProgress &progress) {
                                      readings.append(progress.detail.value<HealthReading>());
                                  });
        const feetech::OperationResult result = run([&] {
            m_session->submit(
                feetech::operations::checkHealth(m_found, feetech::kDefaultHealthReads));
        });
        disconnect(connection);
        if (!result.ok)
            qWarning("health check: %s", qPrintable(result.message));
        QVector<ServoHealth> verdicts;
        for (const HealthReading &reading : std::as_const(readings))
            verdicts.append(feetech::assessHealth(reading));
        feetech::flagFirmwareMismatches(verdicts);
        return verdicts;
    }

    std::optional<feetech::MoveTestResult> moveTest(const ServoInfo &servo)
    {
        const feetech::OperationResult result =
            run([&] { m_session->submit(feetech::operations::moveTest(servo)); });
        if (!result.detail.canConvert<feetech::MoveTestResult>())
            return std::nullopt;
        return result.detail.value<feetech::MoveTestResult>();
    }

    int writesTo(int address) const
    {
        int count = 0;
        for (const feetech::Packet &packet :
             testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write)) {
            const int start = quint8(packet.parameters.at(0));
            if (address >= start && address < start + packet.parameters.size() - 1)
                ++count;
        }
        return count;
    }

private slots:
    void cleanup() { stopSession(); }

    void aHealthyServoIsOkWithEveryReadAnsweredAtOnce()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 1);
        const ServoHealth &servo = servos.first();
        QVERIFY2(servo.verdict == Verdict::Ok, qPrintable(codes(servo)));
        QVERIFY(servo.findings.isEmpty());
        QCOMPARE(servo.firmware, QStringLiteral("3.10"));
        QVERIFY(servo.voltage && *servo.voltage > 6.0 && *servo.voltage < 8.0);
        QVERIFY(servo.temperature.has_value());
        QCOMPARE(servo.comm.reads, feetech::kDefaultHealthReads);
        QCOMPARE(servo.comm.answered, feetech::kDefaultHealthReads);
        QVERIFY(servo.comm.clean());
    }

    void theCheckOnlyReads()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})));
        QCOMPARE(check().size(), 2);
        QVERIFY(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).isEmpty());
        QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncWrite)
                    .isEmpty());
    }

    void aSupplyAboveTheServosMaximumIsAFault()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})));
        QVERIFY(withServo(2, k1M, [](sim::VirtualFeetechServo &s) { s.setSupplyVoltage(12.0); }));
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 2);
        QVERIFY2(servos.at(0).verdict == Verdict::Ok, qPrintable(codes(servos.at(0))));
        QCOMPARE(servos.at(1).verdict, Verdict::Fault);
        QVERIFY2(hasFinding(servos.at(1), QStringLiteral("voltage-high")),
                 qPrintable(codes(servos.at(1))));
        QVERIFY(feetech::anyFault(servos));
    }

    void aServoNearItsMaximumTemperatureWarnsAndOneAtItIsAFault()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})));
        const qint32 maximum = simulatorValue(1, u"max_temperature");
        QVERIFY(maximum > 20);
        QVERIFY(withServo(
            1, k1M, [maximum](sim::VirtualFeetechServo &s) { s.setTemperature(maximum - 4); }));
        QVERIFY(withServo(
            2, k1M, [maximum](sim::VirtualFeetechServo &s) { s.setTemperature(maximum + 2); }));
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 2);
        QCOMPARE(servos.at(0).verdict, Verdict::Warning);
        QVERIFY2(hasFinding(servos.at(0), QStringLiteral("temperature-high")),
                 qPrintable(codes(servos.at(0))));
        QCOMPARE(servos.at(1).verdict, Verdict::Fault);
        QVERIFY2(hasFinding(servos.at(1), QStringLiteral("temperature-over")),
                 qPrintable(codes(servos.at(1))));
    }

    void servosOfOneModelWithDifferentFirmwareAreFlagged()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS0009"})));
        setSimulatorValue(2, u"firmware_minor", 7);
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 3);
        QCOMPARE(servos.at(1).firmware, QStringLiteral("3.07"));
        QVERIFY(hasFinding(servos.at(0), QStringLiteral("firmware-mismatch")));
        QVERIFY(hasFinding(servos.at(1), QStringLiteral("firmware-mismatch")));
        QVERIFY(!hasFinding(servos.at(2), QStringLiteral("firmware-mismatch")));
        QCOMPARE(servos.at(0).verdict, Verdict::Warning);
    }

    void aLatchedOverloadIsAFaultNamedAfterItsStatusBit()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setOverloadLatched(true); }));
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 1);
        QCOMPARE(servos.first().verdict, Verdict::Fault);
        // Bit 5 of the status register, "Load" in the STS table.
        QVERIFY2(hasFinding(servos.first(), QStringLiteral("status-load")),
                 qPrintable(codes(servos.first())));
        QVERIFY(servos.first().statusText.contains(QStringLiteral("Load")));
    }

    void aServoThatLostPowerIsAFaultAndTheOthersAreStillChecked()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"STS3215"})));
        QCOMPARE(m_found.size(), 3);
        QVERIFY(testsupport::onSimulatedBus(
            *m_simulator, [](sim::VirtualFeetechBus &bus) { return bus.setPowered(1, false); }));
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 3);
        QVERIFY2(servos.at(0).verdict == Verdict::Ok, qPrintable(codes(servos.at(0))));
        QCOMPARE(servos.at(1).verdict, Verdict::Fault);
        QVERIFY2(hasFinding(servos.at(1), QStringLiteral("unreadable")),
                 qPrintable(codes(servos.at(1))));
        QVERIFY2(servos.at(2).verdict == Verdict::Ok, qPrintable(codes(servos.at(2))));
    }

    void aFaultyLineShowsInTheServosCommunicationCounts()
    {
        auto options = busOptions(testsupport::servosAt(k1M, {u"STS3215"}));
        startBus(options);
        const ServoInfo servo = m_found.value(0);
        QCOMPARE(servo.id, quint8(1));
        // The same servo again, now with a line that drops and garbles replies.
        stopSession();
        options.faults.drop = 0.2;
        options.faults.corrupt = 0.2;
        QString error;
        QVERIFY2(startSession(options, &error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(
            m_session->status().state != seriallink::ConnectionState::Connecting, 10000);
        m_found = {servo};
        const QVector<ServoHealth> servos = check();
        QCOMPARE(servos.size(), 1);
        const feetech::CommQuality &comm = servos.first().comm;
        QCOMPARE(comm.reads, feetech::kDefaultHealthReads);
        QVERIFY(comm.timeouts > 0);
        QVERIFY(comm.retries > 0);
        QVERIFY(comm.checksumErrors > 0);
        QVERIFY(!comm.clean());
        QVERIFY(hasFinding(servos.first(), QStringLiteral("comm-retries"))
                || hasFinding(servos.first(), QStringLiteral("comm-lost")));
    }

    void theMoveTestMeasuresTheStepAndPutsEverythingBack()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        const qint32 start = simulatorValue(1, u"present_position");
        setSimulatorValue(1, u"goal_position", 3000); // a stale goal torque-on must not chase
        const auto moved = moveTest(m_found.value(0));
        QVERIFY(moved.has_value());
        QVERIFY2(moved->ok, qPrintable(moved->message));
        QCOMPARE(moved->failure, feetech::OperationFailure::None);
        QCOMPARE(moved->start, start);
        QCOMPARE(moved->target, start + feetech::HealthMoveTest::kAmplitude);
        QVERIFY(moved->metrics.has_value());
        QVERIFY(moved->metrics->riseTime.has_value());
        QVERIFY(*moved->metrics->riseTime > 0.0);
        QVERIFY(moved->metrics->overshootPercent.has_value());
        QVERIFY(moved->metrics->steadyStateError.has_value());
        QVERIFY(std::abs(*moved->metrics->steadyStateError) <= 10.0);
        // The goal became the present position before torque went on: the first goal written
        // is where the horn stood, never the stale 3000.
        QVERIFY(writesTo(kGoalAddress) >= 3);
        const auto first =
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write);
        for (const feetech::Packet &packet : first) {
            if (quint8(packet.parameters.at(0)) == kGoalAddress) {
                QCOMPARE(quint8(packet.parameters.at(1)) | (quint8(packet.parameters.at(2)) << 8),
                         start);
                break;
            }
        }
        QVERIFY(std::abs(simulatorValue(1, u"present_position") - start) <= 15);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(1, u"goal_position"), 3000);
        ServoHealth health;
        feetech::addMoveTest(health, *moved);
        QVERIFY2(health.verdict == Verdict::Ok, qPrintable(codes(health)));
    }

    void aServoWhoseLimitsLeaveNoRoomIsNotMoved()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        const qint32 start = simulatorValue(1, u"present_position");
        setSimulatorValue(1, u"min_angle_limit", start - 10);
        setSimulatorValue(1, u"max_angle_limit", start + 10);
        const auto moved = moveTest(m_found.value(0));
        QVERIFY(moved.has_value());
        QVERIFY(!moved->ok);
        QCOMPARE(moved->failure, feetech::OperationFailure::NoRoomToMove);
        QCOMPARE(writesTo(kGoalAddress), 0);
    }

    void aHealthCheckStoppedBeforeItsFirstServoSaysSo()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})));
        const feetech::OperationResult result = run([&] {
            m_session->submit(
                feetech::operations::checkHealth(m_found, feetech::kDefaultHealthReads));
            m_session->cancel(feetech::Operation::HealthCheck);
        });
        QVERIFY(!result.ok);
        QCOMPARE(result.failure, feetech::OperationFailure::Stopped);
    }

    void aBlockedHornFailsTheMoveTest()
    {
        startBus(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setExternalLoad(1000); }));
        const auto moved = moveTest(m_found.value(0));
        QVERIFY(moved.has_value());
        ServoHealth health;
        feetech::addMoveTest(health, *moved);
        QCOMPARE(health.verdict, Verdict::Fault);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        Q_UNUSED(kTorqueAddress);
    }

    void theReportIsSavedAsJsonAndHtmlAndAFailedSaveSaysWhy()
    {
        ServoHealth hot;
        hot.id = 3;
        hot.model = QStringLiteral("STS3215");
        hot.firmware = QStringLiteral("3.10");
        hot.temperature = 71;
        hot.add(QStringLiteral("temperature-over"), Verdict::Fault,
                QStringLiteral("Hot <servo> & more"));
        feetech::HealthReport report;
        report.port = QStringLiteral("/dev/ttyUSB0");
        report.checkedAt = QDateTime::currentDateTime();
        report.servos = {hot};

        const QString json = m_dir.filePath(QStringLiteral("report.json"));
        QString error;
        QVERIFY2(feetech::saveHealthReport(json, feetech::ReportFormat::Json, report, &error),
                 qPrintable(error));
        QFile jsonFile(json);
        QVERIFY(jsonFile.open(QIODevice::ReadOnly));
        const QJsonObject root = QJsonDocument::fromJson(jsonFile.readAll()).object();
        const QJsonObject servo = root.value(QStringLiteral("servos")).toArray().at(0).toObject();
        QCOMPARE(servo.value(QStringLiteral("id")).toInt(), 3);
        QCOMPARE(servo.value(QStringLiteral("verdict")).toString(), QStringLiteral("fault"));
        QCOMPARE(servo.value(QStringLiteral("temperature")).toDouble(), 71.0);
        QVERIFY(servo.value(QStringLiteral("voltage")).isNull());
        QCOMPARE(servo.value(QStringLiteral("findings"))
                     .toArray()
                     .at(0)
                     .toObject()
                     .value(QStringLiteral("code")),
                 QJsonValue(QStringLiteral("temperature-over")));

        const QString html = m_dir.filePath(QStringLiteral("report.html"));
        QVERIFY2(feetech::saveHealthReport(html, feetech::ReportFormat::Html, report, &error),
                 qPrintable(error));
        QFile htmlFile(html);
        QVERIFY(htmlFile.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(htmlFile.readAll());
        QVERIFY(page.contains(QStringLiteral("<table>")));
        QVERIFY(page.contains(QStringLiteral("Hot &lt;servo&gt; &amp; more")));
        QVERIFY(page.contains(QStringLiteral("temperature-over")));

        const QString nowhere = m_dir.filePath(QStringLiteral("missing/folder/report.html"));
        error.clear();
        QVERIFY(!feetech::saveHealthReport(nowhere, feetech::ReportFormat::Html, report, &error));
        QVERIFY2(error.contains(QStringLiteral("report.html")), qPrintable(error));
        QVERIFY(!QFile::exists(nowhere));
        QCOMPARE(feetech::reportFormatFor(QStringLiteral("a.JSON")), feetech::ReportFormat::Json);
        QVERIFY(!feetech::reportFormatFor(QStringLiteral("a.txt")));
    }
};

QTEST_GUILESS_MAIN(TestHealthCheck)
#include "tst_healthcheck.moc"
