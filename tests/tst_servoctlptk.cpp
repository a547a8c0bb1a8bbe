// servoctl ptk against the simulated servo over a pty: output, JSON and exit codes.
#include "servoctlrun.h"
#include "simclient.h"

#include "ptkparameters.h"
#include "simulatorthread.h"
#include "virtualptkservo.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using testsupport::runServoctl;

class TestServoctlPtk : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    sim::SimulatorThread m_simulator;
    QString m_logPath;

    QStringList device(const QStringList &arguments) const
    {
        return QStringList {QStringLiteral("--port"), m_simulator.linkPath()} + arguments;
    }

    ptk::ParameterSet servoValues()
    {
        ptk::ParameterSet values;
        m_simulator.call([&](sim::Simulator &s) { values = s.ptkServo()->values(); });
        return values;
    }

    int framesReceived() const
    {
        return int(testsupport::logLinesStartingWith(m_logPath, QStringLiteral("in ")).size());
    }

private slots:
    void init()
    {
        QVERIFY(m_dir.isValid());
        static int run = 0;
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Ptk;
        options.linkPath = m_dir.filePath(QStringLiteral("ptk%1").arg(++run));
        m_logPath = options.linkPath + QStringLiteral(".log");
        options.logPath = m_logPath;
        options.echo = run % 2 == 0; // every other test through a single-wire adapter
        options.instant = testsupport::instantTestDevice();
        QString error;
        QVERIFY2(m_simulator.start(options, &error), qPrintable(error));
    }

    void cleanup() { m_simulator.stop(); }

    void readJsonIsKeyedByParameterInUserUnits()
    {
        const auto result = runServoctl(
            device({QStringLiteral("--json"), QStringLiteral("ptk"), QStringLiteral("read")}));
        QCOMPARE(result.exitCode, 0);
        const QJsonObject values = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(values.size(), ptk::kParameterCount);
        QCOMPARE(values.value(QStringLiteral("gain")).toInt(), 29);
        QCOMPARE(values.value(QStringLiteral("min_pulse_us")).toDouble(), 500.0);
        QCOMPARE(values.value(QStringLiteral("max_pulse_us")).toDouble(), 2500.0);
        QCOMPARE(values.value(QStringLiteral("inversion")), QJsonValue(true));
        QCOMPARE(values.value(QStringLiteral("soft_start")), QJsonValue(false));
    }

    void readTextListsEveryParameter()
    {
        const auto result = runServoctl(device({QStringLiteral("ptk"), QStringLiteral("read")}));
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(result.out.count(u'\n'), ptk::kParameterCount);
        QVERIFY(result.out.contains(QStringLiteral("min_pulse_us      500 µs")));
    }

    void writeChangesTheServoAndVerifies()
    {
        const auto result = runServoctl(
            device({QStringLiteral("ptk"), QStringLiteral("write"), QStringLiteral("gain=21"),
                    QStringLiteral("max_pulse_us=2000"), QStringLiteral("soft_start=on")}));
        QCOMPARE(result.exitCode, 0);
        const ptk::ParameterSet values = servoValues();
        QCOMPARE(*values.value(ptk::Parameter::Gain), quint16(21));
        QCOMPARE(*values.value(ptk::Parameter::MaxPulse), quint16(8000));
        QCOMPARE(*values.value(ptk::Parameter::SoftStart), quint16(1));
        QCOMPARE(*values.value(ptk::Parameter::Damping), quint16(12)); // untouched
    }

    void aWriteTheServoIgnoresExitsOneNamingTheMismatch()
    {
        m_simulator.call([](sim::Simulator &s) { s.ptkServo()->ignoreWrites(0x43); });
        const auto result =
            runServoctl(device({QStringLiteral("--json"), QStringLiteral("ptk"),
                                QStringLiteral("write"), QStringLiteral("deadband=7")}));
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QStringLiteral("deadband")));
        const QJsonObject report = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(report.value(QStringLiteral("verified")), QJsonValue(false));
        const QJsonArray mismatches = report.value(QStringLiteral("mismatches")).toArray();
        QCOMPARE(mismatches.size(), 1);
        QCOMPARE(mismatches.first()[QStringLiteral("key")].toString(), QStringLiteral("deadband"));
        QCOMPARE(mismatches.first()[QStringLiteral("read")].toInt(), 15);
    }

    void badNamesAndValuesExitTwoAndSendNothing_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::newRow("unknown name")
            << QStringList {QStringLiteral("write"), QStringLiteral("gian=3")};
        QTest::newRow("out of range")
            << QStringList {QStringLiteral("write"), QStringLiteral("gain=31")};
        QTest::newRow("pulse out of range")
            << QStringList {QStringLiteral("write"), QStringLiteral("min_pulse_us=499")};
        QTest::newRow("not a number")
            << QStringList {QStringLiteral("write"), QStringLiteral("gain=lots")};
        QTest::newRow("one bad among good") << QStringList {
            QStringLiteral("write"), QStringLiteral("gain=3"), QStringLiteral("neutral=9000")};
        QTest::newRow("no assignment") << QStringList {QStringLiteral("write")};
        QTest::newRow("unknown command") << QStringList {QStringLiteral("flash")};
        QTest::newRow("missing profile")
            << QStringList {QStringLiteral("load"), QStringLiteral("/nonexistent/p.json")};
        QTest::newRow("bad echo mode")
            << QStringList {QStringLiteral("--echo=maybe"), QStringLiteral("read")};
    }

    void badNamesAndValuesExitTwoAndSendNothing()
    {
        QFETCH(QStringList, arguments);
        const auto result = runServoctl(device(QStringList {QStringLiteral("ptk")} + arguments));
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.out.isEmpty());
        QCOMPARE(result.err.count(u'\n'), 1);
        QCOMPARE(framesReceived(), 0);
    }

    void everyCommandWithMalformedArgumentsExitsTwoAndSendsNothing()
    {
        const QStringList commands = {QStringLiteral("read"), QStringLiteral("write gain=3"),
                                      QStringLiteral("save"), QStringLiteral("load"),
                                      QStringLiteral("monitor")};
        const QStringList malformed = {QStringLiteral("--bogus 1"),
                                       QStringLiteral("--id 1"),
                                       QStringLiteral("--rate nan"),
                                       QStringLiteral("--interval -5"),
                                       QStringLiteral("--duration x"),
                                       QStringLiteral("--echo"),
                                       QStringLiteral("--echo on --echo off"),
                                       QStringLiteral("--ids 1-3"),
                                       QStringLiteral("--json=yes"),
                                       QStringLiteral("a.json b.json c.json")};
        QStringList wrong;
        for (const QString &command : commands) {
            for (const QString &arguments : malformed) {
                const QString line = QStringLiteral("ptk ") + command + u' ' + arguments;
                const auto result = runServoctl(device(line.split(u' ')));
                if (result.exitCode != 2 || result.err.count(u'\n') != 1)
                    wrong.append(QStringLiteral("%1: exit %2, %3")
                                     .arg(line)
                                     .arg(result.exitCode)
                                     .arg(result.err.trimmed()));
            }
        }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u'\n')));
        QCOMPARE(framesReceived(), 0);
    }

    void anInvalidProfileIsRefusedBeforeAnythingIsSent()
    {
        const QString path = m_dir.filePath(QStringLiteral("bad.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format":"servobench-profile","version":1,"family":"ptk",
                      "parameters":{"gain":20,"neutral":99999}})");
        file.close();
        const auto result =
            runServoctl(device({QStringLiteral("ptk"), QStringLiteral("load"), path}));
        QCOMPARE(result.exitCode, 2);
        QVERIFY(result.err.contains(QStringLiteral("neutral")));
        QCOMPARE(framesReceived(), 0);
    }

    void aSavedProfileLoadsBackOntoTheServo()
    {
        const QString path = m_dir.filePath(QStringLiteral("servo.json"));
        QCOMPARE(
            runServoctl(device({QStringLiteral("ptk"), QStringLiteral("save"), path})).exitCode, 0);
        const ptk::ParameterSet original = servoValues();
        QCOMPARE(runServoctl(device({QStringLiteral("ptk"), QStringLiteral("write"),
                                     QStringLiteral("gain=3"), QStringLiteral("neutral=3000")}))
                     .exitCode,
                 0);
        QVERIFY(!(servoValues() == original));
        const auto loaded =
            runServoctl(device({QStringLiteral("ptk"), QStringLiteral("load"), path}));
        QCOMPARE(loaded.exitCode, 0);
        QCOMPARE(servoValues(), original);
    }

    void monitorCsvHasAHeaderAndOneRowPerRefresh()
    {
        const auto result = runServoctl(
            device({QStringLiteral("--csv"), QStringLiteral("--duration"), QStringLiteral("1"),
                    QStringLiteral("ptk"), QStringLiteral("monitor")}));
        QCOMPARE(result.exitCode, 0);
        const QStringList lines = result.out.trimmed().split(u'\n');
        QVERIFY(lines.size() >= 2);
        QCOMPARE(lines.first().split(u',').size(), 1 + ptk::kParameterCount);
        QVERIFY(lines.first().startsWith(QStringLiteral("time_s,gain,")));
        for (const QString &row : lines.mid(1)) {
            const QStringList cells = row.split(u',');
            QCOMPARE(cells.size(), 1 + ptk::kParameterCount);
            QCOMPARE(cells.at(1), QStringLiteral("29"));
        }
    }

    void aMissingPortExitsOneWithTheReason()
    {
        const auto result =
            runServoctl({QStringLiteral("--port"), m_dir.filePath(QStringLiteral("absent")),
                         QStringLiteral("ptk"), QStringLiteral("read")});
        QCOMPARE(result.exitCode, 1);
        QVERIFY(result.err.contains(QStringLiteral("does not exist")));
    }

    void aSilentServoExitsOne()
    {
        m_simulator.stop();
        // A port with nothing behind it: the simulator's link is gone, so use a fresh one
        // whose servo ignores every query by being of the other family.
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Feetech;
        options.linkPath = m_dir.filePath(QStringLiteral("silent"));
        options.servos = {{1, QStringLiteral("STS3215"), 1000000}};
        QString error;
        QVERIFY2(m_simulator.start(options, &error), qPrintable(error));
        const auto result = runServoctl(device({QStringLiteral("ptk"), QStringLiteral("read")}));
        QCOMPARE(result.exitCode, 1);
        QVERIFY(!result.err.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestServoctlPtk)
#include "tst_servoctlptk.moc"
