// servoctl feetech calibrate and calibration save/load: an arm's joints recorded by hand, and
// LeRobot calibration files read from and written to the servos.
#include "feetechcalibration.h"
#include "feetechcommand.h"

#include "armcalibration.h"
#include "lerobotcalibration.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QSocketNotifier>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <cstring>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

namespace {

// The servoctl translation context, as in every servoctl file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servoctl)
};

} // namespace

namespace cli {

namespace {

// How often the live table is redrawn on a terminal.
constexpr int kLiveRefreshMs = 100;

bool isTerminal(FILE *stream)
{
#ifdef Q_OS_UNIX
    return isatty(fileno(stream)) != 0;
#else
    Q_UNUSED(stream);
    return false;
#endif
}

} // namespace

std::optional<QHash<QString, qint32>> readCalibrationRegisters(FeetechDevice &device,
                                                               const ServoInfo &servo)
{
    QVector<feetech::Block> blocks;
    for (const QString &key :
         {QString::fromUtf16(feetech::kOffsetKey), QString::fromUtf16(feetech::kMinimumLimitKey),
          QString::fromUtf16(feetech::kMaximumLimitKey), QStringLiteral("torque_enable")}) {
        if (const feetech::Register *reg = servo.table().find(key))
            blocks.append({reg->address, reg->size});
    }
    const auto memory = device.read(servo, blocks);
    if (!memory)
        return std::nullopt;
    return valuesByKey(decodeMemory(servo.table(), *memory));
}

// --ids LIST: the joints, each once.
QVector<quint8> FeetechCommand::jointIds(const QString &what) const
{
    if (!m_args.has(QStringLiteral("ids")))
        throw UsageError {Tr::tr("%1 needs --ids LIST (such as 1-6)").arg(what)};
    const QVector<quint8> ids = idList(m_args.value(QStringLiteral("ids")), feetech::kMaxServoId);
    if (ids.isEmpty())
        throw UsageError {Tr::tr("--ids names no servo")};
    for (int i = 0; i < ids.size(); ++i) {
        if (ids.indexOf(ids.at(i)) != i)
            throw UsageError {Tr::tr("--ids names servo %1 twice").arg(ids.at(i))};
    }
    return ids;
}

// --names LIST: one name a joint, in the order of --ids; id_N when not given.
QStringList FeetechCommand::jointNames(const QVector<quint8> &ids) const
{
    QStringList names;
    if (!m_args.has(QStringLiteral("names"))) {
        for (const quint8 id : ids)
            names.append(QStringLiteral("id_%1").arg(id));
        return names;
    }
    names = m_args.value(QStringLiteral("names")).split(u',');
    if (names.size() != ids.size())
        throw UsageError {Tr::tr("--names gives %1 name(s) for %2 servo(s) in --ids")
                              .arg(names.size())
                              .arg(ids.size())};
    for (int i = 0; i < names.size(); ++i) {
        names[i] = names.at(i).trimmed();
        if (!feetech::isLeRobotMotorName(names.at(i)))
            throw UsageError {Tr::tr("--names: \"%1\" is not a joint name (letters, digits and "
                                     "_, a letter first)")
                                  .arg(names.at(i))};
        if (names.indexOf(names.at(i)) != i)
            throw UsageError {Tr::tr("--names: \"%1\" is given twice").arg(names.at(i))};
    }
    return names;
}

// Opens the port and identifies the servo of every joint; nothing, once the failure is printed,
// when the port cannot be opened, or a servo cannot be reached or has no position offset.
std::optional<QVector<ServoInfo>> FeetechCommand::identifyJoints(FeetechDevice &device,
                                                                 const QVector<quint8> &ids)
{
    if (!device.open(busBaud())) {
        fail(device.error());
        return std::nullopt;
    }
    QVector<ServoInfo> servos;
    for (const quint8 id : ids) {
        const auto servo = device.identify(id, busBaud());
        if (!servo) {
            fail(device.error());
            return std::nullopt;
        }
        if (!servo->hasTable() || !feetech::calibrationLimits(servo->table())) {
            fail(Tr::tr("servo %1 (%2) has no position offset on a 4096-step encoder: it "
                        "cannot be calibrated; nothing was written")
                     .arg(id)
                     .arg(servo->model.name));
            return std::nullopt;
        }
        servos.append(*servo);
    }
    return servos;
}

int FeetechCommand::calibrate(const QString &what, const QStringList &operands)
{
    allowOptions(what,
                 {QStringLiteral("ids"), QStringLiteral("names"), QStringLiteral("full-turn"),
                  QStringLiteral("duration"), QStringLiteral("out"), QStringLiteral("dry-run")});
    expectOperands(what, operands, 0, {});
    const QVector<quint8> ids = jointIds(what);
    const QStringList names = jointNames(ids);
    QVector<quint8> fullTurn;
    if (m_args.has(QStringLiteral("full-turn"))) {
        try {
            fullTurn = idList(m_args.value(QStringLiteral("full-turn")), feetech::kMaxServoId);
        } catch (UsageError &error) {
            error.message.replace(QStringLiteral("--ids"), QStringLiteral("--full-turn"));
            throw;
        }
        for (const quint8 id : std::as_const(fullTurn)) {
            if (!ids.contains(id))
                throw UsageError {Tr::tr("--full-turn: servo %1 is not in --ids").arg(id)};
        }
    }
    const std::optional<double> duration = durationOption(m_args);
    if (!m_args.has(QStringLiteral("out")))
        throw UsageError {
            Tr::tr("%1 needs --out FILE: the LeRobot calibration file to save").arg(what)};
    const QString out = m_args.value(QStringLiteral("out"));
    checkFolder(out);
    if (!duration && !isTerminal(stdin))
        throw UsageError {Tr::tr("%1 needs --duration S when standard input is not a terminal "
                                 "(Enter on a terminal ends the recording otherwise)")
                              .arg(what)};
    const bool dryRun = m_args.flag(QStringLiteral("dry-run"));

    FeetechDevice device(m_args, m_output);
    const auto servos = identifyJoints(device, ids);
    if (!servos)
        return ExitDeviceFailure;
    QVector<feetech::JointRecording> joints;
    for (int i = 0; i < servos->size(); ++i) {
        const ServoInfo &servo = servos->at(i);
        const auto current = readCalibrationRegisters(device, servo);
        if (!current)
            return fail(device.error());
        feetech::JointRecording joint;
        joint.name = names.at(i);
        joint.id = servo.id;
        joint.fullTurn = fullTurn.contains(servo.id);
        joint.currentOffset = current->value(QString::fromUtf16(feetech::kOffsetKey));
        joint.limits = *feetech::calibrationLimits(servo.table());
        joints.append(joint);
    }
    // Torque off (never a move): the joints are turned by hand.
    for (const ServoInfo &servo : std::as_const(*servos)) {
        const Programmed off = writeVerified(device, servo, {{QStringLiteral("torque_enable"), 0}});
        if (!isVerified(off))
            return fail(Tr::tr("servo %1: torque could not be switched off: %2")
                            .arg(servo.id)
                            .arg(problemText(off)));
    }
    if (!recordJoints(device, *servos, joints, duration))
        return ExitDeviceFailure;

    QVector<feetech::LeRobotMotor> saved;
    QJsonArray reports;
    bool allDone = true;
    for (int i = 0; i < joints.size(); ++i) {
        const feetech::JointRecording &joint = joints.at(i);
        const feetech::JointCalibration result =
            feetech::calibrateJoint(joint, feetech::CalibrationOrder::RangeFirst);
        QJsonObject report {{QStringLiteral("name"), joint.name},
                            {QStringLiteral("id"), joint.id},
                            {QStringLiteral("full_turn"), joint.fullTurn},
                            {QStringLiteral("recorded"),
                             QJsonObject {{QStringLiteral("min"), joint.range.minimum()},
                                          {QStringLiteral("max"), joint.range.maximum()},
                                          {QStringLiteral("present"), joint.range.present()}}},
                            {QStringLiteral("ok"), result.ok()}};
        if (!result.ok()) {
            allDone = false;
            report.insert(QStringLiteral("refusal"), result.refusal);
            reports.append(report);
            if (!m_output.json)
                m_output.out << Tr::tr("%1 (servo %2): refused, nothing written: %3")
                                    .arg(joint.name)
                                    .arg(joint.id)
                                    .arg(result.refusal)
                             << '\n';
            continue;
        }
        report.insert(QStringLiteral("offset"), result.offset);
        report.insert(QStringLiteral("min_limit"), result.minimumLimit);
        report.insert(QStringLiteral("max_limit"), result.maximumLimit);
        Programmed outcome;
        if (!dryRun)
            outcome = writeVerified(device, servos->at(i),
                                    feetech::calibrationWrites(result.offset, result.minimumLimit,
                                                               result.maximumLimit));
        const QJsonObject written = writeJson(outcome, !dryRun);
        for (auto it = written.begin(); it != written.end(); ++it)
            report.insert(it.key(), it.value());
        reports.append(report);
        if (!m_output.json) {
            m_output.out << Tr::tr("%1 (servo %2): offset %3, limits %4 to %5")
                                .arg(joint.name)
                                .arg(joint.id)
                                .arg(result.offset)
                                .arg(result.minimumLimit)
                                .arg(result.maximumLimit);
            if (dryRun)
                m_output.out << Tr::tr(" (not written: --dry-run)");
            else if (isVerified(outcome))
                m_output.out << Tr::tr(", written and verified");
            else
                m_output.out << Tr::tr(", NOT verified: %1").arg(problemText(outcome));
            m_output.out << '\n';
        }
        if (!dryRun && !isVerified(outcome)) {
            allDone = false;
            continue;
        }
        saved.append(
            {joint.name, joint.id, 0, result.offset, result.minimumLimit, result.maximumLimit});
    }
    m_output.out.flush();
    QString error;
    const bool fileSaved = !saved.isEmpty() && feetech::saveLeRobotCalibration(saved, out, &error);
    if (m_output.json) {
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("dry_run"), dryRun},
                               {QStringLiteral("file"), fileSaved ? QJsonValue(out) : QJsonValue()},
                               {QStringLiteral("joints"), reports}});
    } else if (fileSaved) {
        m_output.out << Tr::tr("saved %n joint(s) to %1", nullptr, int(saved.size()))
                            .arg(QDir::toNativeSeparators(out))
                     << '\n';
        m_output.out.flush();
    }
    if (!error.isEmpty())
        return fail(error);
    if (saved.isEmpty())
        return fail(Tr::tr("no joint could be calibrated; %1 was not written")
                        .arg(QDir::toNativeSeparators(out)));
    if (!allDone)
        return fail(Tr::tr("not every joint was calibrated: see the refusals above"));
    return ExitOk;
}

// Streams the joints' positions into their recorders until --duration has passed, or Enter on
// the terminal. A servo that misses cycles is marked lost. False, once
// the failure is printed, when the link went down or the user interrupted.
bool FeetechCommand::recordJoints(FeetechDevice &device, const QVector<ServoInfo> &servos,
                                  QVector<feetech::JointRecording> &joints,
                                  std::optional<double> duration)
{
    feetech::Session &session = device.session();
    feetech::TelemetryOptions options;
    options.servos = servos;
    options.rateHz = feetech::kRecordingRateHz;
    options.missesBeforeMissing = feetech::kRecordingMissesBeforeLost;
    options.logEveryFrame = m_args.flag(QStringLiteral("trace"));
    const auto jointOf = [&joints](quint8 id) -> feetech::JointRecording * {
        for (feetech::JointRecording &joint : joints) {
            if (joint.id == id)
                return &joint;
        }
        return nullptr;
    };
    QEventLoop loop;
    QObject::connect(&session, &feetech::Session::telemetry, &loop,
                     [&](const QVector<feetech::FeedbackSample> &samples) {
                         for (const feetech::FeedbackSample &sample : samples) {
                             const auto position = sample.value(feetech::Quantity::Position);
                             feetech::JointRecording *joint = jointOf(sample.id);
                             if (joint && position)
                                 joint->range.addSample(int(std::lround(*position)));
                         }
                     });
    QObject::connect(&session, &feetech::Session::telemetryStats, &loop,
                     [&](const feetech::TelemetryStats &stats) {
                         for (const feetech::ServoTelemetry &servo : stats.servos) {
                             feetech::JointRecording *joint = jointOf(servo.id);
                             if (joint && servo.missing)
                                 joint->range.markLost();
                         }
                     });
    QObject::connect(&session, &feetech::Session::statusChanged, &loop,
                     [&](const seriallink::ConnectionStatus &status) {
                         if (status.state != seriallink::ConnectionState::Connected)
                             loop.quit();
                     });
    const bool live = !m_output.json && isTerminal(stdout);
    if (!m_output.json) {
        m_output.err << (duration ? Tr::tr("servoctl: torque is off; move every joint through "
                                           "its whole range for %1 s")
                                        .arg(*duration)
                                  : Tr::tr("servoctl: torque is off; move every joint through "
                                           "its whole range, then press Enter"))
                     << '\n';
        m_output.err.flush();
    }
    QTimer redraw;
    bool drawn = false;
    QObject::connect(&redraw, &QTimer::timeout, &loop, [&] {
        if (drawn)
            m_output.out << QStringLiteral("\x1b[%1A").arg(joints.size() + 1);
        printRecording(joints, true);
        drawn = true;
    });
    if (live)
        redraw.start(kLiveRefreshMs);
    std::unique_ptr<QSocketNotifier> enter;
    if (!duration) {
        enter = std::make_unique<QSocketNotifier>(fileno(stdin), QSocketNotifier::Read);
        QObject::connect(enter.get(), &QSocketNotifier::activated, &loop, [&] {
            char line[256];
            if (!std::fgets(line, sizeof line, stdin) || std::strchr(line, '\n'))
                loop.quit();
        });
    }
    bool interrupted = false;
    QTimer::singleShot(0, &loop, [&session, options] { session.startTelemetry(options); });
    runUntilInterrupted(loop, duration, [&] {
        interrupted = true;
        loop.quit();
    });
    const bool linkLost = session.status().state != seriallink::ConnectionState::Connected;
    session.stopTelemetry();
    redraw.stop();
    if (drawn)
        m_output.out << QStringLiteral("\x1b[%1A").arg(joints.size() + 1);
    if (!m_output.json)
        printRecording(joints, live);
    if (linkLost) {
        fail(session.status().message);
        return false;
    }
    if (interrupted) {
        fail(Tr::tr("interrupted: nothing was written (torque stays off)"));
        return false;
    }
    return true;
}

// The recorded ranges, one row a joint; `live` clears what an earlier table left on the line.
void FeetechCommand::printRecording(const QVector<feetech::JointRecording> &joints, bool live)
{
    const QString endOfLine = live ? QStringLiteral("\x1b[K\n") : QStringLiteral("\n");
    m_output.out << QStringLiteral("%1  %2  %3  %4  %5")
                        .arg(Tr::tr("joint"), -16)
                        .arg(Tr::tr("id"), 3)
                        .arg(Tr::tr("min"), 6)
                        .arg(Tr::tr("present"), 7)
                        .arg(Tr::tr("max"), 6)
                 << endOfLine;
    for (const feetech::JointRecording &joint : joints) {
        const feetech::JointRangeRecorder &range = joint.range;
        const auto cell = [&range](int value, int width) {
            return range.hasSamples() ? QStringLiteral("%1").arg(value, width)
                                      : QStringLiteral("%1").arg(QStringLiteral("-"), width);
        };
        m_output.out << QStringLiteral("%1  %2  %3  %4  %5%6")
                            .arg(joint.name, -16)
                            .arg(joint.id, 3)
                            .arg(cell(range.minimum(), 6), cell(range.present(), 7),
                                 cell(range.maximum(), 6),
                                 range.isLost() ? Tr::tr("  (stopped answering)") : QString())
                     << endOfLine;
    }
    m_output.out.flush();
}

} // namespace cli
