// Tests of the PTK session in the test thread against the simulated PTK servo on a pty.
#include "simclient.h"

#include "linksession.h"
#include "ptksession.h"

#include <QSignalSpy>
#include <QtTest>

#include <algorithm>

using ptk::ParameterSet;
using ptk::ReadSource;
using seriallink::ConnectionState;

class TestPtkSession : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    sim::SimulatorOptions m_options;
    std::unique_ptr<sim::SimulatorThread> m_simulator;
    std::unique_ptr<ptk::Session> m_session;

    void startSimulator()
    {
        m_simulator = std::make_unique<sim::SimulatorThread>();
        QString error;
        QVERIFY2(m_simulator->start(m_options, &error), qPrintable(error));
    }

    // Opens a session with `timing` on the simulator at PTK's rate.
    void openSession(const ptk::SessionTiming &timing = testsupport::ptkTestTiming())
    {
        m_session = std::make_unique<ptk::Session>(timing);
        m_session->open(m_simulator->linkPath(), sim::VirtualPtkServo::kBaudRate,
                        seriallink::EchoMode::Off);
    }

    // Every value the servo holds, as a read of the session reports it.
    ParameterSet readValues()
    {
        ParameterSet values;
        auto connection = connect(m_session.get(), &ptk::Session::valuesRead, this,
                                  [&values](const ParameterSet &read, ReadSource) {
                                      for (const ptk::ParameterInfo &meta : ptk::parameterInfos()) {
                                          if (const auto value = read.value(meta.parameter))
                                              values.set(meta.parameter, *value);
                                      }
                                  });
        QSignalSpy finished(m_session.get(), &ptk::Session::readFinished);
        m_session->readAll();
        if (finished.isEmpty() && !finished.wait(10000))
            qWarning("the read did not end within 10 s");
        disconnect(connection);
        return values;
    }

private slots:
    void init()
    {
        m_options = testsupport::ptkOptions(m_dir, QStringLiteral("ptk"));
        startSimulator();
    }

    void cleanup()
    {
        m_session.reset();
        m_simulator.reset();
        QFile::remove(m_options.logPath);
    }

    void pollingAsksTheEightQueriesInTurn()
    {
        auto timing = testsupport::ptkTestTiming();
        timing.pollInterval = std::chrono::milliseconds(10);
        timing.engine.replyTimeout = std::chrono::milliseconds(100);
        openSession(timing);
        QSignalSpy read(m_session.get(), &ptk::Session::valuesRead);
        QTRY_VERIFY_WITH_TIMEOUT(read.size() >= 16, 10000);
        QCOMPARE(m_session->status().state, ConnectionState::Connected);
        for (const QList<QVariant> &arguments : std::as_const(read))
            QCOMPARE(arguments.at(1).value<ReadSource>(), ReadSource::Poll);
        // A query asked again right away is the engine's retry of one that went unanswered.
        QVector<quint8> queries = testsupport::ptkQueriesReceived(m_options.logPath);
        queries.erase(std::unique(queries.begin(), queries.end()), queries.end());
        QVERIFY(queries.size() >= 16);
        for (int i = 0; i < queries.size(); ++i)
            QCOMPARE(queries.at(i), ptk::queryLayouts().at(std::size_t(i % 8)).command);
    }

    void fastPollingAsksAgainAsSoonAsAnAnswerCame()
    {
        // A minute between polls, but fast: the interval plays no part.
        openSession();
        m_session->setPollInterval(60000, true);
        QSignalSpy read(m_session.get(), &ptk::Session::valuesRead);
        QTRY_VERIFY_WITH_TIMEOUT(read.size() >= 24, 10000);
        for (const QList<QVariant> &arguments : std::as_const(read))
            QCOMPARE(arguments.at(1).value<ReadSource>(), ReadSource::Poll);
    }

    void applySendsTheTwelveWritesThenReadsBackAndSucceeds()
    {
        openSession();
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::Connected, 10000);
        ParameterSet values = readValues();
        QVERIFY(values.isComplete());
        values.set(ptk::Parameter::Gain, 21);
        values.set(ptk::Parameter::Deadband, 7);
        QSignalSpy finished(m_session.get(), &ptk::Session::applyFinished);
        QSignalSpy progress(m_session.get(), &ptk::Session::applyProgress);
        QSignalSpy read(m_session.get(), &ptk::Session::valuesRead);
        m_session->apply(values);
        QVERIFY(m_session->isApplying());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        QCOMPARE(testsupport::ptkWritesReceived(m_options.logPath),
                 testsupport::ptkWriteFrames(values));
        QCOMPARE(testsupport::ptkServoValues(*m_simulator), values);
        // Then the eight queries, as a read-back.
        int readBack = 0;
        for (const QList<QVariant> &arguments : std::as_const(read))
            readBack += arguments.at(1).value<ReadSource>() == ReadSource::ReadBack ? 1 : 0;
        QCOMPARE(readBack, 8);
        QCOMPARE(progress.last().at(0).toInt(), 20);
        QCOMPARE(progress.last().at(1).toInt(), 20);
        QVERIFY(!m_session->isApplying());
    }

    void anOutOfRangeValueIsRefusedWithNothingSent()
    {
        openSession();
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::Connected, 10000);
        ParameterSet values = readValues();
        QVERIFY(values.isComplete());
        const ptk::ParameterInfo &gain = ptk::info(ptk::Parameter::Gain);
        values.set(ptk::Parameter::Gain, quint16((gain.maximum + 1) * gain.wirePerUnit));
        QSignalSpy finished(m_session.get(), &ptk::Session::applyFinished);
        m_session->apply(values);
        QCOMPARE(finished.size(), 1); // at once
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY2(finished.first().at(1).toString().contains(QLatin1String("nothing was written")),
                 qPrintable(finished.first().at(1).toString()));
        QVERIFY(!m_session->isApplying());
        QVERIFY(testsupport::ptkWritesReceived(m_options.logPath).isEmpty());
    }

    void aServoThatStaysSilentGivesNoReply()
    {
        m_options.faults.drop = 1.0; // every reply lost
        startSimulator();
        openSession();
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::NoReply, 10000);
        QVERIFY(!m_session->status().message.isEmpty());
        QVERIFY(m_session->counters().timeouts > 0);
        QCOMPARE(m_session->counters().repliesOk, 0);
    }

    void losingThePortDuringApplyEndsItAndTheLinkIsLost()
    {
        auto timing = testsupport::ptkTestTiming();
        timing.writeGap = std::chrono::milliseconds(40); // time to pull the plug in between
        openSession(timing);
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::Connected, 10000);
        ParameterSet values = readValues();
        QVERIFY(values.isComplete());
        values.set(ptk::Parameter::Gain, 21);
        QSignalSpy finished(m_session.get(), &ptk::Session::applyFinished);
        QSignalSpy progress(m_session.get(), &ptk::Session::applyProgress);
        m_session->apply(values);
        QTRY_VERIFY_WITH_TIMEOUT(progress.size() >= 2, 10000);
        m_simulator->stop();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QCOMPARE(finished.first().at(0).toBool(), false);
        QCOMPARE(m_session->status().state, ConnectionState::Lost);
        QVERIFY(!m_session->isApplying());
        QVERIFY(progress.last().at(0).toInt() < 12);
    }

    void aReturningPortIsConnectingUntilTheServoAnswersThenPollingGoesOn()
    {
        openSession();
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::Connected, 10000);
        m_simulator->stop();
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::Lost, 10000);
        QSignalSpy status(m_session.get(), &ptk::Session::statusChanged);
        QSignalSpy read(m_session.get(), &ptk::Session::valuesRead);
        startSimulator();
        QTRY_COMPARE_WITH_TIMEOUT(m_session->status().state, ConnectionState::Connected, 10000);
        QCOMPARE(
            testsupport::connectionStates(status),
            (QVector<ConnectionState> {ConnectionState::Connecting, ConnectionState::Connected}));
        QTRY_VERIFY_WITH_TIMEOUT(read.size() >= 8, 10000);
        QVERIFY(testsupport::ptkQueriesReceived(m_options.logPath).size() >= 8);
    }
};

QTEST_GUILESS_MAIN(TestPtkSession)
#include "tst_ptksession.moc"
