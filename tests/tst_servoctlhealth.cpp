// servoctl feetech health against a simulated bus over a pty: verdicts as text and JSON, exit
// codes, reads only unless --move-test, which says what moves first.
#include "feetechbus.h"
#include "servoctlrun.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using testsupport::runServoctl;

namespace {

constexpr qint32 k1M = 1000000;

QJsonArray arrayOf(const QString &json)
{
    return QJsonDocument::fromJson(json.toUtf8()).array();
}

QStringList findingCodes(const QJsonObject &servo)
{
    QStringList codes;
    for (const QJsonValue &finding : servo.value(QStringLiteral("findings")).toArray())
        codes.append(finding[QStringLiteral("code")].toString());
    return codes;
}

} // namespace

class TestServoctlHealth : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    void startBus(std::initializer_list<QStringView> models)
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, models)), &error),
                 qPrintable(error));
    }

    testsupport::ServoctlResult health(const QString &line) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath(),
                                        QStringLiteral("feetech"), QStringLiteral("health")}
                           + line.split(u' ', Qt::SkipEmptyParts));
    }

    int writesReceived() const
    {
        return int(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size());
    }

private slots:
    void cleanup()
    {
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aHealthyBusExitsZeroWithOneJsonEntryPerServoAndWritesNothing()
    {
        startBus({u"STS3215", u"SCS0009"});
        const auto result = health(QStringLiteral("--ids 1,2 --json"));
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QJsonArray servos = arrayOf(result.out);
        QCOMPARE(servos.size(), 2);
        for (const QJsonValue &value : servos) {
            const QJsonObject servo = value.toObject();
            for (const char *field :
                 {"id", "verdict", "findings", "voltage", "temperature", "firmware"})
                QVERIFY2(servo.contains(QLatin1String(field)), field);
            QCOMPARE(servo[QStringLiteral("verdict")].toString(), QStringLiteral("ok"));
            QVERIFY(servo[QStringLiteral("findings")].toArray().isEmpty());
            QVERIFY(servo[QStringLiteral("voltage")].toDouble() > 6.0);
            QVERIFY(servo[QStringLiteral("temperature")].isDouble());
        }
        QCOMPARE(servos.at(0)[QStringLiteral("id")].toInt(), 1);
        QCOMPARE(servos.at(0)[QStringLiteral("firmware")].toString(), QStringLiteral("3.10"));
        QCOMPARE(writesReceived(), 0);
    }

    void theTextSaysEachServosVerdictAndCommunication()
    {
        startBus({u"STS3215"});
        const auto result = health(QStringLiteral("--ids 1"));
        QCOMPARE(result.exitCode, 0);
        QVERIFY2(result.out.contains(QStringLiteral("servo 1 (STS3215, firmware 3.10): OK")),
                 qPrintable(result.out));
        QVERIFY(result.out.contains(QStringLiteral("20/20 answered")));
    }

    void anOverVoltageServoExitsOneWithItsFinding()
    {
        startBus({u"STS3215", u"STS3215"});
        QVERIFY(withServo(2, k1M, [](sim::VirtualFeetechServo &s) { s.setSupplyVoltage(12.0); }));
        const auto result = health(QStringLiteral("--ids 1-2 --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonArray servos = arrayOf(result.out);
        QCOMPARE(servos.size(), 2);
        QCOMPARE(servos.at(0)[QStringLiteral("verdict")].toString(), QStringLiteral("ok"));
        QCOMPARE(servos.at(1)[QStringLiteral("verdict")].toString(), QStringLiteral("fault"));
        QVERIFY2(findingCodes(servos.at(1).toObject()).contains(QStringLiteral("voltage-high")),
                 qPrintable(result.out));
    }

    void aHotServoWarnsWithoutFailingTheExitCode()
    {
        startBus({u"STS3215"});
        const qint32 maximum = simulatorValue(1, u"max_temperature");
        QVERIFY(withServo(
            1, k1M, [maximum](sim::VirtualFeetechServo &s) { s.setTemperature(maximum - 3); }));
        const auto result = health(QStringLiteral("--ids 1 --json"));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject servo = arrayOf(result.out).at(0).toObject();
        QCOMPARE(servo[QStringLiteral("verdict")].toString(), QStringLiteral("warning"));
        QVERIFY(findingCodes(servo).contains(QStringLiteral("temperature-high")));
    }

    void aServoThatDoesNotAnswerIsAFault()
    {
        startBus({u"STS3215"});
        const auto result = health(QStringLiteral("--ids 1,9 --json"));
        QCOMPARE(result.exitCode, 1);
        const QJsonArray servos = arrayOf(result.out);
        QCOMPARE(servos.size(), 2);
        QCOMPARE(servos.at(0)[QStringLiteral("verdict")].toString(), QStringLiteral("ok"));
        QCOMPARE(servos.at(1)[QStringLiteral("id")].toInt(), 9);
        QCOMPARE(servos.at(1)[QStringLiteral("verdict")].toString(), QStringLiteral("fault"));
        QVERIFY(servos.at(1)[QStringLiteral("firmware")].isNull());
    }

    void theMoveTestSaysWhatMovesAndReportsItsMetrics()
    {
        startBus({u"STS3215"});
        const auto result = health(QStringLiteral("--ids 1 --move-test --json"));
        QVERIFY2(result.exitCode == 0, qPrintable(result.err + result.out));
        QVERIFY2(result.err.contains(QStringLiteral("moving servo 1 by 100 steps")),
                 qPrintable(result.err));
        const QJsonObject move = arrayOf(result.out).at(0)[QStringLiteral("move")].toObject();
        QVERIFY(move[QStringLiteral("ok")].toBool());
        QVERIFY(move[QStringLiteral("rise_time_s")].toDouble() > 0.0);
        QVERIFY(move.contains(QStringLiteral("overshoot_percent")));
        QVERIFY(move.contains(QStringLiteral("steady_state_error")));
        QVERIFY(writesReceived() > 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void aServoWithAFaultIsNotMoved()
    {
        startBus({u"STS3215"});
        QVERIFY(withServo(1, k1M, [](sim::VirtualFeetechServo &s) { s.setSupplyVoltage(12.0); }));
        const auto result = health(QStringLiteral("--ids 1 --move-test"));
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.out.contains(QStringLiteral("not run")), qPrintable(result.out));
        QCOMPARE(writesReceived(), 0);
    }

    void withoutIdsItIsAUsageErrorAndNothingIsSent()
    {
        startBus({u"STS3215"});
        const auto result = health(QString());
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.err.contains(QStringLiteral("--ids")));
        QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
        QCOMPARE(health(QStringLiteral("--ids 1 --csv")).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestServoctlHealth)
#include "tst_servoctlhealth.moc"
