// servoctl feetech record and replay: a motion moved by hand into CSV, and back onto the servos.
#include "feetechmotioncommands.h"

#include "lerobotcalibration.h"
#include "motionrecorder.h"
#include "motionreplay.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QTimer>

#include <cmath>

namespace cli {

namespace {

constexpr double kDefaultRecordRate = 50.0;
constexpr double kMaximumRecordRate = 200.0;
constexpr int kMaximumLoops = 1000000;

} // namespace

// --names LIST: one joint name per --ids servo; without it, joints are known by ID.
QVector<feetech::MotionJoint>
FeetechMotionCommands::recordedJoints(const QVector<quint8> &ids) const
{
    QVector<feetech::MotionJoint> joints;
    for (const quint8 id : ids)
        joints.append({QString(), id});
    if (!m_args.has(QStringLiteral("names")))
        return joints;
    const QStringList names = m_args.value(QStringLiteral("names")).split(u',');
    if (names.size() != ids.size())
        throw UsageError {ServoctlTr::tr("--names gives %1 name(s) for %2 servo(s) in --ids")
                              .arg(names.size())
                              .arg(ids.size())};
    for (int i = 0; i < names.size(); ++i) {
        const QString name = names.at(i).trimmed();
        if (!feetech::isLeRobotMotorName(name))
            throw UsageError {
                ServoctlTr::tr("--names: \"%1\" is not a joint name (letters, digits and "
                               "_, a letter first)")
                    .arg(name)};
        if (names.indexOf(names.at(i)) != i)
            throw UsageError {ServoctlTr::tr("--names: \"%1\" is given twice").arg(name)};
        joints[i].name = name;
    }
    return joints;
}

// A number option (`fallback` when absent) that `accepts`; a usage error naming `range`
// otherwise.
double FeetechMotionCommands::numberOption(const QString &name, double fallback,
                                           const std::function<bool(double)> &accepts,
                                           const QString &range) const
{
    if (!m_args.has(name))
        return fallback;
    bool ok = false;
    const double value = m_args.value(name).toDouble(&ok);
    if (!ok || !std::isfinite(value) || !accepts(value))
        throw UsageError {ServoctlTr::tr("--%1 must be %2").arg(name, range)};
    return value;
}

// Records the positions of --ids (torque left as it is) until --duration, Ctrl-C or SIGTERM;
// the file is written whole at the end, whichever ended it.
int FeetechMotionCommands::record(const QString &what, const QStringList &operands)
{
    allowOptions(what,
                 {QStringLiteral("ids"), QStringLiteral("out"), QStringLiteral("duration"),
                  QStringLiteral("rate"), QStringLiteral("names")});
    expectOperands(what, operands, 0, {});
    const QVector<quint8> ids = jointIds(what);
    const QVector<feetech::MotionJoint> joints = recordedJoints(ids);
    if (!m_args.has(QStringLiteral("out")))
        throw UsageError {
            ServoctlTr::tr("%1 needs --out FILE: the CSV file to record into").arg(what)};
    const QString out = m_args.value(QStringLiteral("out"));
    checkFolder(out);
    const std::optional<double> duration = durationOption(m_args);
    const double rate = numberOption(
        QStringLiteral("rate"), kDefaultRecordRate,
        [](double value) { return value >= 1.0 && value <= kMaximumRecordRate; },
        ServoctlTr::tr("a number of frames per second from 1 to %1").arg(kMaximumRecordRate));
    const qint32 baud = busBaud();

    FeetechDevice device(m_args, m_output);
    if (!device.open(baud))
        return fail(device.error());
    feetech::TelemetryOptions options;
    options.rateHz = rate;
    options.logEveryFrame = m_args.flag(QStringLiteral("trace"));
    for (const quint8 id : ids) {
        const auto servo = device.identify(id, baud);
        if (!servo)
            return fail(device.error());
        if (!servo->hasTable())
            return fail(
                ServoctlTr::tr("servo %1 is of an unknown model (%2): its position cannot be "
                               "read")
                    .arg(id)
                    .arg(servo->modelNumber()));
        options.servos.append(*servo);
    }

    feetech::Session &session = device.session();
    feetech::MotionRecorder recorder;
    recorder.start(joints, baud);
    QEventLoop loop;
    QObject::connect(&session, &feetech::Session::telemetry, &loop,
                     [&recorder](const QVector<feetech::FeedbackSample> &samples) {
                         recorder.addSamples(samples);
                     });
    QObject::connect(&session, &feetech::Session::statusChanged, &loop,
                     [&loop](const seriallink::ConnectionStatus &status) {
                         if (status.state != seriallink::ConnectionState::Connected)
                             loop.quit(); // unplugged: nothing more will come
                     });
    m_output.err << "servoctl: "
                 << ServoctlTr::tr("recording %n joint(s); move them by hand, Ctrl-C ends", nullptr,
                                   int(ids.size()))
                 << '\n';
    m_output.err.flush();
    QTimer::singleShot(0, &loop, [&session, options] { session.startTelemetry(options); });
    streamWithoutWaiting(m_output);
    runUntilInterrupted(loop, duration);
    sayDroppedLines(m_output);
    const bool linkLost = session.status().state != seriallink::ConnectionState::Connected;
    session.stopTelemetry(); // flushes the last samples through the connection above

    const feetech::MotionRecording &recording = recorder.recording();
    if (recording.isEmpty())
        return fail(linkLost ? session.status().message
                             : ServoctlTr::tr("no frame was recorded: not every servo answered; "
                                              "nothing was written"));
    util::FileError error;
    if (!feetech::saveMotionRecording(out, recording, &error))
        return fail(error.describe());
    if (m_output.json) {
        QJsonArray columns;
        for (const feetech::MotionJoint &joint : recording.joints)
            columns.append(joint.column());
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("file"), out},
                               {QStringLiteral("joints"), columns},
                               {QStringLiteral("frames"), recording.frames.size()},
                               {QStringLiteral("duration_s"), recording.duration()},
                               {QStringLiteral("complete"), !linkLost}});
    } else {
        m_output.out << ServoctlTr::tr("recorded %n frame(s) of %1 joint(s) over %2 s into %3",
                                       nullptr, int(recording.frames.size()))
                            .arg(recording.joints.size())
                            .arg(recording.duration(), 0, 'f', 2)
                            .arg(QDir::toNativeSeparators(out))
                     << '\n';
        m_output.out.flush();
    }
    if (linkLost)
        return fail(ServoctlTr::tr("%1; what was recorded until then is in %2")
                        .arg(session.status().message, QDir::toNativeSeparators(out)));
    return ExitOk;
}

std::optional<QVector<ServoInfo>>
FeetechMotionCommands::replayedServos(FeetechDevice &device,
                                      const feetech::MotionRecording &recording, qint32 baud)
{
    QVector<ServoInfo> servos;
    for (const feetech::MotionJoint &joint : recording.joints) {
        const auto servo = device.identify(joint.id, baud);
        if (!servo) {
            if (device.session().status().state != seriallink::ConnectionState::Connected) {
                fail(device.error());
                return std::nullopt;
            }
            throw UsageError {ServoctlTr::tr("column %1 matches no servo: %2; nothing was moved")
                                  .arg(joint.column(), device.error())};
        }
        if (!servo->hasTable())
            throw UsageError {
                ServoctlTr::tr("column %1: servo %2 is of an unknown model (%3); nothing "
                               "was moved")
                    .arg(joint.column())
                    .arg(joint.id)
                    .arg(servo->modelNumber())};
        if (sharesItsId(device, *servo))
            return std::nullopt;
        servos.append(*servo);
    }
    return servos;
}

// Plays FILE on the servos its columns name: eased in, at the recorded times × --speed,
// --loop times, then held (or released). Ctrl-C and SIGTERM stop it with the arm held.
int FeetechMotionCommands::replay(const QString &what, const QStringList &operands)
{
    allowOptions(what,
                 {QStringLiteral("speed"), QStringLiteral("ease"), QStringLiteral("loop"),
                  QStringLiteral("release")});
    expectOperands(what, operands, 1, QStringLiteral("FILE"));
    feetech::ReplayPlan plan;
    plan.speed = numberOption(
        QStringLiteral("speed"), 1.0, [](double value) { return value > 0.0; },
        ServoctlTr::tr("a number above 0 (2 plays twice as fast)"));
    if (m_args.has(QStringLiteral("ease")))
        plan.easeSeconds = numberOption(
            QStringLiteral("ease"), 0.0, [](double value) { return value >= 0.0; },
            ServoctlTr::tr("a number of seconds from 0"));
    if (m_args.has(QStringLiteral("loop")))
        plan.loops = int(integerOption(m_args, QStringLiteral("loop"), 1, kMaximumLoops));
    plan.release = m_args.flag(QStringLiteral("release"));
    const QString path = operands.first();
    util::FileError error;
    const auto recording = feetech::loadMotionRecording(path, &error);
    if (!recording)
        throw UsageError {error.describe()};
    plan.times = recording->times;
    plan.frames = recording->frames;
    const qint32 baud = busBaud();

    FeetechDevice device(m_args, m_output);
    if (!device.open(baud))
        return fail(device.error());
    const auto servos = replayedServos(device, *recording, baud);
    if (!servos)
        return ExitDeviceFailure;
    plan.servos = *servos;

    feetech::Session &session = device.session();
    QEventLoop loop;
    std::optional<feetech::OperationResult> result;
    QObject::connect(&session, &feetech::Session::operationFinished, &loop,
                     [&](const feetech::OperationResult &finished) {
                         if (finished.operation != feetech::Operation::Replay)
                             return;
                         result = finished;
                         loop.quit();
                     });
    // A line on stderr as each loop (and its eased start) begins.
    std::optional<std::pair<int, bool>> stage;
    QObject::connect(&session, &feetech::Session::operationProgress, &loop,
                     [&](const feetech::OperationProgress &progress) {
                         const auto at = progress.detail.value<feetech::ReplayPosition>();
                         if (stage && *stage == std::make_pair(at.loop, at.easing))
                             return;
                         stage = std::make_pair(at.loop, at.easing);
                         m_output.err << "servoctl: " << progress.text << '\n';
                         m_output.err.flush();
                     });
    QTimer::singleShot(
        0, &loop, [&session, plan] { session.submit(feetech::operations::replayMotion(plan)); });
    bool interrupted = false;
    runUntilInterrupted(loop, std::nullopt, [&] {
        if (interrupted) {
            loop.quit(); // a second Ctrl-C stops waiting for the hold
            return;
        }
        interrupted = true;
        session.cancel(feetech::Operation::Replay);
    });
    if (!result)
        return fail(ServoctlTr::tr("interrupted again before the arm was held: check the servos' "
                                   "torque"));
    if (interrupted && result->failure == feetech::OperationFailure::Stopped)
        return fail(ServoctlTr::tr("interrupted: %1").arg(result->message));
    if (result->failure == feetech::OperationFailure::InvalidRequest) {
        m_output.err << "servoctl: " << result->message << '\n';
        m_output.err.flush();
        return ExitUsage;
    }
    if (!result->ok)
        return fail(result->message);
    if (m_output.json) {
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("file"), path},
                               {QStringLiteral("frames"), recording->frames.size()},
                               {QStringLiteral("duration_s"), recording->duration() / plan.speed},
                               {QStringLiteral("loops"), plan.loops},
                               {QStringLiteral("speed"), plan.speed},
                               {QStringLiteral("released"), plan.release},
                               {QStringLiteral("message"), result->message}});
    } else {
        m_output.out << result->message << '\n';
        m_output.out.flush();
    }
    return ExitOk;
}

} // namespace cli
