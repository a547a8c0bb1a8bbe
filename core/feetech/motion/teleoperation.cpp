// Teleoperation from the GUI thread: refusals, the checked and holding start, the loop, the stop.
#include "teleoperation.h"

#include "armcalibration.h"
#include "busclient.h"
#include "busoperations.h"
#include "registerkeys.h"
#include "robottemplate.h"
#include "servoparameters.h"

#include <QDir>
#include <QFileInfo>

namespace {

// Register values by key from what a read brought back.
QHash<QString, qint32> valuesByKey(const feetech::RegisterTable &table,
                                   const QMap<int, QByteArray> &memory)
{
    QHash<QString, qint32> values;
    for (auto it = memory.cbegin(); it != memory.cend(); ++it) {
        for (const feetech::DecodedRegister &item :
             feetech::decodeRegisters(table, it.key(), it.value()))
            values.insert(item.reg->key, item.value);
    }
    return values;
}

bool samePort(const QString &a, const QString &b)
{
    const QString canonicalA = QFileInfo(a).canonicalFilePath();
    return a == b || (!canonicalA.isEmpty() && canonicalA == QFileInfo(b).canonicalFilePath());
}

constexpr qint64 kRateWindowMs = 1000;

} // namespace

namespace feetech {

Teleoperation::Teleoperation(BusClient *follower, QObject *parent)
    : QObject(parent)
    , m_client(follower)
{
    m_clock.start();
}

// Destroyed while running (the window closes): the follower keeps its last goal and its torque,
// so it holds there; the leader's session ends with its thread.
Teleoperation::~Teleoperation() = default;

bool Teleoperation::start(const TeleopSettings &settings)
{
    if (m_state != State::Idle)
        return false; // the run goes on, and what it will say is its own
    m_problem = Problem::None;
    m_message.clear();
    m_settings = settings;
    if (!m_client || !m_client->link()->isConnected())
        return refuse(Problem::NoFollower,
                      tr("Connect to the follower arm's bus first: it is the bus the window has "
                         "open."));
    if (settings.leaderPort.isEmpty())
        return refuse(Problem::LeaderUnreachable, tr("Choose the leader arm's port."));
    if (samePort(settings.leaderPort, m_client->link()->status().portName))
        return refuse(Problem::SamePort,
                      tr("The leader's port is the follower's: the leader and the follower are "
                         "two arms on two adapters."));
    if (settings.followerCalibration.isEmpty())
        return refuse(Problem::UnreadableFile,
                      tr("Choose the follower's LeRobot calibration file: the one saved when "
                         "the follower arm was calibrated (Robot › Calibrate arm…)."));
    if (settings.leaderCalibration.isEmpty())
        return refuse(Problem::UnreadableFile,
                      tr("Choose the leader's LeRobot calibration file: the one saved when the "
                         "leader arm was calibrated."));
    util::FileError error;
    const auto followerMotors = loadLeRobotCalibration(settings.followerCalibration, &error);
    if (!followerMotors)
        return refuse(Problem::UnreadableFile, error.describe());
    const auto leaderMotors = loadLeRobotCalibration(settings.leaderCalibration, &error);
    if (!leaderMotors)
        return refuse(Problem::UnreadableFile, error.describe());
    QStringList missing;
    const auto mapping =
        TeleopMapping::match(*followerMotors, *leaderMotors, &missing, settings.normMode);
    if (!mapping)
        return refuse(
            Problem::DifferentJoints,
            tr("The two files name different joints: %1.").arg(missing.join(QStringLiteral(", "))));
    m_mapping = *mapping;

    m_followerServos.clear();
    const ServoList *servos = m_client->servos();
    for (const TeleopJoint &joint : m_mapping.joints()) {
        std::optional<ServoInfo> found;
        for (int i = 0; i < servos->count() && !found; ++i) {
            if (servos->at(i).info.id == joint.follower.id && servos->at(i).info.hasTable())
                found = servos->at(i).info;
        }
        if (!found)
            return refuse(Problem::NoFollower,
                          tr("The follower's joint %1 (servo %2) is not on the bus the window "
                             "has open: scan it, or choose the follower's file.")
                              .arg(joint.name)
                              .arg(joint.follower.id));
        m_followerServos.append(*found);
    }

    m_leaderServos.clear();
    m_loop.reset();
    m_torqueOn = false;
    m_leaderOpen = false;
    m_follower = std::make_unique<TeleopBus>(m_client.data());
    m_leader = std::make_unique<TeleopBus>(settings.leaderPort, kBaud);
    connect(m_leader->session(), &Session::statusChanged, this, &Teleoperation::onLeaderStatus);
    connect(m_client.data(), &BusClient::statusChanged, this, &Teleoperation::onFollowerStatus);
    connect(m_leader->session(), &Session::telemetry, this,
            [this](const QVector<FeedbackSample> &samples) { onLeaderCycle(samples); });
    setState(State::Starting);
    emit progress(tr("Opening the leader's port…"));
    m_leader->open();
    return true;
}

void Teleoperation::stop()
{
    switch (m_state) {
    case State::Idle:
    case State::Stopping:
        return;
    case State::Starting:
        m_message = tr("Stopped before the follower moved.");
        if (m_torqueOn) {
            setState(State::Stopping);
            holdAndEnd();
        } else {
            end(false);
        }
        return;
    case State::Running:
        windDown();
        return;
    }
}

void Teleoperation::windDown()
{
    setState(State::Stopping);
    m_leader->runInSession([](Session &session) { session.stopTelemetry(); });
    m_loop->stop();
    if (!m_loop->isWriting())
        holdAndEnd(); // else once the write on the wire has ended (sendGoals)
}

double Teleoperation::rateHz() const
{
    const qint64 now = m_clock.elapsed();
    const auto recent = std::count_if(m_writesEnded.begin(), m_writesEnded.end(),
                                      [now](qint64 at) { return now - at <= kRateWindowMs; });
    return recent * 1000.0 / kRateWindowMs;
}

void Teleoperation::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

bool Teleoperation::refuse(Problem problem, const QString &message)
{
    m_problem = problem;
    m_message = message;
    return false;
}

void Teleoperation::fail(Problem problem, const QString &message)
{
    m_problem = problem;
    m_message = message;
    if (m_state == State::Running) {
        windDown();
    } else if (m_torqueOn) {
        setState(State::Stopping);
        holdAndEnd();
    } else {
        end(false);
    }
}

void Teleoperation::onLeaderStatus(const seriallink::ConnectionStatus &status)
{
    if (m_state == State::Idle)
        return;
    if (status.state == seriallink::ConnectionState::Connected) {
        if (!m_leaderOpen && m_state == State::Starting) {
            m_leaderOpen = true;
            emit progress(tr("Checking the leader's joints…"));
            identifyLeader(0);
        }
        return;
    }
    if (status.state == seriallink::ConnectionState::Connecting)
        return;
    m_leader->forget();
    const QString lost = m_leaderOpen
        ? tr("The leader was lost: %1").arg(status.message)
        : tr("The leader's port could not be opened: %1").arg(status.message);
    if (m_state == State::Stopping)
        return; // the follower's hold is on its way and needs nothing of the leader
    fail(m_leaderOpen ? Problem::LinkLost : Problem::LeaderUnreachable, lost);
}

void Teleoperation::onFollowerStatus(const seriallink::ConnectionStatus &status)
{
    if (m_state == State::Idle || status.state == seriallink::ConnectionState::Connected)
        return;
    m_follower->forget();
    m_problem = Problem::LinkLost;
    m_message = tr("The follower was lost: %1. It could not be told to hold.").arg(status.message);
    end(false);
}

void Teleoperation::identifyLeader(int joint)
{
    if (m_state != State::Starting)
        return;
    if (joint == m_mapping.joints().size()) {
        emit progress(tr("Checking the follower's joints…"));
        checkFollower(0);
        return;
    }
    const LeRobotMotor &motor = m_mapping.joints().at(joint).leader;
    const quint8 id = quint8(motor.id);
    const auto unreachable = [this, motor](const QString &why) {
        fail(Problem::LeaderUnreachable,
             tr("The leader's joint %1 (servo %2) does not answer: %3")
                 .arg(motor.name)
                 .arg(motor.id)
                 .arg(why));
    };
    m_leader->run(
        operations::ping(id, kBaud), id, kBaud, [=](const OperationResult &pinged, const Memory &) {
            if (m_state != State::Starting)
                return;
            if (!pinged.ok) {
                unreachable(pinged.message);
                return;
            }
            ServoInfo unknown;
            unknown.id = id;
            unknown.baud = kBaud;
            m_leader->run(operations::read(unknown, {{0, kIdentitySize}}, ReadSource::Read), id,
                          kBaud, [=](const OperationResult &read, const Memory &memory) {
                              if (m_state != State::Starting)
                                  return;
                              const auto info = read.ok
                                  ? servoInfoFromIdentity(id, kBaud, memory.value(0))
                                  : std::nullopt;
                              if (!info || !info->hasTable()) {
                                  unreachable(read.ok ? tr("its model is unknown") : read.message);
                                  return;
                              }
                              m_leaderServos.append(*info);
                              checkCalibration(m_leader.get(), *info, motor,
                                               m_settings.leaderCalibration,
                                               [this, joint] { identifyLeader(joint + 1); });
                          });
        });
}

void Teleoperation::checkCalibration(TeleopBus *bus, const ServoInfo &servo,
                                     const LeRobotMotor &motor, const QString &file,
                                     std::function<void()> next)
{
    QVector<Block> blocks;
    for (const QStringView key :
         {QStringView(kOffsetKey), QStringView(kMinimumLimitKey), QStringView(kMaximumLimitKey)}) {
        if (const Register *reg = servo.table().find(key))
            blocks.append({reg->address, reg->size});
    }
    bus->run(operations::read(servo, blocks, ReadSource::Read), servo.id, servo.baud,
             [=](const OperationResult &read, const Memory &memory) {
                 if (m_state != State::Starting)
                     return;
                 if (!read.ok) {
                     fail(Problem::BusFailed, read.message);
                     return;
                 }
                 const QStringList differences = calibrationDifferences(
                     servo.table(),
                     calibrationWrites(motor.homingOffset, motor.rangeMin, motor.rangeMax),
                     valuesByKey(servo.table(), memory));
                 if (!differences.isEmpty()) {
                     const bool leader = bus == m_leader.get();
                     fail(Problem::NotCalibrated,
                          (leader ? tr("The leader's %1 (servo %2) does not hold what %3 says "
                                       "(%4). Nothing was written. Connect to the leader arm and "
                                       "write the file to it (Robot › Load calibration…), or "
                                       "choose the leader's own file.")
                                  : tr("The follower's %1 (servo %2) does not hold what %3 says "
                                       "(%4). Nothing was written. Write the file to the "
                                       "follower (Robot › Load calibration…), or choose the "
                                       "follower's own file."))
                              .arg(jointDisplayName(motor.name))
                              .arg(motor.id)
                              .arg(QDir::toNativeSeparators(file),
                                   differences.join(QStringLiteral("; "))));
                     return;
                 }
                 next();
             });
}

void Teleoperation::checkFollower(int joint)
{
    if (joint == m_mapping.joints().size()) {
        readFollower(0, {}, [this](const QVector<qint32> &standing) {
            if (m_state != State::Starting)
                return;
            emit progress(tr("The follower holds where it stands…"));
            m_torqueOn = true;
            hold(standing, [this, standing](bool held) {
                if (m_state != State::Starting)
                    return;
                if (!held) {
                    fail(Problem::BusFailed, tr("The follower's torque could not be switched on."));
                    return;
                }
                startLoop(standing);
            });
        });
        return;
    }
    checkCalibration(m_follower.get(), m_followerServos.at(joint),
                     m_mapping.joints().at(joint).follower, m_settings.followerCalibration,
                     [this, joint] { checkFollower(joint + 1); });
}

void Teleoperation::readFollower(int joint, QVector<qint32> positions,
                                 std::function<void(QVector<qint32>)> done)
{
    if (joint == m_followerServos.size()) {
        done(positions);
        return;
    }
    const ServoInfo &servo = m_followerServos.at(joint);
    const Register *reg = servo.table().find(registerkeys::kPresentPosition);
    if (!reg) {
        fail(Problem::BusFailed, tr("Servo %1 reports no position.").arg(servo.id));
        return;
    }
    m_follower->run(operations::read(servo, {{reg->address, reg->size}}, ReadSource::Read),
                    servo.id, servo.baud,
                    [=](const OperationResult &read, const Memory &memory) mutable {
                        if (m_state == State::Idle)
                            return; // ended meanwhile (the follower was lost)
                        const auto values = valuesByKey(servo.table(), memory);
                        if (!read.ok || !values.contains(registerkeys::kPresentPosition)) {
                            m_problem = Problem::BusFailed;
                            m_message = read.message;
                            if (m_state == State::Stopping)
                                end(false);
                            else if (m_state == State::Starting)
                                fail(Problem::BusFailed, read.message);
                            return;
                        }
                        positions.append(values.value(registerkeys::kPresentPosition));
                        readFollower(joint + 1, positions, done);
                    });
}

void Teleoperation::hold(const QVector<qint32> &positions, std::function<void(bool)> done)
{
    // Goal = present first, torque on after: a servo switched on holds, it never jumps.
    const RegisterTable &table = m_followerServos.first().table();
    const qint32 baud = m_followerServos.first().baud;
    const auto syncWrite = [&](const QString &key, const QVector<qint32> &values) {
        const Register *reg = table.find(key);
        QVector<SyncWriteEntry> entries;
        for (int i = 0; i < m_followerServos.size(); ++i)
            entries.append({m_followerServos.at(i).id,
                            encodeValue(values.at(i), table.format(*reg)).value_or(QByteArray())});
        return operations::syncWrite(baud, reg->address, reg->size, entries);
    };
    const qint32 torqueOn = table.torqueValue(TorqueMode::On).value_or(1);
    const BusOperation goals = syncWrite(registerkeys::kGoalPosition, positions);
    const BusOperation torque =
        syncWrite(registerkeys::kTorqueEnable, QVector<qint32>(m_followerServos.size(), torqueOn));
    const quint8 id = m_followerServos.first().id;
    m_follower->run(goals, id, baud, [=](const OperationResult &wrote, const Memory &) {
        if (m_state == State::Idle)
            return;
        if (!wrote.ok) {
            if (done)
                done(false);
            return;
        }
        m_follower->run(torque, id, baud, [=](const OperationResult &on, const Memory &) {
            if (done)
                done(on.ok);
        });
    });
}

void Teleoperation::startLoop(const QVector<qint32> &standing)
{
    m_loop = std::make_unique<TeleopLoop>(m_mapping, m_followerServos, m_leaderServos, standing,
                                          m_settings.maxSpeed);
    m_writesEnded.clear();
    TelemetryOptions stream;
    stream.servos = m_leaderServos;
    stream.rateHz = m_settings.rateHz;
    stream.publishEachCycle = true;
    setState(State::Running);
    emit progress(tr("Following the leader."));
    m_leader->runInSession([stream](Session &session) { session.startTelemetry(stream); });
}

void Teleoperation::onLeaderCycle(const QVector<FeedbackSample> &samples)
{
    if (m_state != State::Running)
        return;
    if (const auto write = m_loop->takeLeaderCycle(samples))
        sendGoals(*write);
}

void Teleoperation::sendGoals(const BusOperation &write)
{
    const ServoInfo &first = m_followerServos.first();
    m_follower->run(write, first.id, first.baud, [this](const OperationResult &, const Memory &) {
        if (!m_loop)
            return;
        const auto next = m_loop->takeWriteFinished();
        m_writesEnded.push_back(m_clock.elapsed());
        while (m_clock.elapsed() - m_writesEnded.front() > kRateWindowMs)
            m_writesEnded.pop_front();
        emit cycled();
        if (next && m_state == State::Running)
            sendGoals(*next);
        else if (m_state == State::Stopping)
            holdAndEnd();
    });
}

void Teleoperation::holdAndEnd()
{
    readFollower(0, {}, [this](const QVector<qint32> &here) {
        hold(here, [this](bool held) {
            if (!held && m_problem == Problem::None) {
                m_problem = Problem::BusFailed;
                m_message = tr("The follower could not be told to hold.");
            }
            end(held);
        });
    });
}

void Teleoperation::end(bool held)
{
    if (m_state == State::Idle)
        return;
    if (held && m_problem == Problem::None)
        m_message = tr("Stopped: the follower holds where it is.");
    else if (held)
        m_message = tr("%1 The follower holds where it is.").arg(m_message);
    disconnect(m_client.data(), &BusClient::statusChanged, this, nullptr);
    // Often called from inside one of their callbacks: they go once it has returned.
    m_leader.release()->deleteLater();
    m_follower.release()->deleteLater();
    setState(State::Idle);
    emit ended(held);
}

} // namespace feetech
