// End to end over a pty: the PTK session and client against the simulated servo.
#include "simclient.h"

#include "hex.h"
#include "ptkclient.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "simulatorthread.h"
#include "virtualptkservo.h"

#include <QtTest>

using seriallink::ConnectionState;

namespace {

bool modelMatches(ptk::Client &client, const ptk::ParameterSet &values)
{
    for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
        const auto shown = client.model()->deviceValue(QLatin1String(meta.key));
        if (!shown || *shown != values.value(meta.parameter).value_or(0))
            return false;
    }
    return true;
}

} // namespace

class TestPtkClient : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    sim::SimulatorOptions options(const QString &name, bool echo = false)
    {
        return testsupport::ptkOptions(m_dir, name, echo);
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void readShowsTheServosValues_data()
    {
        QTest::addColumn<bool>("echo");
        QTest::newRow("plain adapter") << false;
        QTest::newRow("single-wire adapter with echo") << true;
    }

    void readShowsTheServosValues()
    {
        QFETCH(bool, echo);
        sim::SimulatorThread simulator;
        QString error;
        auto opts = options(QStringLiteral("read%1").arg(echo), echo);
        opts.ptkValues = QStringLiteral("gain=20,min_pulse_us=900,soft_start=1");
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        // No timeout is the point here: the wait is long enough that a machine busy with other
        // tests (the simulator shares it) never stretches an answer past it.
        auto timing = testsupport::ptkTestTiming();
        timing.engine.replyTimeout = std::chrono::milliseconds(250);
        ptk::Client client(timing);
        client.connectTo(simulator.linkPath());
        QTRY_COMPARE(client.status().state, ConnectionState::Connected);
        const ptk::ParameterSet expected = testsupport::ptkServoValues(simulator);
        QTRY_VERIFY(modelMatches(client, expected));
        QCOMPARE(*client.model()->deviceValue(QStringLiteral("min_pulse_us")), 3600);
        QTRY_VERIFY(client.counters().repliesOk >= 8);
        QCOMPARE(client.counters().echoBytes > 0, echo);
        QCOMPARE(client.counters().timeouts, 0);
    }

    void applySendsTheTwelveFramesInOrderAndVerifies_data() { readShowsTheServosValues_data(); }

    void applySendsTheTwelveFramesInOrderAndVerifies()
    {
        QFETCH(bool, echo);
        sim::SimulatorThread simulator;
        QString error;
        const auto opts = options(QStringLiteral("apply%1").arg(echo), echo);
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        ptk::Client client(testsupport::ptkTestTiming());
        client.connectTo(simulator.linkPath());
        QTRY_VERIFY(modelMatches(client, testsupport::ptkServoValues(simulator)));

        model::ParameterModel &model = *client.model();
        QVERIFY(model.edit(QStringLiteral("gain"), 21));
        QVERIFY(model.edit(QStringLiteral("deadband"), 7));
        QSignalSpy finished(&client, &ptk::Client::applyFinished);
        QVERIFY(client.apply());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 5000);
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));

        ptk::ParameterSet written = ptk::ParameterSet::seedSample(false);
        written.set(ptk::Parameter::Gain, 21);
        written.set(ptk::Parameter::Deadband, 7);
        const QStringList expected = testsupport::ptkWriteFrames(written);
        QCOMPARE(expected.size(), 12);
        QCOMPARE(testsupport::ptkWritesReceived(opts.logPath), expected);
        QCOMPARE(model.state(QStringLiteral("gain")), model::State::Verified);
        QCOMPARE(model.state(QStringLiteral("deadband")), model::State::Verified);
        QCOMPARE(model.state(QStringLiteral("damping")), model::State::Clean);
        QCOMPARE(testsupport::ptkServoValues(simulator), written);
    }

    void aWriteTheServoIgnoresIsAMismatchOnThatParameterOnly()
    {
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options(QStringLiteral("ignored")), &error), qPrintable(error));
        simulator.call([](sim::Simulator &s) { s.ptkServo()->ignoreWrites(0x43); }); // deadband
        ptk::Client client(testsupport::ptkTestTiming());
        client.connectTo(simulator.linkPath());
        QTRY_VERIFY(modelMatches(client, testsupport::ptkServoValues(simulator)));

        model::ParameterModel &model = *client.model();
        QVERIFY(model.edit(QStringLiteral("gain"), 21));
        QVERIFY(model.edit(QStringLiteral("deadband"), 7));
        QSignalSpy finished(&client, &ptk::Client::applyFinished);
        QVERIFY(client.apply());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 5000);
        QCOMPARE(model.state(QStringLiteral("gain")), model::State::Verified);
        QCOMPARE(model.state(QStringLiteral("deadband")), model::State::Mismatch);
        QCOMPARE(*model.deviceValue(QStringLiteral("deadband")), 15);
        for (const QString &other :
             QStringList {QStringLiteral("damping"), QStringLiteral("neutral")})
            QCOMPARE(model.state(other), model::State::Clean);
    }

    void aPollDuringAnEditLeavesTheEditAlone()
    {
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options(QStringLiteral("edit")), &error), qPrintable(error));
        ptk::Client client(testsupport::ptkTestTiming());
        client.connectTo(simulator.linkPath());
        QTRY_VERIFY(modelMatches(client, testsupport::ptkServoValues(simulator)));
        model::ParameterModel &model = *client.model();
        QVERIFY(model.edit(QStringLiteral("gain"), 3));
        const qint64 editedAt = model.lastReadMs(QStringLiteral("gain"));
        QTRY_VERIFY(model.lastReadMs(QStringLiteral("gain")) > editedAt + 20);
        QCOMPARE(*model.pendingValue(QStringLiteral("gain")), 3);
        QCOMPARE(*model.deviceValue(QStringLiteral("gain")), 29);
        QCOMPARE(model.state(QStringLiteral("gain")), model::State::Edited);
    }

    void withDroppedAndCorruptedRepliesEveryValueShownIsTheServos()
    {
        sim::SimulatorThread simulator;
        QString error;
        auto opts = options(QStringLiteral("faults"));
        sim::OptionError badFaults;
        const auto faults =
            sim::FaultSettings::parse(QStringLiteral("drop=0.2,corrupt=0.2"), &badFaults);
        QVERIFY2(faults, qPrintable(badFaults.describe()));
        opts.faults = *faults;
        opts.seed = 7;
        // Values no other query's reply holds, so a reply taken for the wrong query shows.
        opts.ptkValues = QStringLiteral("gain=11,damping=22,deadband=33,min_angle=44,"
                                        "max_angle=55,max_power=666,overload_power=777");
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        const ptk::ParameterSet truth = testsupport::ptkServoValues(simulator);
        ptk::Client client(testsupport::ptkTestTiming());
        QStringList wrong;
        connect(client.model(), &model::ParameterModel::parameterChanged, this,
                [&](const QString &key) {
                    const ptk::ParameterInfo *meta = ptk::findParameter(key);
                    const auto shown = client.model()->deviceValue(key);
                    if (shown && *shown != truth.value(meta->parameter).value_or(0))
                        wrong.append(QStringLiteral("%1=%2").arg(key).arg(*shown));
                });
        client.connectTo(simulator.linkPath());
        QTRY_VERIFY_WITH_TIMEOUT(client.counters().repliesOk >= 80, 20000);
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(u' ')));
        QVERIFY(modelMatches(client, truth));
        const auto &counters = client.counters();
        qInfo() << "ok" << counters.repliesOk << "timeouts" << counters.timeouts << "checksum"
                << counters.checksumErrors << "discarded" << counters.discardedBytes;
        QVERIFY(client.counters().timeouts > 0);
        QVERIFY(client.counters().checksumErrors > 0);
    }

    void killingTheSimulatorDisconnectsAndItsReturnReconnects()
    {
        sim::SimulatorThread simulator;
        QString error;
        const auto opts = options(QStringLiteral("replug"));
        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        ptk::Client client(testsupport::ptkTestTiming());
        QSignalSpy states(&client, &ptk::Client::statusChanged);
        client.connectTo(simulator.linkPath());
        QTRY_COMPARE(client.status().state, ConnectionState::Connected);

        simulator.stop();
        QTRY_VERIFY_WITH_TIMEOUT(client.status().state == ConnectionState::Lost, 5000);
        QVERIFY(!client.status().message.isEmpty());

        QVERIFY2(simulator.start(opts, &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(client.status().state, ConnectionState::Connected, 5000);
        const qint64 before = client.counters().repliesOk;
        QTRY_VERIFY(client.counters().repliesOk > before);
    }

    void disconnectingDuringAnApplyEndsItAReadSettlesItAndTheNextApplyWorks()
    {
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options(QStringLiteral("cut")), &error), qPrintable(error));
        auto timing = testsupport::ptkTestTiming();
        timing.writeGap = std::chrono::milliseconds(40); // time to cut in between writes
        ptk::Client client(timing);
        client.connectTo(simulator.linkPath());
        QTRY_VERIFY(modelMatches(client, testsupport::ptkServoValues(simulator)));
        model::ParameterModel &model = *client.model();
        QVERIFY(model.edit(QStringLiteral("gain"), 21));
        QSignalSpy finished(&client, &ptk::Client::applyFinished);
        QSignalSpy progress(&client, &ptk::Client::applyProgress);
        QVERIFY(client.apply());
        QTRY_VERIFY(progress.size() >= 2);
        client.disconnectFrom();
        QTRY_COMPARE(finished.size(), 1);
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY(!client.isBusy());
        // It may have gone out before the cut: not known until the servo is read again.
        QCOMPARE(model.state(QStringLiteral("gain")), model::State::Unknown);
        QCOMPARE(*model.pendingValue(QStringLiteral("gain")), 21); // kept for another try
        // The session's "Apply ended" can come before the link's "Disconnected": wait for that
        // too, or the stale news would end the next Apply.
        QTRY_COMPARE(client.status().state, ConnectionState::Disconnected);

        client.connectTo(simulator.linkPath());
        QTRY_COMPARE(client.status().state, ConnectionState::Connected);
        // Gain travels in the first write frame, which left before the cut: the first poll
        // shows it landed and settles it.
        QTRY_COMPARE(model.state(QStringLiteral("gain")), model::State::Verified);
        QVERIFY(!model.pendingValue(QStringLiteral("gain")));
        QVERIFY(model.edit(QStringLiteral("gain"), 22));
        QTRY_VERIFY(client.applyBlocker().isEmpty());
        QVERIFY(client.apply());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 5000);
        QVERIFY2(finished.at(1).at(0).toBool(), qPrintable(finished.at(1).at(1).toString()));
        QCOMPARE(model.state(QStringLiteral("gain")), model::State::Verified);
    }

    void withPollingOffTheServoIsStillFound()
    {
        sim::SimulatorThread simulator;
        QString error;
        QVERIFY2(simulator.start(options(QStringLiteral("quiet")), &error), qPrintable(error));
        ptk::Client client(testsupport::ptkTestTiming());
        client.setPolling(false);
        client.connectTo(simulator.linkPath());
        QTRY_COMPARE(client.status().state, ConnectionState::Connected);
        QSignalSpy read(&client, &ptk::Client::readFinished);
        client.readAll();
        QTRY_COMPARE(read.size(), 1);
        QVERIFY(read.first().at(0).toBool());
        QVERIFY(modelMatches(client, testsupport::ptkServoValues(simulator)));
    }

    void anApplyIsRefusedUntilEverythingHasBeenRead()
    {
        ptk::Client client(testsupport::ptkTestTiming());
        QVERIFY(client.model()->edit(QStringLiteral("gain"), 3));
        QString why;
        QVERIFY(!client.apply(&why));
        QVERIFY(!why.isEmpty());
    }

    void aMissingPortIsAClearError()
    {
        ptk::Client client(testsupport::ptkTestTiming());
        QSignalSpy states(&client, &ptk::Client::statusChanged);
        client.connectTo(m_dir.filePath(QStringLiteral("nothing-here")));
        QTRY_COMPARE(client.status().state, ConnectionState::Disconnected);
        QTRY_VERIFY(!client.status().message.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestPtkClient)
#include "tst_ptkclient.moc"
