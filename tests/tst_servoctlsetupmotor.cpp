// servoctl feetech setup-motor against the simulated bus over a pty: a whole arm set up one
// servo at a time, the JSON report, and every refusal with nothing written and its exit code.
#include "pluggedbus.h"
#include "servoctlrun.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using testsupport::runServoctl;

namespace {

constexpr qint32 k1M = 1000000;

const QString kArm = QStringLiteral("SO-101 follower arm");

QString armFile()
{
    return QStringLiteral(SERVOBENCH_SOURCE_DIR "/resources/robots/so101-follower.json");
}

} // namespace

class TestServoctlSetupMotor : public testsupport::PluggedBusTest
{
    Q_OBJECT

private:
    feetech::RobotTemplate m_robot = testsupport::builtInRobot(kArm);

    // servoctl --port LINK [--json] feetech setup-motor `line`.
    testsupport::ServoctlResult setupMotor(const QString &line, bool json = false) const
    {
        QStringList arguments {QStringLiteral("--port"), m_simulator->linkPath()};
        if (json)
            arguments.append(QStringLiteral("--json"));
        arguments << QStringLiteral("feetech") << QStringLiteral("setup-motor");
        return runServoctl(arguments + line.split(u' ', Qt::SkipEmptyParts));
    }

    // A setup-motor that must fail with exit 1, writing nothing to any servo; its message.
    QString refused(const QString &line)
    {
        const QVector<testsupport::PluggedServo> before = pluggedServos();
        const auto result = setupMotor(line);
        [&] {
            QCOMPARE(result.exitCode, int(cli::ExitDeviceFailure));
            QVERIFY(result.out.isEmpty());
            const QVector<testsupport::PluggedServo> after = pluggedServos();
            QCOMPARE(after.size(), before.size());
            for (int i = 0; i < before.size(); ++i) {
                QCOMPARE(after.at(i).revision, before.at(i).revision);
                QCOMPARE(after.at(i).eeprom, before.at(i).eeprom);
                QCOMPARE(after.at(i).id, before.at(i).id);
            }
            QVERIFY(testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write)
                        .isEmpty());
        }();
        return result.err.trimmed();
    }

    // A setup-motor that must be refused as a usage error (exit 2) with nothing sent.
    QString usageError(const QString &line)
    {
        const auto result = setupMotor(line);
        [&] {
            QCOMPARE(result.exitCode, int(cli::ExitUsage));
            QVERIFY(testsupport::feetechFramesReceived(logPath()).isEmpty());
        }();
        return result.err.trimmed();
    }

private slots:
    void init()
    {
        QString error;
        QVERIFY2(startEmptyBus(&error), qPrintable(error));
    }

    void cleanup()
    {
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void aWholeArmIsSetUpOneFactoryServoAtATime()
    {
        // As LeRobot asks: only the servo being set up is connected; each arrives at ID 1.
        for (const feetech::RobotJoint &joint : std::as_const(m_robot.joints)) {
            unplugAll();
            QVERIFY(plug(1, QStringLiteral("STS3215"), testsupport::kFactoryBaud));
            const auto result =
                setupMotor(QStringLiteral("--id %1 --settings %2").arg(joint.id).arg(armFile()));
            QVERIFY2(result.exitCode == cli::ExitOk, qPrintable(result.err));
            QVERIFY2(result.out.contains(joint.name + QStringLiteral(" is set up")),
                     qPrintable(result.out));
            verifySetUp(0, m_robot, joint);
            powerCycle();
            verifySetUp(0, m_robot, joint, Settings::EepromOnly);
        }
    }

    void jsonSaysTheModelWhereTheServoWasAndWhereItIsNow()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), 115200));
        const auto result = setupMotor(QStringLiteral("--id 4 --baud 500000"), true);
        QCOMPARE(result.exitCode, int(cli::ExitOk));
        const QJsonObject report = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(report.value(QStringLiteral("model")).toString(), QStringLiteral("STS3215"));
        const QJsonObject from {{QStringLiteral("id"), 1}, {QStringLiteral("baud"), 115200}};
        const QJsonObject to {{QStringLiteral("id"), 4}, {QStringLiteral("baud"), 500000}};
        QCOMPARE(report.value(QStringLiteral("from")).toObject(), from);
        QCOMPARE(report.value(QStringLiteral("to")).toObject(), to);
        QCOMPARE(pluggedServos().first().id, quint8(4));
        QCOMPARE(pluggedServos().first().baud, 500000);
    }

    void aServoFoundAt500kbpsMovesTo1MbpsByDefault()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), 500000));
        const auto result = setupMotor(QStringLiteral("--id 2 --model sts3215"));
        QVERIFY2(result.exitCode == cli::ExitOk, qPrintable(result.err));
        QCOMPARE(pluggedServos().first().id, quint8(2));
        QCOMPARE(pluggedServos().first().baud, k1M);
    }

    void noServoExitsOne()
    {
        QCOMPARE(refused(QStringLiteral("--id 2")),
                 QStringLiteral("servoctl: No servo answers at any rate: check the power and the "
                                "cable, and connect the next servo."));
    }

    void twoServosAtDifferentIdsExitOne()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(3, QStringLiteral("STS3215"), k1M));
        QVERIFY(refused(QStringLiteral("--id 2")).endsWith(QLatin1String("at a time.")));
    }

    void twoServosAtOneIdExitOne()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QCOMPARE(
            refused(QStringLiteral("--id 2")),
            QStringLiteral("servoctl: Two servos answer at ID 1; connect them one at a time."));
    }

    void aServoAtAnotherRateBesidesOneAt1MbpsExitsOne()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(plug(5, QStringLiteral("STS3215"), 115200));
        const QString message = refused(QStringLiteral("--id 2"));
        QVERIFY2(message.contains(QLatin1String("2 servos answer")), qPrintable(message));
        QVERIFY(message.contains(QLatin1String("ID 5 at 115")));
    }

    void aModelOtherThanAskedForExitsOne()
    {
        QVERIFY(plug(1, QStringLiteral("SCS15"), k1M));
        const QString message = refused(QStringLiteral("--id 2 --model STS3215"));
        QVERIFY2(message.contains(QLatin1String("model SCS15")), qPrintable(message));
        QVERIFY(message.contains(QLatin1String("needs model STS3215")));
    }

    void theTemplatesModelIsExpectedToo()
    {
        QVERIFY(plug(1, QStringLiteral("SCS15"), k1M));
        QVERIFY(refused(QStringLiteral("--id 3 --settings %1").arg(armFile()))
                    .contains(QLatin1String("elbow_flex needs model STS3215")));
    }

    void usageErrorsExitTwoWithNothingSent()
    {
        QVERIFY(plug(1, QStringLiteral("STS3215"), k1M));
        QVERIFY(usageError(QString()).contains(QLatin1String("needs --id N")));
        QVERIFY(!usageError(QStringLiteral("--id 254")).isEmpty());
        QVERIFY(!usageError(QStringLiteral("--id two")).isEmpty());
        QVERIFY(usageError(QStringLiteral("--id 2 --baud 12345"))
                    .contains(QLatin1String("not a Feetech baud rate")));
        QVERIFY(usageError(QStringLiteral("--id 2 --model XYZ123"))
                    .contains(QLatin1String("no model with a known register table")));
        QVERIFY(usageError(QStringLiteral("--id 2 --settings %1")
                               .arg(m_dir.filePath(QStringLiteral("none.json"))))
                    .contains(QLatin1String("none.json")));
        const QString notJson = m_dir.filePath(QStringLiteral("broken.json"));
        QFile broken(notJson);
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{ not json");
        broken.close();
        QVERIFY(usageError(QStringLiteral("--id 2 --settings %1").arg(notJson))
                    .contains(QLatin1String("broken.json")));
        QVERIFY(usageError(QStringLiteral("--id 9 --settings %1").arg(armFile()))
                    .contains(QLatin1String("has no joint with ID 9")));
        QVERIFY(usageError(QStringLiteral("--id 2 --model SCS15 --settings %1").arg(armFile()))
                    .contains(QLatin1String("does not match")));
        QVERIFY(usageError(QStringLiteral("--id 2 extra")).contains(QLatin1String("no arguments")));
        QCOMPARE(pluggedServos().first().id, quint8(1));
    }

    void helpNamesTheCommandAndWhatItsSettingsFileIs()
    {
        const auto result = runServoctl({QStringLiteral("--help")});
        QVERIFY(result.out.contains(QLatin1String("feetech setup-motor --id N")));
        QVERIFY(result.out.contains(QLatin1String("ROBOT: a robot template file")));
    }
};

QTEST_GUILESS_MAIN(TestServoctlSetupMotor)
#include "tst_servoctlsetupmotor.moc"
