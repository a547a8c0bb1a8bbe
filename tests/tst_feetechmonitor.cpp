// End-to-end tests of Feetech telemetry and bus-wide control against a simulated bus on a pty.
#include "busoperations.h"
#include "feetechbus.h"
#include "feetechsession.h"
#include "operationlog.h"

#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using feetech::FeedbackSample;
using feetech::OperationResult;
using feetech::ServoInfo;
using feetech::Session;

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k500k = 500000;

} // namespace

class TestFeetechMonitor : public testsupport::FeetechSessionTest
{
    Q_OBJECT

private:
    QVector<FeedbackSample> m_samples;
    feetech::TelemetryStats m_stats;

    ServoInfo found(quint8 id) const
    {
        for (const ServoInfo &servo : m_found) {
            if (servo.id == id)
                return servo;
        }
        return {};
    }

    int samplesOf(quint8 id) const
    {
        return int(std::count_if(m_samples.begin(), m_samples.end(),
                                 [id](const FeedbackSample &s) { return s.id == id; }));
    }

    // The frames the simulated servos heard, decoded.
    QVector<feetech::Packet> packetsReceived() const
    {
        return testsupport::feetechPacketsReceived(logPath());
    }

    // Runs the event loop until `condition` holds. QTest::qWait sleeps between its rounds of
    // events, which would cap a fast telemetry stream at about 100 cycles a second.
    static bool runUntil(const std::function<bool()> &condition, int timeoutMs)
    {
        QEventLoop loop;
        QTimer check;
        QObject::connect(&check, &QTimer::timeout, &loop, [&] {
            if (condition())
                loop.quit();
        });
        check.start(5);
        QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
        if (!condition())
            loop.exec();
        return condition();
    }

private slots:
    void init()
    {
        m_found.clear();
        m_samples.clear();
        // STS3215 ×2, SCS15, HLS at 1 Mbps; an STS3215 at 500 kbps.
        auto servos = testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS15", u"HLS"});
        servos.append({6, QStringLiteral("STS3215"), k500k});
        QString error;
        QVERIFY2(startSession(busOptions(servos), &error), qPrintable(error));
        connect(m_session.get(), &Session::telemetry, this,
                [this](const QVector<FeedbackSample> &batch) { m_samples += batch; });
        connect(m_session.get(), &Session::telemetryStats, this,
                [this](const feetech::TelemetryStats &stats) { m_stats = stats; });
        QSignalSpy finished(m_session.get(), &Session::scanFinished);
        feetech::ScanOptions options;
        options.bauds = {k1M, k500k};
        options.lastId = 10;
        m_session->submit(feetech::operations::scan(options));
        QVERIFY(!finished.isEmpty() || finished.wait(30000));
        QCOMPARE(m_found.size(), 5);
    }

    void cleanup() { stopSession(); }

    void samplesArriveForEverySelectedServo()
    {
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(2)->setValue(u"goal_position", 3000);
            simulator.feetechBus()->findServo(2)->setValue(u"torque_enable", 1);
        });
        feetech::TelemetryOptions options;
        options.servos = {found(1), found(2), found(3), found(4), found(6)};
        options.rateHz = 100;
        m_session->startTelemetry(options);
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(1) >= 20 && samplesOf(2) >= 20 && samplesOf(3) >= 20
                                     && samplesOf(4) >= 20 && samplesOf(6) >= 20,
                                 10000);
        m_session->stopTelemetry();
        // Decoded in real units, with the servo's own clock order.
        const auto sts = std::find_if(m_samples.begin(), m_samples.end(),
                                      [](const FeedbackSample &s) { return s.id == 1; });
        QVERIFY(sts->value(feetech::Quantity::Voltage).has_value());
        QVERIFY(*sts->value(feetech::Quantity::Voltage) > 5.0);
        QVERIFY(sts->value(feetech::Quantity::Current).has_value());
        const auto scs = std::find_if(m_samples.begin(), m_samples.end(),
                                      [](const FeedbackSample &s) { return s.id == 3; });
        QVERIFY(scs->value(feetech::Quantity::Position).has_value());
        QVERIFY(!scs->value(feetech::Quantity::Current).has_value()); // no documented scale
        for (int i = 1; i < m_samples.size(); ++i)
            QVERIFY(m_samples.at(i).steadyUs >= m_samples.at(i - 1).steadyUs);
        // Servo 2 was moving toward 3000: its positions rise.
        QVector<double> positions;
        for (const FeedbackSample &sample : std::as_const(m_samples)) {
            if (sample.id == 2)
                positions.append(*sample.value(feetech::Quantity::Position));
        }
        QVERIFY(positions.last() > positions.first());
        QCOMPARE(m_stats.running, false);
        QVERIFY(m_stats.cycles >= 20);
        QCOMPARE(m_stats.missed, 0);
    }

    void syncReadForStsAndSingleReadsForScs()
    {
        feetech::TelemetryOptions options;
        options.servos = {found(1), found(2), found(3), found(4)};
        options.rateHz = 50;
        // The scan read each servo's feedback (whether two servos share its ID): not the stream.
        const qsizetype beforeStream = packetsReceived().size();
        m_session->startTelemetry(options);
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(3) >= 5 && samplesOf(1) >= 5, 10000);
        m_session->stopTelemetry();
        int syncReads = 0;
        int scsReads = 0;
        for (const feetech::Packet &packet : packetsReceived().mid(beforeStream)) {
            if (packet.code == quint8(feetech::Instruction::SyncRead)) {
                ++syncReads;
                // Address 56, 15 bytes, the SYNC READ families only, in the order asked.
                QCOMPARE(packet.id, feetech::kBroadcastId);
                QCOMPARE(packet.parameters, QByteArray::fromHex("380f010204"));
            }
            if (packet.code == quint8(feetech::Instruction::Read) && packet.id == 3
                && packet.parameters == QByteArray::fromHex("380f"))
                ++scsReads;
            QVERIFY(!(packet.code == quint8(feetech::Instruction::Read)
                      && (packet.id == 1 || packet.id == 2)
                      && packet.parameters == QByteArray::fromHex("380f")));
        }
        QVERIFY(syncReads >= 5);
        QVERIFY(scsReads >= 5);
    }

    void missingServoIsReportedWithoutStallingTheOthers()
    {
        // Servo 9 was "found" and then unplugged: it is asked, and never answers.
        ServoInfo gone = found(2);
        gone.id = 9;
        feetech::TelemetryOptions options;
        options.servos = {found(1), gone, found(3)};
        options.rateHz = 0; // as fast as the bus allows
        options.missingProbeInterval = std::chrono::milliseconds(200);
        QSignalSpy notes(m_session.get(), &Session::packetLogged);
        m_session->startTelemetry(options);
        QVERIFY(runUntil(
            [this] { return m_stats.servos.size() == 3 && m_stats.servos.at(1).missing; }, 10000));
        const int before = samplesOf(1);
        const int beforeScs = samplesOf(3);
        // The others go on at full speed while the missing one is asked now and then.
        QVERIFY(runUntil([this] { return m_stats.servos.at(1).missed >= 6; }, 10000));
        m_session->stopTelemetry();
        QCOMPARE(samplesOf(9), 0); // nothing invented
        // 3 misses put it out of the cycle; each later miss is one probe, 200 ms apart, while
        // the others answer every cycle: many cycles a probe (some 50 here; a missing servo
        // asked in every cycle would allow one). A slow machine runs fewer: 5 is far from one.
        QVERIFY2(samplesOf(1) - before >= 5 * (m_stats.servos.at(1).missed - 3),
                 qPrintable(QStringLiteral("%1 samples, %2 missed")
                                .arg(samplesOf(1) - before)
                                .arg(m_stats.servos.at(1).missed)));
        // The SCS servo, read alone in every cycle, keeps its pace too.
        QVERIFY(samplesOf(3) - beforeScs >= 5 * (m_stats.servos.at(1).missed - 3));
        const bool reported = std::any_of(notes.begin(), notes.end(), [](const QVariantList &a) {
            return a.first().value<seriallink::PacketLogEntry>().summary.contains(
                QLatin1String("stopped answering"));
        });
        QVERIFY(reported);
    }

    void servoBackOnTheBusRejoinsTheCycle()
    {
        feetech::TelemetryOptions options;
        options.servos = {found(1), found(2)};
        options.rateHz = 100;
        options.missingProbeInterval = std::chrono::milliseconds(100);
        m_session->startTelemetry(options);
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(2) >= 5, 10000);
        // Servo 2 goes silent (its ID moves away), then comes back.
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(2)->setValue(u"id", 20);
        });
        QTRY_VERIFY_WITH_TIMEOUT(m_stats.servos.size() == 2 && m_stats.servos.at(1).missing, 10000);
        m_simulator->call([](sim::Simulator &simulator) {
            simulator.feetechBus()->findServo(20)->setValue(u"id", 2);
        });
        QTRY_VERIFY_WITH_TIMEOUT(!m_stats.servos.at(1).missing, 10000);
        const int back = samplesOf(2);
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(2) >= back + 10, 10000);
        m_session->stopTelemetry();
    }

    void allTorqueOffSendsTorqueEnableZeroToEveryServo()
    {
        m_simulator->call([](sim::Simulator &simulator) {
            auto *bus = simulator.feetechBus();
            for (int i = 0; i < bus->servoCount(); ++i)
                bus->servo(i).setValue(u"torque_enable", 1);
        });
        // While monitoring and with work queued: torque off goes first.
        feetech::TelemetryOptions options;
        options.servos = {found(1), found(3)};
        options.rateHz = 0;
        m_session->startTelemetry(options);
        QSignalSpy finished(m_session.get(), &Session::operationFinished);
        m_session->submit(feetech::operations::read(found(1), {}, feetech::ReadSource::Read));
        m_session->submit(feetech::operations::torqueOffAll({k1M, k500k}, m_found));
        QTRY_VERIFY_WITH_TIMEOUT(finished.size() >= 2, 10000);
        const auto first = finished.at(0).at(0).value<OperationResult>();
        QCOMPARE(first.operation, feetech::Operation::TorqueOff);
        QVERIFY2(first.ok, qPrintable(first.message));
        QVERIFY(first.message.contains(QLatin1String("5 servo")));
        m_session->stopTelemetry();
        for (const quint8 id : {1, 2, 3, 4, 6})
            QCOMPARE(simulatorValue(id, u"torque_enable"), 0);
        // One broadcast WRITE of address 40 = 0 at each rate.
        int broadcasts = 0;
        for (const feetech::Packet &packet : packetsReceived()) {
            if (packet.id == feetech::kBroadcastId
                && packet.code == quint8(feetech::Instruction::Write)
                && packet.parameters == QByteArray::fromHex("2800"))
                ++broadcasts;
        }
        QCOMPARE(broadcasts, 2);
    }

    void syncWriteMovesEveryServoInOneFrame()
    {
        for (const quint8 id : {1, 2})
            QVERIFY(run([&] {
                        m_session->submit(feetech::operations::write(
                            found(id), {{40, QByteArray(1, char(1)), false}}));
                    }).ok);
        const OperationResult result = run([&] {
            m_session->submit(feetech::operations::syncWrite(
                k1M, 42, 2, {{1, QByteArray::fromHex("e803")}, {2, QByteArray::fromHex("d007")}}));
        });
        QVERIFY2(result.ok, qPrintable(result.message));
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(1, u"present_position"), 1000, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(simulatorValue(2, u"present_position"), 2000, 10000);
    }

    void busClientKeepsStreamingAcrossRestartsAndAtFullSpeed()
    {
        m_session.reset(); // the pty takes one opener: the client's worker thread now
        feetech::BusClient client;
        QSignalSpy connected(&client, &feetech::BusClient::statusChanged);
        QVERIFY(testsupport::connectAndScan(client, m_simulator->linkPath(), 4,
                                            seriallink::EchoMode::Off));
        QCOMPARE(client.servos()->count(), 4);
        QHash<int, int> samples;
        connect(client.telemetry(), &feetech::TelemetryHub::samplesReceived, this,
                [&samples](const QVector<FeedbackSample> &batch) {
                    for (const FeedbackSample &sample : batch)
                        ++samples[sample.id];
                });
        QVERIFY(client.telemetry()->subscribe(this, {0, 1, 2, 3}, 50));
        QTRY_VERIFY_WITH_TIMEOUT(samples.value(1) >= 5, 10000);
        // A new selection replaces the stream; the old one's last news must not stop it.
        QVERIFY(client.telemetry()->subscribe(this, {0, 2}, 0));
        client.telemetry()->unsubscribe(this);
        QVERIFY(client.telemetry()->subscribe(this, {0, 2}, 0));
        samples.clear();
        QVERIFY(
            runUntil([&] { return samples.value(1) >= 200 && samples.value(3) >= 200; }, 30000));
        QVERIFY(client.telemetry()->isStreaming());
        QVERIFY(client.link()->isConnected());
        QCOMPARE(samples.value(2), 0); // no longer selected
        QCOMPARE(client.telemetry()->stats().servos.size(), 2);
        QCOMPARE(client.telemetry()->latestSample(0)->id, quint8(1));
        // Control writes go between the cycles; the stream goes on and the link stays clean.
        QVERIFY(client.telemetry()->subscribe(this, {0, 1, 2, 3}, 50));
        OperationLog writtenLog(&client);
        QSignalSpy written(&writtenLog, &OperationLog::finished);
        for (int i = 0; i < 4; ++i) {
            QVERIFY(client.writeValues(i, {{QStringLiteral("torque_enable"), 1}}));
            QVERIFY(client.writeValues(i, {{QStringLiteral("goal_position"), 500 + 100 * i}}));
        }
        QTRY_COMPARE_WITH_TIMEOUT(written.size(), 8, 10000);
        for (const QVariantList &arguments : std::as_const(written)) {
            const auto result = arguments.first().value<OperationResult>();
            QVERIFY2(result.ok, qPrintable(result.message));
        }
        samples.clear();
        QTRY_VERIFY_WITH_TIMEOUT(samples.value(4) >= 50, 10000);
        QVERIFY(client.telemetry()->isStreaming());
        QVERIFY(client.link()->isConnected());
        for (const feetech::ServoTelemetry &servo : client.telemetry()->stats().servos)
            QVERIFY(!servo.missing);
        client.telemetry()->unsubscribe(this);
        QVERIFY(!client.telemetry()->isStreaming());
    }

    void theHubStreamsWhatEverySubscriberAsksForAtTheFastestRate()
    {
        m_session.reset(); // the pty takes one opener: the client's worker thread now
        feetech::BusClient client;
        QVERIFY(testsupport::connectAndScan(client, m_simulator->linkPath(), 4,
                                            seriallink::EchoMode::Off));
        feetech::TelemetryHub &hub = *client.telemetry();
        QSet<int> seen;
        connect(&hub, &feetech::TelemetryHub::samplesReceived, this,
                [&seen](const QVector<FeedbackSample> &batch) {
                    for (const FeedbackSample &sample : batch)
                        seen.insert(sample.id);
                });
        QObject monitor;
        auto test = std::make_unique<QObject>();
        feetech::Refusal refusal;
        QVERIFY(!hub.subscribe(&monitor, {}, 20, &refusal)); // nothing to stream: refused
        QCOMPARE(refusal.code(), feetech::Refusal::Code::NoServoToMonitor);
        QVERIFY(!refusal.describe().isEmpty());
        QVERIFY(!hub.subscribe(&monitor, {0}, -1, &refusal));
        QCOMPARE(refusal.code(), feetech::Refusal::Code::NegativeRate);
        QVERIFY(!hub.subscribe(&monitor, {0, 9}, 20, &refusal));
        QCOMPARE(refusal.code(), feetech::Refusal::Code::NoServo);
        QVERIFY(!hub.isStreaming());
        QVERIFY(hub.subscribe(&monitor, {0, 1}, 20, &refusal));
        QCOMPARE(hub.options().rateHz, 20.0);
        QVERIFY(hub.subscribe(test.get(), {1, 3}, 50, &refusal));
        // The union, in the order first asked for, at the faster rate; nobody's stream replaced.
        QCOMPARE(hub.options().servos.size(), 3);
        QCOMPARE(hub.options().servos.at(0).id, quint8(1));
        QCOMPARE(hub.options().servos.at(2).id, quint8(4));
        QCOMPARE(hub.options().rateHz, 50.0);
        QVERIFY(hub.isStreamed(0) && hub.isStreamed(3) && !hub.isStreamed(2));
        QTRY_VERIFY_WITH_TIMEOUT(seen.contains(1) && seen.contains(2) && seen.contains(4), 10000);
        QVERIFY(!seen.contains(3));
        // A subscriber that goes away unsubscribes: the other's servos at its rate stream on.
        test.reset();
        QTRY_COMPARE(hub.options().servos.size(), 2);
        QVERIFY(hub.isStreaming());
        QCOMPARE(hub.options().rateHz, 20.0);
        QVERIFY(!hub.isStreamed(3));
        QVERIFY(hub.isSubscribed(&monitor));
        // As fast as the bus allows (0) is faster than any rate.
        QObject fastest;
        QVERIFY(hub.subscribe(&fastest, {0}, 0, &refusal));
        QCOMPARE(hub.options().rateHz, 0.0);
        hub.unsubscribe(&fastest);
        QCOMPARE(hub.options().rateHz, 20.0);
        hub.unsubscribe(&monitor);
        QVERIFY(!hub.isStreaming());
    }

    void writesQueuedBeforeTorqueOffAreNotSent()
    {
        QSignalSpy finished(m_session.get(), &Session::operationFinished);
        m_session->submit(feetech::operations::read(
            found(1), {}, feetech::ReadSource::Read)); // keeps the bus busy
        m_session->submit(feetech::operations::write(
            found(1), {{40, QByteArray(1, char(1)), false}})); // torque on, queued
        m_session->submit(feetech::operations::torqueOffAll({k1M, k500k}, m_found));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 3, 10000);
        QCOMPARE(finished.at(1).at(0).value<OperationResult>().operation,
                 feetech::Operation::TorqueOff);
        const auto write = finished.at(2).at(0).value<OperationResult>();
        QCOMPARE(write.operation, feetech::Operation::Write);
        QVERIFY(!write.ok);
        QCOMPARE(write.failure, feetech::OperationFailure::AfterTorqueOff);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        // Writes asked for afterwards go out as usual.
        const OperationResult later = run([&] {
            m_session->submit(
                feetech::operations::write(found(1), {{40, QByteArray(1, char(1)), false}}));
        });
        QVERIFY2(later.ok, qPrintable(later.message));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
    }

    void csvRowsParseBack()
    {
        FeedbackSample sample;
        sample.id = 7;
        sample.steadyUs = 1'500'000;
        sample.values.at(int(feetech::Quantity::Position)) = 2048;
        sample.values.at(int(feetech::Quantity::Voltage)) = 7.4;
        sample.servoStatus = 0x24;
        sample.moving = true;
        const QString text = feetech::telemetryCsvHeader() + QLatin1Char('\n')
            + feetech::telemetryCsvRow(sample, 500'000) + QLatin1Char('\n');
        QString error;
        const auto parsed = feetech::parseTelemetryCsv(text, &error);
        QVERIFY2(parsed, qPrintable(error));
        QCOMPARE(parsed->size(), 1);
        QCOMPARE(parsed->first().timeSeconds, 1.0);
        QCOMPARE(parsed->first().id, 7);
        QCOMPARE(*parsed->first().values.at(int(feetech::Quantity::Position)), 2048.0);
        QCOMPARE(*parsed->first().values.at(int(feetech::Quantity::Voltage)), 7.4);
        QVERIFY(!parsed->first().values.at(int(feetech::Quantity::Current)));
        QCOMPARE(parsed->first().servoStatus, 0x24);
        QVERIFY(parsed->first().moving);
        QVERIFY(!feetech::parseTelemetryCsv(QStringLiteral("a,b\n1,2\n"), &error));
        QVERIFY(!feetech::parseTelemetryCsv(
            feetech::telemetryCsvHeader() + QStringLiteral("\n1,2,3\n"), &error));
        QVERIFY(error.contains(QLatin1String("Line 2")));
    }
};

QTEST_GUILESS_MAIN(TestFeetechMonitor)
#include "tst_feetechmonitor.moc"
