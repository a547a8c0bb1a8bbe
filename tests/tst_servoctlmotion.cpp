// servoctl feetech record and replay against simulated servos over a pty: positions turned by a
// scripted hand into CSV, and recordings played back eased in, at their times, held at the end.
#include "feetechbus.h"
#include "scriptedhand.h"
#include "servoctlrun.h"

#include "motionrecording.h"

#include <QtTest>

#include <csignal>

using testsupport::runServoctl;
using testsupport::ScriptedHand;

namespace {

constexpr int kGoalAddress = 42;
constexpr int kTorqueAddress = 40;

// A write the bus received: when (the simulator's clock, seconds), how (SYNC WRITE or WRITE),
// where, and the 2-byte value each servo got there.
struct GoalFrame
{
    int index = 0; // among the frames of its kind
    double seconds = 0.0;
    bool sync = false;
    int address = 0;
    QMap<quint8, int> goals;
};

// The WRITE and SYNC WRITE frames of the simulator's log, in order.
QVector<GoalFrame> writeFrames(const QString &logPath)
{
    QVector<GoalFrame> frames;
    QFile file(logPath);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return frames;
    for (const QByteArray &line : file.readAll().split('\n')) {
        const QList<QByteArray> parts = line.split(' ');
        if (parts.size() < 3 || parts.at(1) != "in")
            continue;
        const QString hex = QString::fromLatin1(line.mid(parts.at(0).size() + 4))
                                .section(QStringLiteral("  #"), 0, 0)
                                .trimmed();
        const auto bytes = util::parseHex(hex);
        const auto packet = bytes ? feetech::decodePacket(*bytes) : std::nullopt;
        if (!packet || packet->parameters.size() < 2)
            continue;
        GoalFrame frame;
        frame.seconds = parts.at(0).toDouble();
        frame.address = quint8(packet->parameters.at(0));
        const QByteArray &p = packet->parameters;
        const auto value = [&p](int at, int size) {
            return size == 1 ? int(quint8(p.at(at)))
                             : quint8(p.at(at)) | (quint8(p.at(at + 1)) << 8);
        };
        if (packet->code == quint8(feetech::Instruction::SyncWrite)) {
            frame.sync = true;
            const int length = quint8(p.at(1));
            for (int at = 2; at + length < p.size() + 1; at += length + 1)
                frame.goals.insert(quint8(p.at(at)), value(at + 1, length));
        } else if (packet->code == quint8(feetech::Instruction::Write)) {
            frame.goals.insert(packet->id, value(1, int(p.size()) - 1));
        } else {
            continue;
        }
        frame.index = int(frames.size());
        frames.append(frame);
    }
    return frames;
}

// Those that wrote goal positions, indexed among themselves.
QVector<GoalFrame> goalFrames(const QString &logPath)
{
    QVector<GoalFrame> goals;
    for (GoalFrame frame : writeFrames(logPath)) {
        if (frame.address != kGoalAddress)
            continue;
        frame.index = int(goals.size());
        goals.append(frame);
    }
    return goals;
}

// Where in writeFrames the first write of `address` to servo `id` is; -1 when none.
int firstWrite(const QVector<GoalFrame> &frames, int address, quint8 id)
{
    for (const GoalFrame &frame : frames) {
        if (frame.address == address && frame.goals.contains(id))
            return frame.index;
    }
    return -1;
}

} // namespace

class TestServoctlMotion : public testsupport::FeetechBusTest
{
    Q_OBJECT

private:
    // Two STS3215 at IDs 1 and 2, torque off, horns at `first` and `second`.
    void startArm(int first = 1000, int second = 1700)
    {
        QString error;
        QVERIFY2(startSimulator(
                     busOptions(testsupport::servosAt(1000000, {u"STS3215", u"STS3215"})), &error),
                 qPrintable(error));
        ScriptedHand hand(*m_simulator);
        hand.place(1, first);
        hand.place(2, second);
    }

    testsupport::ServoctlResult servoctl(const QStringList &arguments) const
    {
        return runServoctl(QStringList {QStringLiteral("--port"), m_simulator->linkPath(),
                                        QStringLiteral("feetech")}
                           + arguments);
    }

    QString path(const QString &name) const { return m_dir.filePath(name); }

    int syncReads() const
    {
        return int(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::SyncRead).size());
    }

    // Frames at `step` seconds: servo 1 from 2000 up by 40 a frame, servo 2 down from 1800 by 20.
    QString writeRecording(const QString &name, int frames, double step)
    {
        QByteArray csv = "time_s,pan@1,id_2\n";
        for (int i = 0; i < frames; ++i)
            csv += QByteArray::number(0.5 + i * step, 'f', 3) + ','
                + QByteArray::number(2000 + 40 * i) + ',' + QByteArray::number(1800 - 20 * i)
                + '\n';
        return writeTestFile(name, csv);
    }

    // The SYNC WRITEs that carried the recording's frames (servo 1's goal 2000 + 40 i), from
    // index `from` of the log's goal frames: at most `count` of them from the first frame on.
    // An ease that ended on the first frame's very goals comes just before it: the later one is
    // the first frame.
    static QVector<GoalFrame> played(const QVector<GoalFrame> &frames, int from, int count)
    {
        QVector<GoalFrame> play;
        for (int i = from; i < frames.size() && play.size() < count; ++i) {
            const GoalFrame &frame = frames.at(i);
            const bool first = frame.sync && frame.goals.value(1) == 2000;
            if (play.isEmpty() && !first)
                continue;
            if (play.size() == 1 && first && frame.goals == play.first().goals)
                play.clear();
            play.append(frame);
        }
        return play;
    }

    // The goal frames the log shows once it holds the frame that sets servo 1 to `lastGoal`
    // `times` times (or after 5 s without): the simulator logs a frame a moment after it came,
    // and servoctl exits as soon as it has sent the last one.
    QVector<GoalFrame> goalFramesThrough(int lastGoal, int times = 1) const
    {
        QVector<GoalFrame> frames;
        const bool logged = QTest::qWaitFor(
            [&] {
                frames = goalFrames(logPath());
                return std::count_if(frames.cbegin(), frames.cend(),
                                     [lastGoal](const GoalFrame &frame) {
                                         return frame.sync && frame.goals.value(1) == lastGoal;
                                     })
                    >= times;
            },
            5000);
        if (!logged)
            qWarning("the log shows no frame setting servo 1 to %d %d time(s)", lastGoal, times);
        return frames;
    }

    void checkFramesInOrder(const QVector<GoalFrame> &play, int frames)
    {
        QCOMPARE(play.size(), frames);
        for (int i = 0; i < frames; ++i) {
            QCOMPARE(play.at(i).goals.value(1), 2000 + 40 * i);
            QCOMPARE(play.at(i).goals.value(2), 1800 - 20 * i);
        }
    }

private slots:
    void cleanup()
    {
        m_simulator.reset();
        QFile::remove(logPath());
    }

    void recordWritesAColumnPerJointAsTheHandTurnsThemAndLeavesTorqueAlone()
    {
        startArm(1000, 2000);
        ScriptedHand hand(*m_simulator);
        hand.place(1, 1000);
        hand.place(2, 2000);
        hand.script(1, {3000, 1500});
        hand.script(2, {2500});
        hand.start([this] { return syncReads() > 0; });
        const QString out = path(QStringLiteral("hand.csv"));
        const auto result = servoctl(
            {QStringLiteral("record"), QStringLiteral("--ids"), QStringLiteral("1,2"),
             QStringLiteral("--names"), QStringLiteral("shoulder_pan,shoulder_lift"),
             QStringLiteral("--duration"), QStringLiteral("3"), QStringLiteral("--out"), out});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        QVERIFY2(hand.done(), "the hand had not finished when the recording ended");
        QVERIFY2(result.out.contains(QStringLiteral("into")), qPrintable(result.out));

        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(file.readLine().trimmed(), QByteArray("time_s,shoulder_pan@1,shoulder_lift@2"));
        util::FileError error;
        const auto recording = feetech::loadMotionRecording(out, &error);
        QVERIFY2(recording, qPrintable(error.describe()));
        QVERIFY(recording->frames.size() > 20);
        QCOMPARE(recording->times.first(), 0.0);
        int highest = 0;
        for (int i = 0; i < recording->frames.size(); ++i) {
            if (i > 0)
                QVERIFY(recording->times.at(i) >= recording->times.at(i - 1));
            highest = std::max(highest, recording->frames.at(i).at(0));
        }
        QVERIFY(qAbs(recording->frames.first().at(0) - 1000) <= 60);
        QVERIFY2(highest >= 2940, qPrintable(QString::number(highest)));
        QVERIFY(qAbs(recording->frames.last().at(0) - 1500) <= 5);
        QVERIFY(qAbs(recording->frames.last().at(1) - 2500) <= 5);
        // Torque is left as it is: nothing was written to any servo.
        QCOMPARE(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size(), 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void recordEndedBySigtermLeavesAWholeFileNamedByIds()
    {
        startArm();
        QTimer interrupter;
        connect(&interrupter, &QTimer::timeout, this, [&] {
            if (syncReads() > 10) {
                interrupter.stop();
                std::raise(SIGTERM);
            }
        });
        interrupter.start(5);
        const QString out = path(QStringLiteral("ids.csv"));
        const auto result =
            servoctl({QStringLiteral("--json"), QStringLiteral("record"), QStringLiteral("--ids"),
                      QStringLiteral("1-2"), QStringLiteral("--out"), out});
        QVERIFY(!interrupter.isActive());
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        util::FileError error;
        const auto recording = feetech::loadMotionRecording(out, &error);
        QVERIFY2(recording, qPrintable(error.describe()));
        const QJsonObject report = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(report[QStringLiteral("file")].toString(), out);
        QCOMPARE(report[QStringLiteral("frames")].toInt(), int(recording->frames.size()));
        QCOMPARE(report[QStringLiteral("complete")].toBool(), true);
        QCOMPARE(report[QStringLiteral("joints")].toArray().at(1).toString(),
                 QStringLiteral("id_2"));
        QCOMPARE(recording->joints.size(), 2);
        QCOMPARE(recording->joints.at(0).column(), QStringLiteral("id_1"));
        QCOMPARE(recording->joints.at(1).column(), QStringLiteral("id_2"));
        QVERIFY(!recording->isEmpty());
        QVERIFY(qAbs(recording->frames.last().at(1) - 1700) <= 5);
    }

    void replayEasesInFromWhereTheArmStandsAndHoldsTheLastFrame()
    {
        startArm(1000, 1700);
        const QString file = writeRecording(QStringLiteral("ten.csv"), 10, 0.1);
        const auto result = servoctl({QStringLiteral("replay"), file});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        QVERIFY2(result.out.contains(QStringLiteral("holds")), qPrintable(result.out));

        const QVector<GoalFrame> frames = goalFrames(logPath());
        QVERIFY(!frames.isEmpty());
        // The first goal each servo gets is where it stands: torque on moves nothing.
        QMap<quint8, int> first;
        for (const GoalFrame &frame : frames) {
            for (auto it = frame.goals.cbegin(); it != frame.goals.cend(); ++it) {
                if (!first.contains(it.key()))
                    first.insert(it.key(), it.value());
            }
        }
        QVERIFY(qAbs(first.value(1) - 1000) <= 2);
        QVERIFY(qAbs(first.value(2) - 1700) <= 2);
        // And it came before torque on.
        const QVector<GoalFrame> writes = writeFrames(logPath());
        for (const quint8 id : {1, 2}) {
            const int torqueOn = firstWrite(writes, kTorqueAddress, id);
            QVERIFY(torqueOn >= 0);
            QVERIFY(firstWrite(writes, kGoalAddress, id) < torqueOn);
        }
        // Then the goals walk to the first frame in small steps, never a jump.
        int previous = first.value(1);
        int steps = 0;
        for (const GoalFrame &frame : frames) {
            if (!frame.sync)
                continue;
            QVERIFY2(
                qAbs(frame.goals.value(1) - previous) <= 150,
                qPrintable(QStringLiteral("%1 -> %2").arg(previous).arg(frame.goals.value(1))));
            previous = frame.goals.value(1);
            ++steps;
        }
        QVERIFY(steps > 10);
        checkFramesInOrder(played(frames, 0, 10), 10);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        QCOMPARE(simulatorValue(1, u"goal_position"), 2000 + 40 * 9);
        QCOMPARE(simulatorValue(2, u"goal_position"), 1800 - 20 * 9);
    }

    void replayKeepsTheRecordedSpacingScaledBySpeed_data()
    {
        QTest::addColumn<QString>("speed");
        QTest::addColumn<double>("span");
        QTest::newRow("recorded speed") << QStringLiteral("1") << 1.8;
        QTest::newRow("twice as fast") << QStringLiteral("2") << 0.9;
        QTest::newRow("half speed") << QStringLiteral("0.5") << 3.6;
    }

    void replayKeepsTheRecordedSpacingScaledBySpeed()
    {
        QFETCH(QString, speed);
        QFETCH(double, span);
        startArm(2000, 1800); // at the first frame already: no ease
        const QString file = writeRecording(QStringLiteral("spaced.csv"), 10, 0.2);
        const auto result =
            servoctl({QStringLiteral("replay"), file, QStringLiteral("--speed"), speed});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QVector<GoalFrame> play = played(goalFramesThrough(2000 + 40 * 9), 0, 10);
        checkFramesInOrder(play, 10);
        const double measured = play.last().seconds - play.first().seconds;
        QVERIFY2(measured > span * 0.8 && measured < span * 1.5,
                 qPrintable(QStringLiteral("%1 s for %2 s").arg(measured).arg(span)));
        for (int i = 1; i < play.size(); ++i) {
            const double gap = play.at(i).seconds - play.at(i - 1).seconds;
            QVERIFY2(
                gap > span / 9 * 0.4,
                qPrintable(
                    QStringLiteral("frame %1 came %2 s after the one before").arg(i).arg(gap)));
        }
    }

    void theEaseTakesAsLongAsAskedButNeverRushes_data()
    {
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<double>("seconds");
        // 1000 steps to go: 2.5 s at the default 400 steps/s, never under 1 s (1000 steps/s).
        QTest::newRow("default") << QStringList() << 2.5;
        QTest::newRow("--ease 1.5")
            << QStringList {QStringLiteral("--ease"), QStringLiteral("1.5")} << 1.5;
        QTest::newRow("--ease 0") << QStringList {QStringLiteral("--ease"), QStringLiteral("0")}
                                  << 1.0;
    }

    void theEaseTakesAsLongAsAskedButNeverRushes()
    {
        QFETCH(QStringList, options);
        QFETCH(double, seconds);
        startArm(1000, 1800);
        const QString file = writeRecording(QStringLiteral("ease.csv"), 3, 0.1);
        const auto result = servoctl(QStringList {QStringLiteral("replay"), file} + options);
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QVector<GoalFrame> goals = goalFramesThrough(2000 + 40 * 2);
        const QVector<GoalFrame> play = played(goals, 0, 3);
        checkFramesInOrder(play, 3);
        const auto firstSync = std::find_if(goals.cbegin(), goals.cend(),
                                            [](const GoalFrame &frame) { return frame.sync; });
        QVERIFY(firstSync != goals.cend());
        const double measured = play.first().seconds - firstSync->seconds;
        QVERIFY2(measured > seconds * 0.8 && measured < seconds * 1.5,
                 qPrintable(QStringLiteral("%1 s for %2 s").arg(measured).arg(seconds)));
    }

    void replayLoopsEasingBackToTheFirstFrameBetweenLoops()
    {
        startArm(2000, 1800);
        const QString file = writeRecording(QStringLiteral("loop.csv"), 5, 0.1);
        const auto result = servoctl({QStringLiteral("--json"), QStringLiteral("replay"), file,
                                      QStringLiteral("--loop"), QStringLiteral("3")});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        const QJsonObject report = QJsonDocument::fromJson(result.out.toUtf8()).object();
        QCOMPARE(report[QStringLiteral("loops")].toInt(), 3);
        QCOMPARE(report[QStringLiteral("frames")].toInt(), 5);
        const QVector<GoalFrame> frames = goalFramesThrough(2000 + 40 * 4, 3);
        int from = 0;
        for (int loop = 0; loop < 3; ++loop) {
            const QVector<GoalFrame> play = played(frames, from, 5);
            checkFramesInOrder(play, 5);
            from = play.last().index + 1;
            if (loop < 2) {
                // The way back: goals between the last frame and the first, going down.
                QVERIFY(from < frames.size());
                const int back = frames.at(from).goals.value(1);
                QVERIFY2(back < 2160 && back >= 2000, qPrintable(QString::number(back)));
            }
        }
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        QCOMPARE(simulatorValue(1, u"goal_position"), 2160);
    }

    void replayWithReleaseSwitchesTorqueOffAtTheEnd()
    {
        startArm(2000, 1800);
        const QString file = writeRecording(QStringLiteral("release.csv"), 3, 0.1);
        const auto result = servoctl({QStringLiteral("replay"), file, QStringLiteral("--release")});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        QVERIFY2(result.out.contains(QStringLiteral("torque is off")), qPrintable(result.out));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
        QCOMPARE(simulatorValue(2, u"torque_enable"), 0);
        QVERIFY(testsupport::writesReceived(logPath(), 1, kTorqueAddress) >= 2);
    }

    void sigtermDuringReplayHoldsTheArmWhereItStands()
    {
        startArm(1000, 1700);
        const QString file = writeRecording(QStringLiteral("long.csv"), 50, 0.2);
        QTimer interrupter;
        connect(&interrupter, &QTimer::timeout, this, [&] {
            if (played(goalFrames(logPath()), 0, 3).size() >= 3) {
                interrupter.stop();
                std::raise(SIGTERM);
            }
        });
        interrupter.start(20);
        const auto result = servoctl({QStringLiteral("replay"), file});
        QVERIFY(!interrupter.isActive());
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QStringLiteral("interrupted")), qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("holds where it stood")),
                 qPrintable(result.err));
        QCOMPARE(simulatorValue(1, u"torque_enable"), 1);
        const int goal = simulatorValue(1, u"goal_position");
        QVERIFY2(goal < 2000 + 40 * 49, qPrintable(QString::number(goal)));
        // The hold wrote where each servo stood after the last goal the replay sent.
        const QVector<GoalFrame> goals = goalFrames(logPath());
        QVERIFY(!goals.last().sync);
        QCOMPARE(goals.last().goals.value(1, -1), -1);
        QCOMPARE(goals.at(goals.size() - 2).goals.value(1), goal);
        QVERIFY(!goals.at(goals.size() - 2).sync);
        QTRY_VERIFY(qAbs(simulatorValue(1, u"present_position") - goal) <= 10);
        QCOMPARE(simulatorValue(1, u"goal_position"), goal);
    }

    void framesALittleBeyondTheAngleLimitsArePlayedAtTheLimit()
    {
        // The hand's overshoot: the last frame, 2160, is 10 steps past the limit of 2150.
        startArm(2000, 1800);
        setSimulatorValue(1, u"max_angle_limit", 2150);
        const QString file = writeRecording(QStringLiteral("overshoot.csv"), 5, 0.1);
        const auto result = servoctl({QStringLiteral("replay"), file});
        QVERIFY2(result.exitCode == 0, qPrintable(result.err));
        QVERIFY2(result.out.contains(QStringLiteral("1 position(s) a little past a joint's limit")),
                 qPrintable(result.out));
        const QVector<GoalFrame> frames = goalFrames(logPath());
        QVERIFY(!frames.isEmpty());
        QCOMPARE(frames.last().goals.value(1), 2150);
        QCOMPARE(simulatorValue(1, u"goal_position"), 2150);
    }

    void framesBeyondTheAngleLimitsAreRefusedBeforeAnythingMoves()
    {
        // Frame 3 (2080) is within the overshoot allowed, frame 4 (2120) 70 steps past: no
        // overshoot of a hand, but a recording of another arm.
        startArm(1000, 1700);
        setSimulatorValue(1, u"max_angle_limit", 2050);
        const QString file = writeRecording(QStringLiteral("wide.csv"), 5, 0.1);
        const auto result = servoctl({QStringLiteral("replay"), file});
        QCOMPARE(result.exitCode, 2);
        QVERIFY2(result.err.contains(QStringLiteral("Frame 4")), qPrintable(result.err));
        QVERIFY2(result.err.contains(QStringLiteral("2120")), qPrintable(result.err));
        QCOMPARE(goalFrames(logPath()).size(), 0);
        QCOMPARE(
            testsupport::feetechRequestsReceived(logPath(), feetech::Instruction::Write).size(), 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void malformedFilesAndBadOptionsAreUsageErrors_data()
    {
        QTest::addColumn<QByteArray>("csv");
        QTest::addColumn<QStringList>("options");
        QTest::addColumn<QString>("said");
        const QByteArray good = "time_s,id_1,id_2\n0,2000,1800\n0.1,2010,1800\n";
        QTest::newRow("empty") << QByteArray() << QStringList() << QStringLiteral("empty");
        QTest::newRow("no time column")
            << QByteArray("t,id_1\n0,2000\n") << QStringList() << QStringLiteral("time_s");
        QTest::newRow("a column naming no servo")
            << QByteArray("time_s,elbow\n0,2000\n") << QStringList()
            << QStringLiteral("\"elbow\" names no servo");
        QTest::newRow("a servo twice") << QByteArray("time_s,id_1,arm@1\n0,2000,2000\n")
                                       << QStringList() << QStringLiteral("two columns");
        QTest::newRow("a short row") << QByteArray("time_s,id_1,id_2\n0,2000\n") << QStringList()
                                     << QStringLiteral("line 2 has 2 cells");
        QTest::newRow("time going back") << QByteArray("time_s,id_1\n1,2000\n0.5,2000\n")
                                         << QStringList() << QStringLiteral("goes back");
        QTest::newRow("not a position")
            << QByteArray("time_s,id_1\n0,far\n") << QStringList() << QStringLiteral("\"far\"");
        QTest::newRow("no frame") << QByteArray("time_s,id_1\n") << QStringList()
                                  << QStringLiteral("no frame");
        QTest::newRow("a column of a servo not on the bus")
            << QByteArray("time_s,id_1,id_9\n0,2000,2000\n") << QStringList()
            << QStringLiteral("id_9 matches no servo");
        QTest::newRow("speed 0") << good
                                 << QStringList {QStringLiteral("--speed"), QStringLiteral("0")}
                                 << QStringLiteral("--speed");
        QTest::newRow("negative speed")
            << good << QStringList {QStringLiteral("--speed"), QStringLiteral("-1")}
            << QStringLiteral("--speed");
        QTest::newRow("no loop") << good
                                 << QStringList {QStringLiteral("--loop"), QStringLiteral("0")}
                                 << QStringLiteral("--loop");
        QTest::newRow("negative ease")
            << good << QStringList {QStringLiteral("--ease"), QStringLiteral("-2")}
            << QStringLiteral("--ease");
    }

    void malformedFilesAndBadOptionsAreUsageErrors()
    {
        QFETCH(QByteArray, csv);
        QFETCH(QStringList, options);
        QFETCH(QString, said);
        startArm();
        const QString file = writeTestFile(QStringLiteral("bad.csv"), csv);
        const auto result = servoctl(QStringList {QStringLiteral("replay"), file} + options);
        QCOMPARE(result.exitCode, 2);
        QVERIFY2(result.err.contains(said), qPrintable(result.err));
        QCOMPARE(goalFrames(logPath()).size(), 0);
        QCOMPARE(simulatorValue(1, u"torque_enable"), 0);
    }

    void twoServosAtOneIdAreNotReplayed()
    {
        sim::SimulatorOptions options = busOptions(
            {{1, QStringLiteral("STS3215"), 1000000}, {1, QStringLiteral("STS3215"), 1000000}});
        options.allowSharedIds = true;
        QString error;
        QVERIFY2(startSimulator(options, &error), qPrintable(error));
        const QString file = writeTestFile(QStringLiteral("one.csv"), "time_s,id_1\n0,2000\n");
        const auto result = servoctl({QStringLiteral("replay"), file});
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(result.err.contains(QStringLiteral("at ID 1")), qPrintable(result.err));
        QCOMPARE(writeFrames(logPath()).size(), 0);
    }

    void aBusLostDuringReplayExitsOneSayingSo()
    {
        startArm(1000, 1700);
        const QString file = writeRecording(QStringLiteral("lost.csv"), 50, 0.2);
        const QString link = m_simulator->linkPath();
        QTimer unplugger;
        connect(&unplugger, &QTimer::timeout, this, [&] {
            if (played(goalFrames(logPath()), 0, 2).size() >= 2) {
                unplugger.stop();
                m_simulator->stop();
            }
        });
        unplugger.start(20);
        const auto result = servoctl({QStringLiteral("replay"), file});
        QVERIFY(!unplugger.isActive());
        QCOMPARE(result.exitCode, 1);
        // The port's own words: the link went away under the replay.
        const QString lastLine = result.err.trimmed().section(QLatin1Char('\n'), -1);
        QVERIFY2(lastLine.contains(link), qPrintable(result.err));
        QVERIFY2(!result.err.contains(QStringLiteral("interrupted")), qPrintable(result.err));
    }
};

QTEST_GUILESS_MAIN(TestServoctlMotion)
#include "tst_servoctlmotion.moc"
