// A shared bus end to end: a program that talks like the vendors' SDKs (blocking, in a thread of
// its own) on the share's pseudo-terminal, servosim behind it, and what the share sees and says.
#include "blockingclient.h"
#include "busshare.h"
#include "feetechbus.h"
#include "feetechdescription.h"
#include "linksession.h"
#include "porttransport.h"
#include "servoctlrun.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QScopeGuard>
#include <QtTest>

#include <future>
#include <thread>

#include <sys/ioctl.h>
#include <unistd.h>

namespace {

constexpr qint32 k1M = 1000000;
constexpr qint32 k500k = 500000;
// How long the program waits for an answer where the test is not about how soon it comes.
constexpr std::chrono::milliseconds kPatient {250};

using bench::BlockingClient;

} // namespace

class TestBusShare : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    // The simulated bus, a link on it and the share offering it at programPath().
    void startShare(const sim::SimulatorOptions &options, bool watch = false,
                    const QString &record = {})
    {
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        m_link = std::make_unique<seriallink::LinkSession>(m_format, feetech::describeFrame);
        m_link->setReconnectInterval(std::chrono::milliseconds(50));
        QVERIFY2(m_link->open(m_simulator->linkPath(), k1M, seriallink::EchoMode::Auto),
                 qPrintable(m_link->status().message));
        m_share = std::make_unique<share::BusShare>(*m_link);
        connect(m_share.get(), &share::BusShare::transactionEnded, this,
                [this](const share::SharedTransaction &transaction) {
                    m_transactions.append(transaction);
                });
        connect(m_share.get(), &share::BusShare::alertRaised, this,
                [this](const share::ShareAlert &alert) { m_alerts.append(alert); });
        connect(m_share.get(), &share::BusShare::noted, this,
                [this](const QString &text) { m_notes.append(text); });
        share::ShareOptions shared;
        shared.linkPath = programPath();
        shared.recordPath = record;
        shared.watch = watch;
        QCOMPARE(m_share->start(shared), QString());
    }

    QString programPath() const { return m_dir.filePath(QStringLiteral("program")); }

    // Runs `work` in a thread of its own, as another program would, while this thread's event
    // loop (the share's) goes on.
    template<typename Work>
    auto asProgram(Work work)
    {
        auto done = std::async(std::launch::async, work);
        while (done.wait_for(std::chrono::milliseconds(0)) != std::future_status::ready)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 2);
        return done.get();
    }

    QVector<share::SharedTransaction> programTransactions(feetech::Instruction code) const
    {
        QVector<share::SharedTransaction> found;
        for (const share::SharedTransaction &transaction : m_transactions) {
            if (!transaction.own && transaction.instruction() == quint8(code))
                found.append(transaction);
        }
        return found;
    }

    bool hasAlert(const QString &code, quint8 id) const
    {
        return std::any_of(m_alerts.begin(), m_alerts.end(), [&](const share::ShareAlert &alert) {
            return alert.code == code && alert.id == id;
        });
    }

    QStringList alertCodes() const
    {
        QStringList codes;
        for (const share::ShareAlert &alert : m_alerts)
            codes.append(QStringLiteral("%1/%2").arg(alert.code).arg(alert.id));
        return codes;
    }

    feetech::FrameFormat m_format;
    std::unique_ptr<seriallink::LinkSession> m_link;
    std::unique_ptr<share::BusShare> m_share;
    QVector<share::SharedTransaction> m_transactions;
    QVector<share::ShareAlert> m_alerts;
    QStringList m_notes;

private slots:
    void cleanup()
    {
        m_share.reset();
        m_link.reset();
        m_simulator.reset();
        m_transactions.clear();
        m_alerts.clear();
        m_notes.clear();
        QFile::remove(logPath());
    }

    void aProgramPingsEveryIdAndFindsEachServoWithNothingAdded()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS0009"})));
        const QVector<int> found = asProgram([path = programPath()] {
            QVector<int> ids;
            BlockingClient program;
            if (!program.open(path, k1M))
                return ids;
            for (int id = 0; id <= 8; ++id) {
                if (program.ask(feetech::ping(quint8(id)), quint8(id),
                                std::chrono::milliseconds(20)))
                    ids.append(id);
            }
            return ids;
        });
        QCOMPARE(found, (QVector<int> {1, 2, 3}));
        QTRY_COMPARE(programTransactions(feetech::Instruction::Ping).size(), 9);
        const auto pings = programTransactions(feetech::Instruction::Ping);
        QCOMPARE(pings.at(1).replies.size(), 1);
        QVERIFY(pings.at(1).roundTripUs.has_value());
        QVERIFY(pings.at(4).unanswered());
        // The servos heard the program's nine PINGs and nothing else.
        QCOMPARE(testsupport::feetechFramesReceived(logPath()).size(), 9);
        QCOMPARE(m_share->counters().framesFromProgram, 9);
        QCOMPARE(m_share->counters().unanswered, 6);
    }

    void servoctlScansAndReadsThroughTheShareAsItWouldTheAdapter()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"SCS0009"})));
        // servoctl's own event loop runs the share too: they share this thread.
        const auto scan = testsupport::runServoctl(
            {QStringLiteral("--port"), programPath(), QStringLiteral("--json"),
             QStringLiteral("feetech"), QStringLiteral("scan")});
        QVERIFY2(scan.exitCode == 0, qPrintable(scan.err));
        const QJsonArray servos = QJsonDocument::fromJson(scan.out.toUtf8()).array();
        QCOMPARE(servos.size(), 3);
        QVERIFY(
            servos.at(2)[QStringLiteral("model")].toString().contains(QStringLiteral("SCS0009")));
        const auto read = testsupport::runServoctl(
            {QStringLiteral("--port"), programPath(), QStringLiteral("feetech"),
             QStringLiteral("get"), QStringLiteral("--id"), QStringLiteral("2"),
             QStringLiteral("present_voltage")});
        QVERIFY2(read.exitCode == 0, qPrintable(read.err));
        // Every ID was asked once by the program's scan; none by ServoBench itself.
        QVERIFY(m_share->counters().framesFromProgram > 250);
        QCOMPARE(m_share->counters().ownTransactions, 0);
    }

    void garbageFromEitherSideIsPassedOnAndCounted()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        const bool answered = asProgram([path = programPath()] {
            BlockingClient program;
            if (!program.open(path, k1M))
                return false;
            program.exchange(QByteArray::fromHex("00ff12ffff"), 0, std::chrono::milliseconds(5));
            return program.ask(feetech::ping(1), 1).has_value();
        });
        QVERIFY(answered);
        QTRY_VERIFY(m_share->counters().garbledBytes > 0);
        QCOMPARE(m_share->counters().bytesFromProgram, qint64(5 + 6));
    }

    void aSyncReadLoopIsAnsweredEveryTimeAndDecodedByKey()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"STS3215"})));
        const int complete = asProgram([path = programPath()] {
            BlockingClient program;
            if (!program.open(path, k1M))
                return -1;
            // As LeRobot connects: the model numbers first.
            for (quint8 id = 1; id <= 3; ++id)
                program.ask(feetech::read(id, 3, 2), id);
            int whole = 0;
            for (int cycle = 0; cycle < 50; ++cycle) {
                if (program.exchange(feetech::syncRead(56, 8, {1, 2, 3}), 3).size() == 3)
                    ++whole;
            }
            return whole;
        });
        QCOMPARE(complete, 50);
        QTRY_COMPARE(programTransactions(feetech::Instruction::SyncRead).size(), 50);
        const share::SharedTransaction last =
            programTransactions(feetech::Instruction::SyncRead).last();
        QCOMPARE(last.replies.size(), 3);
        QStringList keys;
        for (const share::RegisterAccess &access : last.registers)
            keys.append(QStringLiteral("%1:%2").arg(access.id).arg(access.key));
        for (const char *key : {"1:present_position", "2:present_load", "3:present_speed"})
            QVERIFY2(keys.contains(QLatin1String(key)), qPrintable(keys.join(u' ')));
        const QJsonObject json = last.toJson();
        QCOMPARE(json[QStringLiteral("instruction")].toString(), QStringLiteral("SYNC READ"));
        QVERIFY(json[QStringLiteral("round_trip_us")].toDouble() > 0);
        QVERIFY(m_share->servos().table(2) != nullptr);
    }

    void aWriteGoesThroughAndReadsBack()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        const std::optional<QByteArray> readBack = asProgram([path = programPath()] {
            BlockingClient program;
            if (!program.open(path, k1M))
                return std::optional<QByteArray>();
            program.ask(feetech::write(1, 41, QByteArray(1, char(10))), 1);
            return program.ask(feetech::read(1, 41, 1), 1);
        });
        QVERIFY(readBack);
        QCOMPARE(quint8(readBack->at(5)), quint8(10));
        QCOMPARE(simulatorValue(1, u"acceleration"), 10);
        QTRY_COMPARE(programTransactions(feetech::Instruction::Write).size(), 1);
    }

    void theRateTheProgramSetsIsFollowedOnThePort()
    {
        auto servos = testsupport::servosAt(k1M, {u"STS3215"});
        servos.append({2, QStringLiteral("STS3215"), k500k});
        startShare(busOptions(servos));
        const QVector<bool> answered = asProgram([path = programPath()] {
            BlockingClient program;
            QVector<bool> results;
            if (!program.open(path, k1M))
                return results;
            results.append(program.ask(feetech::ping(1), 1).has_value());
            results.append(
                program.ask(feetech::ping(2), 2, std::chrono::milliseconds(20)).has_value());
            program.setBaudRate(k500k);
            results.append(program.ask(feetech::ping(2), 2).has_value());
            results.append(
                program.ask(feetech::ping(1), 1, std::chrono::milliseconds(20)).has_value());
            return results;
        });
        QCOMPARE(answered, (QVector<bool> {true, false, true, false}));
        QCOMPARE(m_link->transport().baudRate(), k500k);
        QVERIFY2(m_notes.join(u' ').contains(QStringLiteral("500000")),
                 qPrintable(m_notes.join(u'|')));
    }

    void theProgramClosingAndOpeningAgainKeepsTheShareRunning()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215"})));
        const int answered = asProgram([path = programPath()] {
            int count = 0;
            for (int round = 0; round < 20; ++round) {
                BlockingClient program;
                // Patient as a program on a loaded machine must be: this is about the share
                // staying up, not about how soon it answers.
                if (program.open(path, k1M) && program.ask(feetech::ping(1), 1, kPatient))
                    ++count;
            }
            return count;
        });
        QCOMPARE(answered, 20);
        QVERIFY(m_share->isSharing());
    }

    void theWatchReadsInTheGapsAndNeverCollidesWithTheProgram()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})), true);
        const std::pair<int, int> result = asProgram([path = programPath()] {
            BlockingClient program;
            int answered = 0;
            if (!program.open(path, k1M))
                return std::make_pair(-1, -1);
            for (int cycle = 0; cycle < 150; ++cycle) {
                const quint8 id = quint8(1 + cycle % 2);
                if (program.ask(feetech::read(id, 56, 8), id, kPatient))
                    ++answered;
                // A loop that leaves gaps, short and long, as a program at 30-100 Hz does.
                std::this_thread::sleep_for(std::chrono::milliseconds(cycle % 7 == 0 ? 12 : 1));
            }
            return std::make_pair(answered, program.unexpectedFrames());
        });
        QCOMPARE(result.first, 150);
        QCOMPARE(result.second, 0);
        QVERIFY2(m_share->watchReads() > 0, "the watch read nothing in the gaps");
        // Every READ the servos heard was answered in turn: the program's and the watch's
        // requests never overlapped, or the simulator would have seen a request cut short.
        int own = 0;
        for (const share::SharedTransaction &transaction : std::as_const(m_transactions)) {
            if (transaction.own) {
                ++own;
                QVERIFY(!transaction.replies.isEmpty());
            }
        }
        QVERIFY(own > 0);
        QCOMPARE(m_share->counters().garbledBytes, 0);
    }

    // Servos that answer later than the share waits for a program's request (a loaded machine,
    // an adapter's latency): the watch's READ may go after that wait, yet every answer is the
    // program's or the watch's by what was asked, never by when it came.
    void lateAnswersToTheProgramStayTheProgramsWhileTheWatchReads()
    {
        sim::SimulatorOptions options =
            busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215", u"STS3215"}));
        // Each answer within the share's 30 ms wait for one, a SYNC READ's three past it.
        options.replyDelayUs = 25000;
        startShare(options, true);
        struct Loop
        {
            int whole = 0;
            int foreign = 0;
        };
        const Loop loop = asProgram([path = programPath()] {
            Loop done;
            BlockingClient program;
            if (!program.open(path, k1M))
                return done;
            const QVector<quint8> ids {1, 2, 3};
            for (const quint8 id : ids) // the models first, as LeRobot does
                program.ask(feetech::read(id, 3, 2), id);
            for (int cycle = 0; cycle < 40; ++cycle) {
                const QVector<QByteArray> answers =
                    program.exchange(feetech::syncRead(56, 8, ids), int(ids.size()), kPatient);
                done.whole += answers.size() == ids.size();
                for (qsizetype i = 0; i < answers.size(); ++i) {
                    if (quint8(answers.at(i).at(2)) != ids.value(i) || answers.at(i).size() != 14)
                        ++done.foreign;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(cycle % 5 == 0 ? 60 : 2));
            }
            done.foreign += program.unexpectedFrames();
            return done;
        });
        QCOMPARE(loop.whole, 40);
        QCOMPARE(loop.foreign, 0);
        QVERIFY2(m_share->watchReads() > 0, "the watch read nothing in the gaps");
        // Nothing the watch decoded came from the program's answers: no alert on healthy servos.
        QVERIFY2(m_alerts.isEmpty(), qPrintable(alertCodes().join(u' ')));
        // What the program got late is no unanswered request.
        QCOMPARE(m_share->counters().unanswered, 0);
    }

    void theProgramsReadsRaiseAlertsWithoutTheWatch()
    {
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215", u"STS3215"})));
        const qint32 maximum = simulatorValue(1, u"max_temperature");
        QVERIFY(withServo(1, k1M, [maximum](sim::VirtualFeetechServo &servo) {
            servo.setTemperature(maximum - 2);
        }));
        QVERIFY(withServo(2, k1M,
                          [](sim::VirtualFeetechServo &servo) { servo.setOverloadLatched(true); }));
        asProgram([path = programPath()] {
            BlockingClient program;
            if (!program.open(path, k1M))
                return false;
            for (quint8 id = 1; id <= 2; ++id) {
                program.ask(feetech::read(id, 0, 19), id); // identity and limits
                program.ask(feetech::read(id, 56, 15), id); // the feedback block
            }
            return true;
        });
        QTRY_VERIFY2(hasAlert(QStringLiteral("temperature-high"), 1),
                     qPrintable(alertCodes().join(u' ')));
        QVERIFY2(hasAlert(QStringLiteral("overload"), 2), qPrintable(alertCodes().join(u' ')));
        QVERIFY2(!hasAlert(QStringLiteral("temperature-high"), 2),
                 qPrintable(alertCodes().join(u' ')));
        // Raised once, not at every read.
        const int before = int(m_alerts.size());
        asProgram([path = programPath()] {
            BlockingClient program;
            return program.open(path, k1M) && program.ask(feetech::read(1, 56, 15), 1);
        });
        QTest::qWait(20);
        QCOMPARE(int(m_alerts.size()), before);
    }

    void riskyWritesOfTheProgramRaiseAlerts()
    {
        const QString recording = m_dir.filePath(QStringLiteral("alerts.log"));
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), false, recording);
        asProgram([path = programPath()] {
            BlockingClient program;
            if (!program.open(path, k1M))
                return false;
            program.ask(feetech::read(1, 3, 2), 1); // the model, so the bytes have meaning
            program.ask(feetech::read(1, 56, 2), 1); // where it stands: 2048
            program.ask(feetech::write(1, 55, QByteArray(1, '\0')), 1); // EEPROM unlocked
            program.ask(feetech::write(1, 18, QByteArray(1, char(0x1C))), 1); // phase bit 4
            program.ask(feetech::write(1, 42, QByteArray::fromHex("0008")), 1); // goal 2048
            program.ask(feetech::write(1, 42, QByteArray::fromHex("b80b")), 1); // goal 3000
            program.ask(feetech::write(1, 40, QByteArray(1, char(1))), 1); // torque on: a jump
            return true;
        });
        QTRY_VERIFY2(hasAlert(QStringLiteral("torque-jump"), 1),
                     qPrintable(alertCodes().join(u' ')));
        QVERIFY2(hasAlert(QStringLiteral("multi-turn"), 1), qPrintable(alertCodes().join(u' ')));
        // Left unlocked: said once its time is up, by the share's own clock.
        QTRY_VERIFY_WITH_TIMEOUT(hasAlert(QStringLiteral("eeprom-unlocked"), 1), 8000);
        // Every alert is in the recording, the one the clock raised too.
        m_share->stop();
        const auto frames = share::ShareRecording::load(recording, nullptr);
        QVERIFY(frames.has_value());
        QStringList notes;
        for (const share::RecordedFrame &frame : *frames)
            notes.append(frame.note);
        for (const char *code : {"alert torque-jump 1", "alert eeprom-unlocked 1"}) {
            QVERIFY2(std::any_of(notes.cbegin(), notes.cend(),
                                 [code](const QString &note) {
                                     return note.startsWith(QLatin1String(code));
                                 }),
                     qPrintable(notes.join(u'|')));
        }
    }

    void aRecordingIsExplainedFrameByFrameByDecodeLog()
    {
        const QString recording = m_dir.filePath(QStringLiteral("session.log"));
        startShare(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), false, recording);
        asProgram([path = programPath()] {
            BlockingClient program;
            return program.open(path, k1M) && program.ask(feetech::read(1, 56, 2), 1)
                && program.ask(feetech::read(1, 3, 2), 1) // the model: now bytes have keys
                && program.ask(feetech::write(1, 55, QByteArray(1, '\0')), 1)
                && program.ask(feetech::write(1, 55, QByteArray(1, '\1')), 1);
        });
        QTRY_COMPARE(programTransactions(feetech::Instruction::Write).size(), 2);
        m_share->stop();
        const auto text = testsupport::runServoctl(
            {QStringLiteral("decode"), QStringLiteral("--family"), QStringLiteral("feetech"),
             QStringLiteral("--log"), recording});
        QVERIFY2(text.exitCode == 0, qPrintable(text.err));
        QVERIFY2(text.out.contains(QStringLiteral(" program  FF FF 01 04 02 38 02")),
                 qPrintable(text.out));
        QVERIFY2(text.out.contains(QStringLiteral("READ ID 1 address 56")), qPrintable(text.out));
        QVERIFY2(text.out.contains(QStringLiteral("status from ID 1")), qPrintable(text.out));
        // By key and value, as the share's JSON names them, once the model is known.
        QVERIFY2(text.out.contains(QStringLiteral("ID 1: lock = 0")), qPrintable(text.out));
        QVERIFY2(text.out.contains(QStringLiteral("ID 1: model_major = 9, model_minor = 3")),
                 qPrintable(text.out));
        const auto json =
            testsupport::runServoctl({QStringLiteral("--json"), QStringLiteral("decode"),
                                      QStringLiteral("--log"), recording});
        QCOMPARE(json.exitCode, 0);
        const QJsonArray frames = QJsonDocument::fromJson(json.out.toUtf8()).array();
        QCOMPARE(frames.size(), 8);
        QCOMPARE(frames.at(0)[QStringLiteral("direction")].toString(), QStringLiteral("program"));
        QCOMPARE(frames.at(1)[QStringLiteral("direction")].toString(), QStringLiteral("bus"));
        QVERIFY(!frames.at(1).toObject().contains(QStringLiteral("registers"))); // model unknown
        const QJsonObject unlock = frames.at(4)[QStringLiteral("registers")][0].toObject();
        QCOMPARE(unlock[QStringLiteral("key")].toString(), QStringLiteral("lock"));
        QCOMPARE(unlock[QStringLiteral("value")].toInt(), 0);
        QCOMPARE(unlock[QStringLiteral("access")].toString(), QStringLiteral("write"));
        // Something that is no recording is refused with the reason, exit 2.
        const QString other = writeTestFile(QStringLiteral("other.log"), "0.1 program FF FF\n");
        const auto refused =
            testsupport::runServoctl({QStringLiteral("decode"), QStringLiteral("--log"), other});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.contains(QStringLiteral("no ServoBench share recording")),
                 qPrintable(refused.err));
    }

    void theAdapterUnpluggedIsReportedAndTheShareGoesOnWhenItIsBack()
    {
        const auto options = busOptions(testsupport::servosAt(k1M, {u"STS3215"}));
        startShare(options);
        m_simulator.reset(); // the adapter is gone
        QTRY_VERIFY_WITH_TIMEOUT(m_notes.join(u' ').contains(QStringLiteral("went away")), 5000);
        QVERIFY(m_share->isSharing());
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        QTRY_VERIFY2_WITH_TIMEOUT(m_notes.size() == 2
                                      && m_notes.last().contains(QStringLiteral("goes on")),
                                  qPrintable(m_notes.join(u'|')), 5000);
        const bool answered = asProgram([path = programPath()] {
            BlockingClient program;
            return program.open(path, k1M) && program.ask(feetech::ping(1), 1).has_value();
        });
        QVERIFY2(answered, qPrintable(m_notes.join(u'|')));
    }

    void servoctlShareForwardsUntilSigtermAndSaysWhatPassed()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
        QProcess servoctl;
        servoctl.start(QStringLiteral(SERVOBENCH_BINARY_DIR "/app/servoctl"),
                       {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("share"),
                        QStringLiteral("--link"), programPath(), QStringLiteral("--json")});
        QVERIFY(servoctl.waitForStarted(10000));
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(programPath()).isSymLink(), 10000);
        const bool answered = asProgram([path = programPath()] {
            BlockingClient program;
            return program.open(path, k1M) && program.ask(feetech::ping(1), 1).has_value();
        });
        QVERIFY(answered);
        QTRY_VERIFY_WITH_TIMEOUT(servoctl.bytesAvailable() > 0, 5000);
        const QJsonObject line = QJsonDocument::fromJson(servoctl.readLine()).object();
        QCOMPARE(line[QStringLiteral("instruction")].toString(), QStringLiteral("PING"));
        QCOMPARE(line[QStringLiteral("id")].toInt(), 1);
        servoctl.terminate(); // SIGTERM
        QVERIFY(servoctl.waitForFinished(10000));
        QCOMPARE(servoctl.exitStatus(), QProcess::NormalExit);
        QCOMPARE(servoctl.exitCode(), 0);
        const QString summary = QString::fromUtf8(servoctl.readAllStandardError());
        QVERIFY2(summary.contains(QStringLiteral("1 frame(s) (6 bytes) from the program")),
                 qPrintable(summary));
        QVERIFY(!QFileInfo::exists(programPath())); // the link is gone with the share
    }

    void servoctlShareAnswersTheProgramWhileNobodyReadsItsOutput()
    {
        QString error;
        QVERIFY2(
            startSimulator(
                busOptions(testsupport::servosAt(
                    k1M, {u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215", u"STS3215"})),
                &error),
            qPrintable(error));
        // servoctl's stdout is a pipe this test does not read: a paused pager. Once it is full,
        // more than the outlet's queue holds passes (some 1.5 kB of JSON per exchange).
        constexpr int kExchangesWhileFull = 600;
        int pipeEnds[2];
        QCOMPARE(::pipe(pipeEnds), 0);
        const auto closePipe = qScopeGuard([&] {
            ::close(pipeEnds[0]);
            ::close(pipeEnds[1]);
        });
        QProcess servoctl;
        servoctl.setStandardOutputFile(
            QStringLiteral("/proc/%1/fd/%2").arg(::getpid()).arg(pipeEnds[1]));
        servoctl.start(QStringLiteral(SERVOBENCH_BINARY_DIR "/app/servoctl"),
                       {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("--json"),
                        QStringLiteral("share"), QStringLiteral("--link"), programPath()});
        QVERIFY(servoctl.waitForStarted(10000));
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(programPath()).isSymLink(), 10000);
        struct Loop
        {
            int exchanges = 0;
            int whileFull = 0; // exchanges once the pipe was full
            int unanswered = 0;
            int foreign = 0; // answers that belong to another request
        };
        // Two requests in turn whose answers differ: an answer to the one before is seen. The
        // loop goes on for a number of exchanges once the pipe is full, however long they take.
        const Loop loop = asProgram([path = programPath(), pipeOut = pipeEnds[0]] {
            Loop done;
            BlockingClient program;
            if (!program.open(path, k1M))
                return done;
            const QVector<quint8> ids {1, 2, 3, 4, 5, 6};
            const auto pipeFull = [pipeOut] {
                int held = 0;
                // Linux fills a pipe page by page: 48-64 kB is as full as it gets.
                return ::ioctl(pipeOut, FIONREAD, &held) == 0 && held >= 32 * 1024;
            };
            while (done.whileFull < kExchangesWhileFull && done.exchanges < 100000) {
                if (done.whileFull > 0 || pipeFull())
                    done.whileFull += 2;
                const QVector<QByteArray> feedback =
                    program.exchange(feetech::syncRead(56, 8, ids), int(ids.size()));
                const quint8 id = quint8(1 + done.exchanges % 6);
                const std::optional<QByteArray> model = program.ask(feetech::read(id, 3, 2), id);
                done.exchanges += 2;
                done.unanswered += (feedback.size() < ids.size()) + !model.has_value();
                for (qsizetype i = 0; i < feedback.size(); ++i) {
                    if (quint8(feedback.at(i).at(2)) != ids.value(i) || feedback.at(i).size() != 14)
                        ++done.foreign;
                }
                if (model && model->size() != 8)
                    ++done.foreign;
            }
            done.foreign += program.unexpectedFrames();
            return done;
        });
        QCOMPARE(loop.whileFull, kExchangesWhileFull);
        QCOMPARE(loop.unanswered, 0);
        QCOMPARE(loop.foreign, 0);
        // Stalled on its output, it still ends at once on SIGTERM, and says what it dropped.
        servoctl.terminate();
        QVERIFY(servoctl.waitForFinished(5000));
        QCOMPARE(servoctl.exitCode(), 0);
        const QString summary = QString::fromUtf8(servoctl.readAllStandardError());
        QVERIFY2(summary.contains(QStringLiteral("line(s) nobody read")), qPrintable(summary));
    }

    void servoctlShareRefusesWhatCannotWork()
    {
        QString error;
        QVERIFY2(startSimulator(busOptions(testsupport::servosAt(k1M, {u"STS3215"})), &error),
                 qPrintable(error));
        const auto noLink = testsupport::runServoctl(
            {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("share")});
        QCOMPARE(noLink.exitCode, 2);
        QVERIFY(noLink.err.contains(QStringLiteral("--link")));
        const auto samePort = testsupport::runServoctl(
            {QStringLiteral("--port"), m_simulator->linkPath(), QStringLiteral("share"),
             QStringLiteral("--link"), m_simulator->linkPath()});
        QCOMPARE(samePort.exitCode, 1);
        QVERIFY2(samePort.err.contains(QStringLiteral("own port")), qPrintable(samePort.err));
        const QString file = writeTestFile(QStringLiteral("taken"), "a file");
        const auto taken =
            testsupport::runServoctl({QStringLiteral("--port"), m_simulator->linkPath(),
                                      QStringLiteral("share"), QStringLiteral("--link"), file});
        QCOMPARE(taken.exitCode, 1);
        QVERIFY2(taken.err.contains(QStringLiteral("not a symlink")), qPrintable(taken.err));
        const auto noPort = testsupport::runServoctl(
            {QStringLiteral("--port"), m_dir.filePath(QStringLiteral("absent")),
             QStringLiteral("share"), QStringLiteral("--link"), programPath()});
        QCOMPARE(noPort.exitCode, 1);
    }
};

QTEST_GUILESS_MAIN(TestBusShare)
#include "tst_busshare.moc"
