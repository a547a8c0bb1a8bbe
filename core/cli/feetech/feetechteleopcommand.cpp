// servoctl feetech teleop: checks that nothing can jump, holds, then one SYNC READ of the leader
// and one SYNC WRITE to the follower per cycle until Ctrl-C, SIGTERM or --duration.
#include "feetechteleopcommand.h"

#include "armcalibration.h"
#include "motionrecording.h"
#include "registerkeys.h"
#include "servoctltr.h"
#include "telemetry.h"
#include "teleoploop.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>

namespace cli {

using feetech::LeRobotMotor;

std::optional<QVector<ServoInfo>>
FeetechTeleopCommand::identifyArm(FeetechDevice &device, const QVector<LeRobotMotor> &motors,
                                  const QString &calibrationPath, int *exitCode)
{
    QVector<ServoInfo> servos;
    for (const LeRobotMotor &motor : motors) {
        const auto servo = device.identify(quint8(motor.id), busBaud());
        if (!servo) {
            m_output.err << "servoctl: "
                         << ServoctlTr::tr("joint %1 (servo %2) does not answer: %3")
                                .arg(motor.name)
                                .arg(motor.id)
                                .arg(device.error())
                         << '\n';
            *exitCode = ExitUsage;
            return std::nullopt;
        }
        QVector<feetech::Block> blocks;
        for (const QStringView key :
             {QStringView(feetech::kOffsetKey), QStringView(feetech::kMinimumLimitKey),
              QStringView(feetech::kMaximumLimitKey)}) {
            if (const feetech::Register *reg = servo->table().find(key))
                blocks.append({reg->address, reg->size});
        }
        const auto memory = device.read(*servo, blocks);
        if (!memory) {
            *exitCode = fail(device.error());
            return std::nullopt;
        }
        const QHash<QString, qint32> values = valuesByKey(decodeMemory(servo->table(), *memory));
        const QStringList mismatches = feetech::calibrationDifferences(
            servo->table(),
            feetech::calibrationWrites(motor.homingOffset, motor.rangeMin, motor.rangeMax), values);
        if (!mismatches.isEmpty()) {
            m_output.err << "servoctl: "
                         << ServoctlTr::tr(
                                "joint %1 (servo %2) does not hold what %3 says (%4): write "
                                "the file to the arm first: servoctl --port %5 feetech "
                                "calibration load %3")
                                .arg(motor.name)
                                .arg(motor.id)
                                .arg(QDir::toNativeSeparators(calibrationPath),
                                     mismatches.join(QStringLiteral("; ")), device.port())
                         << '\n';
            *exitCode = ExitUsage;
            return std::nullopt;
        }
        servos.append(*servo);
    }
    return servos;
}

std::optional<QVector<qint32>>
FeetechTeleopCommand::presentPositions(FeetechDevice &device, const QVector<ServoInfo> &servos)
{
    QVector<qint32> positions;
    for (const ServoInfo &servo : servos) {
        const feetech::Register *reg = servo.table().find(feetech::registerkeys::kPresentPosition);
        if (!reg)
            return std::nullopt;
        const auto memory = device.read(servo, {{reg->address, reg->size}});
        if (!memory)
            return std::nullopt;
        positions.append(valuesByKey(decodeMemory(servo.table(), *memory))
                             .value(feetech::registerkeys::kPresentPosition));
    }
    return positions;
}

bool FeetechTeleopCommand::writeAll(FeetechDevice &device, const QVector<ServoInfo> &servos,
                                    const QString &key, const QVector<qint32> &values)
{
    const feetech::RegisterTable &table = servos.first().table();
    const feetech::Register *reg = table.find(key);
    if (!reg)
        return false;
    QVector<feetech::SyncWriteEntry> entries;
    for (int i = 0; i < servos.size(); ++i)
        entries.append({servos.at(i).id, *feetech::encodeValue(values.at(i), table.format(*reg))});
    const auto result =
        device.operate(feetech::operations::syncWrite(busBaud(), reg->address, reg->size, entries));
    return result && result->ok;
}

int FeetechTeleopCommand::teleop(const QString &what, const QStringList &operands)
{
    allowOptions(what,
                 {QStringLiteral("leader"), QStringLiteral("calibration"),
                  QStringLiteral("leader-calibration"), QStringLiteral("rate"),
                  QStringLiteral("duration"), QStringLiteral("max-speed"), QStringLiteral("record"),
                  QStringLiteral("release"), QStringLiteral("norm-mode")});
    expectOperands(what, operands, 0, {});
    for (const char *option : {"port", "leader", "calibration", "leader-calibration"}) {
        if (!m_args.has(QLatin1String(option)))
            throw UsageError {
                ServoctlTr::tr("%1 needs --port FOLLOWER, --leader PORT, --calibration "
                               "FILE and --leader-calibration FILE")
                    .arg(what)};
    }
    const QString followerPort = m_args.value(QStringLiteral("port"));
    const QString leaderPort = m_args.value(QStringLiteral("leader"));
    const auto samePort = [](const QString &a, const QString &b) {
        const QString canonicalA = QFileInfo(a).canonicalFilePath();
        return a == b || (!canonicalA.isEmpty() && canonicalA == QFileInfo(b).canonicalFilePath());
    };
    if (samePort(followerPort, leaderPort))
        throw UsageError {
            ServoctlTr::tr("--leader and --port name the same port: the leader and the "
                           "follower are two arms on two adapters")};
    const double rate = m_args.has(QStringLiteral("rate"))
        ? double(integerOption(m_args, QStringLiteral("rate"), 1, 200))
        : feetech::TeleopLoop::kDefaultRateHz;
    const double maxSpeed = m_args.has(QStringLiteral("max-speed"))
        ? double(integerOption(m_args, QStringLiteral("max-speed"), 1, 720))
        : feetech::TeleopLoop::kDefaultMaxSpeed;
    // LeRobot's names for how body joints map; its SO arms' default unless told.
    auto normMode = feetech::TeleopMapping::kDefaultNormMode;
    if (m_args.has(QStringLiteral("norm-mode"))) {
        const auto named =
            feetech::TeleopMapping::normModeFromKey(m_args.value(QStringLiteral("norm-mode")));
        if (!named)
            throw UsageError {ServoctlTr::tr("--norm-mode must be degrees (LeRobot's use_degrees, "
                                             "the default) or range_m100_100")};
        normMode = *named;
    }
    const std::optional<double> duration = durationOption(m_args);
    const bool release = m_args.flag(QStringLiteral("release"));
    // --record FILE: the follower's goals, as `feetech replay` plays them back on it.
    const QString recordPath = m_args.value(QStringLiteral("record"));
    if (!recordPath.isEmpty())
        checkFolder(recordPath);

    util::FileError error;
    const QString followerFile = m_args.value(QStringLiteral("calibration"));
    const QString leaderFile = m_args.value(QStringLiteral("leader-calibration"));
    const auto followerMotors = feetech::loadLeRobotCalibration(followerFile, &error);
    if (!followerMotors)
        throw UsageError {error.describe()};
    const auto leaderMotors = feetech::loadLeRobotCalibration(leaderFile, &error);
    if (!leaderMotors)
        throw UsageError {error.describe()};
    QStringList missing;
    const auto mapping =
        feetech::TeleopMapping::match(*followerMotors, *leaderMotors, &missing, normMode);
    if (!mapping)
        throw UsageError {ServoctlTr::tr("the two files name different joints: %1")
                              .arg(missing.join(QStringLiteral(", ")))};
    QVector<LeRobotMotor> followerJoints;
    QVector<LeRobotMotor> leaderJoints;
    for (const feetech::TeleopJoint &joint : mapping->joints()) {
        followerJoints.append(joint.follower);
        leaderJoints.append(joint.leader);
    }

    FeetechDevice follower(m_args, m_output);
    FeetechDevice leader(leaderPort, m_args, m_output);
    if (!follower.open(busBaud()))
        return fail(follower.error());
    if (!leader.open(busBaud()))
        return fail(leader.error());
    int refused = ExitOk;
    const auto followerServos = identifyArm(follower, followerJoints, followerFile, &refused);
    if (!followerServos)
        return refused;
    const auto leaderServos = identifyArm(leader, leaderJoints, leaderFile, &refused);
    if (!leaderServos)
        return refused;

    // Safe start: the follower holds where it stands (its first goal), then its torque goes on.
    const auto standing = presentPositions(follower, *followerServos);
    if (!standing)
        return fail(follower.error());
    const feetech::RegisterTable &table = followerServos->first().table();
    const qint32 torqueOn = table.torqueValue(feetech::TorqueMode::On).value_or(1);
    if (!writeAll(follower, *followerServos, feetech::registerkeys::kGoalPosition, *standing)
        || !writeAll(follower, *followerServos, feetech::registerkeys::kTorqueEnable,
                     QVector<qint32>(followerServos->size(), torqueOn)))
        return fail(follower.error().isEmpty()
                        ? ServoctlTr::tr("the follower's torque could not be "
                                         "switched on")
                        : follower.error());
    m_output.err << ServoctlTr::tr("servoctl: the follower holds; it moves to the leader's pose at "
                                   "%1°/s at most, then follows. Ctrl-C stops (it holds).")
                        .arg(maxSpeed)
                 << '\n'
                 << (normMode == feetech::TeleopMapping::NormMode::Degrees
                         ? ServoctlTr::tr("servoctl: joints map in degrees from the middle of "
                                          "their ranges (LeRobot's use_degrees, norm mode "
                                          "degrees)")
                         : ServoctlTr::tr("servoctl: joints map range onto range (LeRobot's norm "
                                          "mode range_m100_100)"))
                 << '\n';
    m_output.err.flush();

    // The loop: the leader's stream gives each cycle's positions, the follower gets one SYNC
    // WRITE of the goals (the newest waits while one is on the wire), each step limited.
    feetech::TeleopLoop teleop(*mapping, *followerServos, *leaderServos, *standing, maxSpeed);
    QEventLoop loop;
    bool linkLost = false;
    QString lostMessage;
    QObject::connect(&follower.session(), &feetech::Session::operationFinished, &loop,
                     [&](const feetech::OperationResult &result) {
                         if (result.operation != feetech::Operation::SyncWrite)
                             return;
                         if (const auto next = teleop.takeWriteFinished())
                             follower.session().submit(*next);
                     });
    QObject::connect(&leader.session(), &feetech::Session::telemetry, &loop,
                     [&](const QVector<feetech::FeedbackSample> &samples) {
                         if (const auto write = teleop.takeLeaderCycle(samples))
                             follower.session().submit(*write);
                     });
    for (FeetechDevice *device : {&follower, &leader}) {
        QObject::connect(&device->session(), &feetech::Session::statusChanged, &loop,
                         [&, device](const seriallink::ConnectionStatus &status) {
                             if (status.state == seriallink::ConnectionState::Connected)
                                 return;
                             linkLost = true;
                             lostMessage =
                                 ServoctlTr::tr("%1 was lost: %2")
                                     .arg(device == &follower ? ServoctlTr::tr("the follower")
                                                              : ServoctlTr::tr("the leader"),
                                          status.message);
                             loop.quit();
                         });
    }
    feetech::TelemetryOptions stream;
    stream.servos = *leaderServos;
    stream.rateHz = rate;
    stream.publishEachCycle = true;
    QElapsedTimer running;
    running.start();
    QTimer::singleShot(0, &loop, [&leader, stream] { leader.session().startTelemetry(stream); });
    streamWithoutWaiting(m_output);
    runUntilInterrupted(loop, duration);
    sayDroppedLines(m_output);
    const double seconds = running.nsecsElapsed() / 1e9;
    leader.session().stopTelemetry();
    teleop.stop();
    QElapsedTimer draining;
    draining.start();
    while (teleop.isWriting() && draining.elapsed() < 1000
           && follower.session().status().state == seriallink::ConnectionState::Connected)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);

    // Stop: the follower holds where it is (or goes limp with --release), if it can be reached.
    bool stopped = false;
    if (follower.session().status().state == seriallink::ConnectionState::Connected) {
        if (release) {
            stopped = writeAll(follower, *followerServos, feetech::registerkeys::kTorqueEnable,
                               QVector<qint32>(followerServos->size(), 0));
        } else if (const auto here = presentPositions(follower, *followerServos)) {
            stopped =
                writeAll(follower, *followerServos, feetech::registerkeys::kGoalPosition, *here);
        }
    }
    util::FileError recordError;
    const bool recorded = !recordPath.isEmpty()
        && feetech::saveMotionRecording(recordPath, teleop.recording(), &recordError);
    if (recordError)
        m_output.err << "servoctl: " << recordError.describe() << '\n';
    else if (recorded)
        m_output.err << ServoctlTr::tr(
                            "servoctl: %n frame(s) of the follower's goals recorded in %1", nullptr,
                            int(teleop.recording().frames.size()))
                            .arg(QDir::toNativeSeparators(recordPath))
                     << '\n';
    const qint64 writes = teleop.cycles();
    const double medianMs = teleop.medianLatencyMs();
    if (m_output.json)
        printJson(m_output.out,
                  QJsonObject {
                      {QStringLiteral("cycles"), writes},
                      {QStringLiteral("norm_mode"), feetech::TeleopMapping::normModeKey(normMode)},
                      {QStringLiteral("rate_hz"), writes / std::max(seconds, 1e-3)},
                      {QStringLiteral("median_latency_ms"), medianMs},
                      {QStringLiteral("released"), release && stopped},
                      {QStringLiteral("held"), !release && stopped},
                      {QStringLiteral("lost"), linkLost}});
    m_output.err << ServoctlTr::tr(
                        "servoctl: %1 cycle(s) in %2 s (%3 per second), leader to follower "
                        "%4 ms (median)")
                        .arg(writes)
                        .arg(seconds, 0, 'f', 1)
                        .arg(writes / std::max(seconds, 1e-3), 0, 'f', 1)
                        .arg(medianMs, 0, 'f', 1)
                 << '\n';
    m_output.err << (stopped
                         ? (release ? ServoctlTr::tr("servoctl: the follower's torque is off")
                                    : ServoctlTr::tr("servoctl: the follower holds where it is"))
                         : ServoctlTr::tr("servoctl: the follower could not be reached to stop it"))
                 << '\n';
    m_output.err.flush();
    if (linkLost)
        return fail(lostMessage);
    return stopped ? ExitOk : ExitDeviceFailure;
}

} // namespace cli
