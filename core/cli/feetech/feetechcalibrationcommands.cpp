// servoctl feetech calibrate and calibration save/load: an arm's joints recorded by hand, and
// LeRobot calibration files read from and written to the servos.
#include "feetechcalibrationcommands.h"

#include "armcalibration.h"
#include "lerobotcalibration.h"
#include "servoctltr.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QSocketNotifier>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

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

// Register values by key: the position offset, the angle limits and torque enable of `servo`.
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

// What FeetechCommandGroup::writeVerified came to, for the calibration commands' reports.
template<typename Programmed>
bool isVerified(const Programmed &outcome)
{
    return outcome.failure.isEmpty() && outcome.mismatches.isEmpty();
}
template<typename Programmed>
QString problemText(const Programmed &outcome)
{
    return outcome.failure.isEmpty() ? outcome.described.join(QStringLiteral("; "))
                                     : outcome.failure;
}
// written, verified, mismatches (and error); both false when the write was not attempted.
template<typename Programmed>
QJsonObject writeJson(const Programmed &outcome, bool attempted)
{
    QJsonObject object {{QStringLiteral("written"), attempted && outcome.failure.isEmpty()},
                        {QStringLiteral("verified"), attempted && isVerified(outcome)},
                        {QStringLiteral("mismatches"), outcome.mismatches}};
    if (!outcome.failure.isEmpty())
        object.insert(QStringLiteral("error"), outcome.failure);
    return object;
}

} // namespace

// --names LIST: one name a joint, in the order of --ids; id_N when not given.
QStringList FeetechCalibrationCommands::jointNames(const QVector<quint8> &ids) const
{
    QStringList names;
    if (!m_args.has(QStringLiteral("names"))) {
        for (const quint8 id : ids)
            names.append(QStringLiteral("id_%1").arg(id));
        return names;
    }
    names = m_args.value(QStringLiteral("names")).split(u',');
    if (names.size() != ids.size())
        throw UsageError {ServoctlTr::tr("--names gives %1 name(s) for %2 servo(s) in --ids")
                              .arg(names.size())
                              .arg(ids.size())};
    for (int i = 0; i < names.size(); ++i) {
        names[i] = names.at(i).trimmed();
        if (!feetech::isLeRobotMotorName(names.at(i)))
            throw UsageError {
                ServoctlTr::tr("--names: \"%1\" is not a joint name (letters, digits and "
                               "_, a letter first)")
                    .arg(names.at(i))};
        if (names.indexOf(names.at(i)) != i)
            throw UsageError {ServoctlTr::tr("--names: \"%1\" is given twice").arg(names.at(i))};
    }
    return names;
}

// Opens the port and identifies the servo of every joint; nothing, once the failure is printed,
// when the port cannot be opened, or a servo cannot be reached or has no position offset.
std::optional<QVector<ServoInfo>>
FeetechCalibrationCommands::identifyJoints(FeetechDevice &device, const QVector<quint8> &ids)
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
            fail(ServoctlTr::tr("servo %1 (%2) has no position offset on a 4096-step encoder: it "
                                "cannot be calibrated; nothing was written")
                     .arg(id)
                     .arg(servo->model.name));
            return std::nullopt;
        }
        servos.append(*servo);
    }
    return servos;
}

int FeetechCalibrationCommands::calibrate(const QString &what, const QStringList &operands)
{
    allowOptions(what,
                 {QStringLiteral("ids"), QStringLiteral("names"), QStringLiteral("full-turn"),
                  QStringLiteral("duration"), QStringLiteral("out"), QStringLiteral("update"),
                  QStringLiteral("dry-run")});
    expectOperands(what, operands, 0, {});
    const QVector<quint8> ids = jointIds(what);
    // --update FILE: these joints calibrated anew (a motor replaced), the file's others kept.
    std::optional<QVector<feetech::LeRobotMotor>> updated;
    QStringList names;
    if (m_args.has(QStringLiteral("update"))) {
        if (m_args.has(QStringLiteral("out")) || m_args.has(QStringLiteral("names")))
            throw UsageError {
                ServoctlTr::tr("%1 --update FILE takes the joints' names from the file and "
                               "saves to it: no --out or --names")
                    .arg(what)};
        util::FileError error;
        updated = feetech::loadLeRobotCalibration(m_args.value(QStringLiteral("update")), &error);
        if (!updated)
            throw UsageError {error.describe()};
        for (const quint8 id : ids) {
            const feetech::LeRobotMotor *motor = feetech::leRobotMotorWithId(*updated, id);
            if (!motor)
                throw UsageError {
                    ServoctlTr::tr("servo %1 is no joint of %2")
                        .arg(id)
                        .arg(QDir::toNativeSeparators(m_args.value(QStringLiteral("update"))))};
            names.append(motor->name);
        }
    } else {
        names = jointNames(ids);
    }
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
                throw UsageError {ServoctlTr::tr("--full-turn: servo %1 is not in --ids").arg(id)};
        }
    }
    const std::optional<double> duration = durationOption(m_args);
    if (!m_args.has(QStringLiteral("out")) && !updated)
        throw UsageError {
            ServoctlTr::tr("%1 needs --out FILE: the LeRobot calibration file to save").arg(what)};
    const QString out = m_args.value(updated ? QStringLiteral("update") : QStringLiteral("out"));
    checkFolder(out);
    if (!duration && !isTerminal(stdin))
        throw UsageError {
            ServoctlTr::tr("%1 needs --duration S when standard input is not a terminal "
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
            return fail(ServoctlTr::tr("servo %1: torque could not be switched off: %2")
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
                m_output.out << ServoctlTr::tr("%1 (servo %2): refused, nothing written: %3")
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
            m_output.out << ServoctlTr::tr("%1 (servo %2): offset %3, limits %4 to %5")
                                .arg(joint.name)
                                .arg(joint.id)
                                .arg(result.offset)
                                .arg(result.minimumLimit)
                                .arg(result.maximumLimit);
            if (dryRun)
                m_output.out << ServoctlTr::tr(" (not written: --dry-run)");
            else if (isVerified(outcome))
                m_output.out << ServoctlTr::tr(", written and verified");
            else
                m_output.out << ServoctlTr::tr(", NOT verified: %1").arg(problemText(outcome));
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
    util::FileError error;
    const bool fileSaved = !saved.isEmpty()
        && feetech::saveLeRobotCalibration(
            updated ? feetech::updatedLeRobotCalibration(*updated, saved) : saved, out, &error);
    if (m_output.json) {
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("dry_run"), dryRun},
                               {QStringLiteral("file"), fileSaved ? QJsonValue(out) : QJsonValue()},
                               {QStringLiteral("joints"), reports}});
    } else if (fileSaved) {
        m_output.out << ServoctlTr::tr("saved %n joint(s) to %1", nullptr, int(saved.size()))
                            .arg(QDir::toNativeSeparators(out))
                     << '\n';
        m_output.out.flush();
    }
    if (error)
        return fail(error.describe());
    if (saved.isEmpty())
        return fail(ServoctlTr::tr("no joint could be calibrated; %1 was not written")
                        .arg(QDir::toNativeSeparators(out)));
    if (!allDone)
        return fail(ServoctlTr::tr("not every joint was calibrated: see the refusals above"));
    return ExitOk;
}

// Streams the joints' positions into their recorders until --duration has passed, or Enter on
// the terminal. A servo that misses cycles is marked lost. False, once
// the failure is printed, when the link went down or the user interrupted.
bool FeetechCalibrationCommands::recordJoints(FeetechDevice &device,
                                              const QVector<ServoInfo> &servos,
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
        m_output.err << (duration
                             ? ServoctlTr::tr("servoctl: torque is off; move every joint through "
                                              "its whole range for %1 s")
                                   .arg(*duration)
                             : ServoctlTr::tr("servoctl: torque is off; move every joint through "
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
        fail(ServoctlTr::tr("interrupted: nothing was written (torque stays off)"));
        return false;
    }
    return true;
}

// The recorded ranges, one row a joint; `live` clears what an earlier table left on the line.
void FeetechCalibrationCommands::printRecording(const QVector<feetech::JointRecording> &joints,
                                                bool live)
{
    const QString endOfLine = live ? QStringLiteral("\x1b[K\n") : QStringLiteral("\n");
    m_output.out << QStringLiteral("%1  %2  %3  %4  %5")
                        .arg(ServoctlTr::tr("joint"), -16)
                        .arg(ServoctlTr::tr("id"), 3)
                        .arg(ServoctlTr::tr("min"), 6)
                        .arg(ServoctlTr::tr("present"), 7)
                        .arg(ServoctlTr::tr("max"), 6)
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
                                 range.isLost() ? ServoctlTr::tr("  (stopped answering)")
                                                : QString())
                     << endOfLine;
    }
    m_output.out.flush();
}

int FeetechCalibrationCommands::calibration(const QString &what, const QStringList &operands)
{
    if (operands.isEmpty())
        throw UsageError {ServoctlTr::tr("%1 needs save or load").arg(what)};
    const QString sub = operands.first();
    const QString named = what + u' ' + sub;
    if (sub == u"save")
        return saveCalibration(named, operands.mid(1));
    if (sub == u"load")
        return loadCalibration(named, operands.mid(1));
    throw UsageError {ServoctlTr::tr("unknown %1 command \"%2\": use save or load").arg(what, sub)};
}

int FeetechCalibrationCommands::saveCalibration(const QString &what, const QStringList &operands)
{
    allowOptions(what, {QStringLiteral("ids"), QStringLiteral("names")});
    expectOperands(what, operands, 1, ServoctlTr::tr("one FILE"));
    const QVector<quint8> ids = jointIds(what);
    const QStringList names = jointNames(ids);
    const QString path = operands.first();
    checkFolder(path);

    FeetechDevice device(m_args, m_output);
    const auto servos = identifyJoints(device, ids);
    if (!servos)
        return ExitDeviceFailure;
    QVector<feetech::LeRobotMotor> motors;
    for (int i = 0; i < servos->size(); ++i) {
        const ServoInfo &servo = servos->at(i);
        const auto values = readCalibrationRegisters(device, servo);
        if (!values)
            return fail(device.error());
        const feetech::LeRobotMotor motor {
            names.at(i),
            servo.id,
            0,
            values->value(QString::fromUtf16(feetech::kOffsetKey)),
            values->value(QString::fromUtf16(feetech::kMinimumLimitKey)),
            values->value(QString::fromUtf16(feetech::kMaximumLimitKey))};
        // A file LeRobot (and load) could not use is not written.
        if (motor.rangeMin >= motor.rangeMax)
            return fail(
                ServoctlTr::tr("servo %1 holds the limits %2 to %3, which are no calibrated range "
                               "(min = max = 0 is multi-turn mode); %4 was not written")
                    .arg(servo.id)
                    .arg(motor.rangeMin)
                    .arg(motor.rangeMax)
                    .arg(QDir::toNativeSeparators(path)));
        motors.append(motor);
    }
    feetech::keepDriveModes(motors, path);
    util::FileError error;
    if (!feetech::saveLeRobotCalibration(motors, path, &error))
        return fail(error.describe());
    QJsonObject joints;
    for (const feetech::LeRobotMotor &motor : std::as_const(motors))
        joints.insert(motor.name,
                      QJsonObject {{QStringLiteral("id"), motor.id},
                                   {QStringLiteral("drive_mode"), motor.driveMode},
                                   {QStringLiteral("homing_offset"), motor.homingOffset},
                                   {QStringLiteral("range_min"), motor.rangeMin},
                                   {QStringLiteral("range_max"), motor.rangeMax}});
    if (m_output.json)
        printJson(m_output.out,
                  QJsonObject {{QStringLiteral("file"), path}, {QStringLiteral("joints"), joints}});
    else
        m_output.out << ServoctlTr::tr("saved the calibration of %n servo(s) to %1", nullptr,
                                       int(motors.size()))
                            .arg(QDir::toNativeSeparators(path))
                     << '\n';
    m_output.out.flush();
    return ExitOk;
}

int FeetechCalibrationCommands::loadCalibration(const QString &what, const QStringList &operands)
{
    allowOptions(what, {});
    expectOperands(what, operands, 1, ServoctlTr::tr("one FILE"));
    const QString path = operands.first();
    util::FileError error;
    const auto motors = feetech::loadLeRobotCalibration(path, &error);
    if (!motors)
        throw UsageError {error.describe()};

    FeetechDevice device(m_args, m_output);
    QVector<quint8> ids;
    for (const feetech::LeRobotMotor &motor : *motors)
        ids.append(quint8(motor.id));
    const auto servos = identifyJoints(device, ids);
    if (!servos)
        return ExitDeviceFailure;
    bool allDone = true;
    QJsonArray reports;
    for (int i = 0; i < motors->size(); ++i) {
        const feetech::LeRobotMotor &motor = motors->at(i);
        const ServoInfo &servo = servos->at(i);
        const auto current = readCalibrationRegisters(device, servo);
        if (!current)
            return fail(device.error());
        const QVector<model::WriteItem> wanted =
            feetech::calibrationWrites(motor.homingOffset, motor.rangeMin, motor.rangeMax);
        QVector<model::WriteItem> changes;
        QJsonArray changesJson;
        QStringList described;
        for (const model::WriteItem &item : wanted) {
            const qint32 now = current->value(item.key);
            // A servo LeRobot gave the limit 4096 holds what the file says.
            const bool asInFile =
                item.key == QString::fromUtf16(feetech::kMaximumLimitKey) && now == motor.rangeMax;
            if (now == item.value || asInFile)
                continue;
            changes.append(item);
            changesJson.append(QJsonObject {{QStringLiteral("key"), item.key},
                                            {QStringLiteral("from"), now},
                                            {QStringLiteral("to"), qint64(item.value)}});
            described.append(QStringLiteral("%1 %2 → %3").arg(item.key).arg(now).arg(item.value));
        }
        QJsonObject report {{QStringLiteral("name"), motor.name},
                            {QStringLiteral("id"), motor.id},
                            {QStringLiteral("drive_mode"), motor.driveMode},
                            {QStringLiteral("changes"), changesJson}};
        const QString joint = ServoctlTr::tr("%1 (servo %2)").arg(motor.name).arg(motor.id);
        if (motor.driveMode != 0) {
            const QString kept =
                ServoctlTr::tr("drive_mode %1 is LeRobot's software setting (the "
                               "direction inverted), held by no register: it is kept "
                               "in the file only")
                    .arg(motor.driveMode);
            report.insert(QStringLiteral("drive_mode_note"), kept);
            if (!m_output.json)
                m_output.out << ServoctlTr::tr("%1: note: %2").arg(joint, kept) << '\n';
        }
        // A new offset under torque would move the horn to the old goal in new coordinates.
        const bool torqueOn = current->value(QStringLiteral("torque_enable")) != 0;
        QString line;
        if (changes.isEmpty()) {
            report.insert(QStringLiteral("verified"), true);
            line = ServoctlTr::tr("%1: already holds the file's values").arg(joint);
        } else if (sharesItsId(device, servo)) {
            return ExitDeviceFailure;
        } else if (torqueOn) {
            allDone = false;
            const QString refusal =
                ServoctlTr::tr("torque is on: the new offset would move the horn; "
                               "switch torque off (support the arm) and load again");
            report.insert(QStringLiteral("refusal"), refusal);
            line = ServoctlTr::tr("%1: %2; refused, nothing written: %3")
                       .arg(joint, described.join(QStringLiteral(", ")), refusal);
        } else {
            const Programmed outcome = writeVerified(device, servo, changes);
            const QJsonObject written = writeJson(outcome, true);
            for (auto it = written.begin(); it != written.end(); ++it)
                report.insert(it.key(), it.value());
            allDone = allDone && isVerified(outcome);
            line = isVerified(outcome)
                ? ServoctlTr::tr("%1: %2; written and verified")
                      .arg(joint, described.join(QStringLiteral(", ")))
                : ServoctlTr::tr("%1: %2; NOT verified: %3")
                      .arg(joint, described.join(QStringLiteral(", ")), problemText(outcome));
        }
        reports.append(report);
        if (!m_output.json)
            m_output.out << line << '\n';
    }
    if (m_output.json)
        printJson(
            m_output.out,
            QJsonObject {{QStringLiteral("file"), path}, {QStringLiteral("joints"), reports}});
    m_output.out.flush();
    if (!allDone)
        return fail(ServoctlTr::tr("the calibration of %1 was not loaded whole: see above")
                        .arg(QDir::toNativeSeparators(path)));
    return ExitOk;
}

} // namespace cli
