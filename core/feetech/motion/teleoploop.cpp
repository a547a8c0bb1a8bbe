// The teleoperation loop: leader cycles to the follower's speed-limited SYNC WRITEs.
#include "teleoploop.h"

#include "busoperations.h"
#include "registerkeys.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kStepsPerDegree = 4096.0 / 360.0;

} // namespace

namespace feetech {

TeleopLoop::TeleopLoop(const TeleopMapping &mapping, const QVector<ServoInfo> &follower,
                       const QVector<ServoInfo> &leader, const QVector<qint32> &standing,
                       double maxSpeedDegreesPerSecond)
    : m_mapping(mapping)
    , m_follower(follower)
    , m_leader(leader)
    , m_standing(standing)
    , m_stepsPerSecond(maxSpeedDegreesPerSecond * kStepsPerDegree)
    , m_sent(standing.begin(), standing.end())
    , m_leaderNormalised(standing.size(), 0.0)
{
    for (int i = 0; i < follower.size(); ++i)
        m_recording.joints.append({mapping.joints().at(i).name, follower.at(i).id});
    m_sinceWrite.start();
}

std::optional<BusOperation> TeleopLoop::takeLeaderCycle(const QVector<FeedbackSample> &samples)
{
    if (m_stopped)
        return std::nullopt; // a cycle the leader's stream handed over as it stopped
    QVector<qint32> targets = m_standing;
    int seen = 0;
    for (const FeedbackSample &sample : samples) {
        const int joint =
            int(std::find_if(m_leader.begin(), m_leader.end(),
                             [&](const ServoInfo &servo) { return servo.id == sample.id; })
                - m_leader.begin());
        const auto position = sample.value(Quantity::Position);
        if (joint >= m_leader.size() || !position)
            continue;
        const TeleopJoint &pair = m_mapping.joints().at(joint);
        m_leaderNormalised[joint] =
            TeleopMapping::normalise(pair.leader, pair.gripper, qint32(*position));
        targets[joint] = m_mapping.followerGoal(joint, qint32(*position));
        ++seen;
    }
    if (samples.isEmpty() || seen < m_leader.size())
        return std::nullopt; // a cycle some joint missed: its goal is not guessed
    if (m_writing) {
        m_waiting = targets;
        m_waitingSampleUs = samples.first().steadyUs;
        return std::nullopt;
    }
    return send(targets, samples.first().steadyUs);
}

std::optional<BusOperation> TeleopLoop::takeWriteFinished()
{
    if (!m_writing)
        return std::nullopt;
    m_writing = false;
    ++m_writes;
    m_latencies.append(steadyMicroseconds() - m_writeSampleUs);
    if (!m_waiting)
        return std::nullopt;
    return send(*std::exchange(m_waiting, std::nullopt), m_waitingSampleUs);
}

void TeleopLoop::stop()
{
    m_stopped = true;
    m_waiting.reset();
}

double TeleopLoop::medianLatencyMs() const
{
    if (m_latencies.isEmpty())
        return 0.0;
    QVector<qint64> sorted = m_latencies;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    return sorted.at(sorted.size() / 2) / 1e3;
}

double TeleopLoop::lastLatencyMs() const
{
    return m_latencies.isEmpty() ? 0.0 : m_latencies.last() / 1e3;
}

QVector<double> TeleopLoop::followerGoalsNormalised() const
{
    QVector<double> goals;
    for (int i = 0; i < m_sent.size(); ++i) {
        const TeleopJoint &pair = m_mapping.joints().at(i);
        goals.append(TeleopMapping::normalise(pair.follower, pair.gripper,
                                              qint32(std::lround(m_sent.at(i)))));
    }
    return goals;
}

BusOperation TeleopLoop::send(const QVector<qint32> &targets, qint64 sampleUs)
{
    const double seconds = std::max(0.001, m_sinceWrite.nsecsElapsed() / 1e9);
    m_sinceWrite.restart();
    const RegisterTable &table = m_follower.first().table();
    const Register *goal = table.find(registerkeys::kGoalPosition);
    const double reach = m_stepsPerSecond * seconds;
    QVector<SyncWriteEntry> entries;
    QVector<qint32> frame;
    for (int i = 0; i < targets.size(); ++i) {
        m_sent[i] += std::clamp(double(targets.at(i)) - m_sent.at(i), -reach, reach);
        frame.append(qint32(std::lround(m_sent.at(i))));
        entries.append({m_follower.at(i).id, *encodeValue(frame.last(), table.format(*goal))});
    }
    if (!m_recordingClock.isValid())
        m_recordingClock.start();
    m_recording.times.append(m_recordingClock.nsecsElapsed() / 1e9);
    m_recording.frames.append(frame);
    m_writing = true;
    m_writeSampleUs = sampleUs;
    return operations::syncWrite(m_follower.first().baud, goal->address, goal->size, entries);
}

} // namespace feetech
