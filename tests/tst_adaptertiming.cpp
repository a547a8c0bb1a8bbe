// End-to-end tests behind simulated USB adapters (servosim --adapter): a Feetech scan, a table
// read and a 50 Hz stream, and PTK polling and an Apply, with the sessions' own timing, over a
// real pty. No timeout, no missed sample, and nothing in the packet log reads as an error.
#include "busoperations.h"
#include "feetechsession.h"
#include "ptksession.h"
#include "simclient.h"
#include "simulatorthread.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

namespace {

constexpr qint32 k1M = 1000000;
constexpr int kServos = 6;

// The errors a session's packet log showed, one line each.
class ErrorLog
{
public:
    template<typename Session>
    explicit ErrorLog(Session &session)
    {
        QObject::connect(&session, &Session::packetLogged,
                         [this](const seriallink::PacketLogEntry &entry) {
                             if (!entry.error.isEmpty())
                                 m_errors.append(entry.error + QStringLiteral(": ")
                                                 + QString::fromLatin1(entry.bytes.toHex(' ')));
                         });
    }
    QString text() const { return m_errors.join(QLatin1Char('\n')); }
    bool isEmpty() const { return m_errors.isEmpty(); }

private:
    QStringList m_errors;
};

void addProfiles()
{
    QTest::addColumn<QString>("profile");
    // The slowest (FTDI at its default latency timer) and the least regular (CH340).
    for (const char *name : {"ftdi", "ch340"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

} // namespace

class TestAdapterTiming : public QObject
{
    Q_OBJECT

private slots:
    void feetechScanReadAndStreamWithoutFalseTimeouts_data() { addProfiles(); }
    void feetechScanReadAndStreamWithoutFalseTimeouts()
    {
        QFETCH(QString, profile);
        QTemporaryDir dir;
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Feetech;
        options.linkPath = dir.filePath(QStringLiteral("bus"));
        for (int id = 1; id <= kServos; ++id)
            options.servos.append({quint8(id), QStringLiteral("STS3215"), k1M});
        options.adapter = sim::adapterProfile(profile);
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options, &error), qPrintable(error));

        feetech::Session session;
        ErrorLog errors(session);
        QVector<feetech::ServoInfo> found;
        QObject::connect(&session, &feetech::Session::servoFound,
                         [&found](const feetech::ServoInfo &servo) { found.append(servo); });
        QSignalSpy scanned(&session, &feetech::Session::scanFinished);
        QSignalSpy finished(&session, &feetech::Session::operationFinished);
        session.open(simulator.linkPath(), k1M, seriallink::EchoMode::Auto);
        feetech::ScanOptions scan;
        scan.lastId = 8;
        session.submit(feetech::operations::scan(scan));
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 30000);
        QCOMPARE(found.size(), kServos);

        session.submit(feetech::operations::read(found.at(2), {}, feetech::ReadSource::Read));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QVERIFY(finished.first().first().value<feetech::OperationResult>().ok);

        feetech::TelemetryStats stats;
        QObject::connect(&session, &feetech::Session::telemetryStats,
                         [&stats](const feetech::TelemetryStats &s) { stats = s; });
        feetech::TelemetryOptions stream;
        stream.servos = found;
        stream.rateHz = 50;
        session.startTelemetry(stream);
        // Twenty cycles, however long a busy machine takes for them.
        QTRY_VERIFY_WITH_TIMEOUT(stats.samples >= kServos * 20, 20000);
        session.stopTelemetry();
        QCOMPARE(stats.missed, 0);
        QCOMPARE(session.counters().timeouts, 0);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.text()));
    }

    void aTelemetryAnswerAfterItsWaitIsASampleCountedLate()
    {
        // Every answer delayed by up to 150 ms: many come after the longest wait (60 ms).
        QTemporaryDir dir;
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Feetech;
        options.linkPath = dir.filePath(QStringLiteral("bus"));
        for (int id = 1; id <= 3; ++id)
            options.servos.append({quint8(id), QStringLiteral("STS3215"), k1M});
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options, &error), qPrintable(error));
        feetech::Session session;
        QSignalSpy scanned(&session, &feetech::Session::scanFinished);
        QVector<feetech::ServoInfo> found;
        QObject::connect(&session, &feetech::Session::servoFound,
                         [&found](const feetech::ServoInfo &servo) { found.append(servo); });
        session.open(simulator.linkPath(), k1M, seriallink::EchoMode::Auto);
        feetech::ScanOptions scan;
        scan.lastId = 4;
        session.submit(feetech::operations::scan(scan));
        QTRY_COMPARE_WITH_TIMEOUT(scanned.size(), 1, 30000);
        QCOMPARE(found.size(), 3);
        sim::FaultSettings faults;
        faults.delayMs = 150;
        simulator.call([&](sim::Simulator &running) { running.setFaults(faults, 5); });

        QStringList unexpected;
        QObject::connect(&session, &feetech::Session::packetLogged,
                         [&unexpected](const seriallink::PacketLogEntry &entry) {
                             if (!entry.error.isEmpty() && !entry.bytes.isEmpty())
                                 unexpected.append(entry.error);
                         });
        qint64 samples = 0;
        QObject::connect(
            &session, &feetech::Session::telemetry,
            [&samples](const QVector<feetech::FeedbackSample> &batch) { samples += batch.size(); });
        feetech::TelemetryStats stats;
        QObject::connect(&session, &feetech::Session::telemetryStats,
                         [&stats](const feetech::TelemetryStats &s) { stats = s; });
        feetech::TelemetryOptions stream;
        stream.servos = found;
        stream.rateHz = 20;
        stream.missesBeforeMissing = 1000; // keep every servo in the cycle
        session.startTelemetry(stream);
        QTRY_VERIFY_WITH_TIMEOUT(stats.late >= 3, 20000);
        session.stopTelemetry();
        // Each late answer was a sample of its own servo, and none was taken for an error.
        QVERIFY(session.counters().lateReplies >= stats.late);
        QCOMPARE(samples, stats.samples);
        qint64 perServo = 0;
        for (const feetech::ServoTelemetry &servo : std::as_const(stats.servos))
            perServo += servo.late;
        QCOMPARE(perServo, stats.late);
        QVERIFY2(unexpected.isEmpty(), qPrintable(unexpected.join(QLatin1Char('\n'))));
    }

    void ptkPollingAndApplyWithoutFalseTimeouts_data() { addProfiles(); }
    void ptkPollingAndApplyWithoutFalseTimeouts()
    {
        QFETCH(QString, profile);
        QTemporaryDir dir;
        // PTK's programmer is a single-wire adapter: every byte sent comes back first.
        sim::SimulatorOptions options = testsupport::ptkOptions(dir, QStringLiteral("ptk"), true);
        options.adapter = sim::adapterProfile(profile);
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options, &error), qPrintable(error));

        ptk::Session session;
        ErrorLog errors(session);
        ptk::ParameterSet values;
        QObject::connect(&session, &ptk::Session::valuesRead,
                         [&values](const ptk::ParameterSet &read, ptk::ReadSource) {
                             for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
                                 if (const auto value = read.value(meta.parameter))
                                     values.set(meta.parameter, *value);
                             }
                         });
        session.open(simulator.linkPath(), 115200, seriallink::EchoMode::Auto);
        session.setPolling(true);
        QTRY_VERIFY_WITH_TIMEOUT(values.isComplete(), 10000);
        values.set(ptk::Parameter::Gain,
                   quint16(*values.value(ptk::Parameter::Gain) == 20 ? 21 : 20));
        QSignalSpy applied(&session, &ptk::Session::applyFinished);
        session.apply(values);
        QTRY_COMPARE_WITH_TIMEOUT(applied.size(), 1, 20000);
        QVERIFY2(applied.first().first().toBool(), qPrintable(applied.first().at(1).toString()));
        QCOMPARE(testsupport::ptkServoValues(simulator).value(ptk::Parameter::Gain),
                 values.value(ptk::Parameter::Gain));
        QCOMPARE(session.counters().timeouts, 0);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.text()));
    }
};

QTEST_GUILESS_MAIN(TestAdapterTiming)
#include "tst_adaptertiming.moc"
