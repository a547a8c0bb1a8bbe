// Calibrating an arm's joints by hand: recording each joint's range across the encoder's seam,
// and the position offset and angle limits that centre the range on the encoder.
#pragma once

#include "parametermodel.h"

#include <QHash>
#include <QString>
#include <QStringList>
#include <QVector>

#include <optional>

namespace feetech {

class RegisterTable;

class RegisterTable;

// The encoder of the families with a position offset (STS, SMS, HLS): 4096 steps a turn.
constexpr int kEncoderSteps = 4096;
// Where ServoBench puts the middle of a joint's range: the middle of the encoder.
constexpr int kEncoderMiddle = kEncoderSteps / 2; // 2048
// Where LeRobot puts the middle pose: its "half turn", (resolution - 1) / 2.
constexpr int kLeRobotHalfTurn = (kEncoderSteps - 1) / 2; // 2047
// A joint's range must leave at least this much of the turn unused, so that the limits stay
// clear of the 0/4095 seam even when the recording missed a few steps at either end.
constexpr int kRangeSafetyMargin = 64;
// A joint whose recorded motion spans fewer steps than this was not moved.
constexpr int kMinimumMotionSteps = 20;
// Samples per second and joint while a range is recorded: smooth enough to follow a hand.
constexpr double kRecordingRateHz = 50.0;
// A joint turned by hand moves far less than half a turn in this many cycles (200 ms at
// kRecordingRateHz), so the unwrapping still holds across such a gap; fewer misses would refuse
// a healthy joint whenever a loaded machine delays a few replies.
constexpr int kRecordingMissesBeforeLost = 10;

// The register keys a calibration writes.
inline constexpr char16_t kOffsetKey[] = u"position_offset";
inline constexpr char16_t kMinimumLimitKey[] = u"min_angle_limit";
inline constexpr char16_t kMaximumLimitKey[] = u"max_angle_limit";

// A position (any number of turns away) as the encoder reads it: 0 to kEncoderSteps - 1.
int wrapToEncoder(int steps);
// The same position as a signed distance from 0: -kEncoderSteps / 2 to kEncoderSteps / 2 - 1.
int wrapSigned(int steps);

// Follows one joint's present position while it is turned by hand. Successive samples that
// differ by more than half a turn are taken as a crossing of the 0/4095 seam, so the motion is
// kept unwrapped: a joint turned from 4000 to 100 has moved 196 steps, not -3900.
class JointRangeRecorder
{
public:
    // A present position as the servo reports it (0 to kEncoderSteps - 1).
    void addSample(int present);
    // The servo stopped answering: the range can no longer be trusted.
    void markLost() { m_lost = true; }
    bool isLost() const { return m_lost; }
    bool hasSamples() const { return m_samples > 0; }
    int sampleCount() const { return m_samples; }

    // Unwrapped: the first sample as it was read, each next one the nearest equivalent of its
    // reading to the one before. Meaningless before the first sample.
    int first() const { return m_first; }
    int minimum() const { return m_minimum; }
    int maximum() const { return m_maximum; }
    int present() const { return m_present; }
    int span() const { return m_maximum - m_minimum; }

private:
    int m_samples = 0;
    int m_first = 0;
    int m_minimum = 0;
    int m_maximum = 0;
    int m_present = 0;
    bool m_lost = false;
};

// ServoBench's order records the range first and centres it; LeRobot's takes the offset from a
// middle pose first (the pose reads kLeRobotHalfTurn), then records the range.
enum class CalibrationOrder { RangeFirst, MiddlePoseFirst };

// What the register table allows a calibration to write.
struct CalibrationLimits
{
    qint32 minimumOffset = -2047; // STS: sign-magnitude with the sign in bit 11
    qint32 maximumOffset = 2047;
    qint32 highestMinimumLimit = 4094;
    qint32 highestMaximumLimit = kEncoderSteps - 1;
};
// The limits of `table`; nothing when the family has no position offset (SCS) or its encoder is
// not a 4096-step one.
std::optional<CalibrationLimits> calibrationLimits(const RegisterTable &table);

struct JointRecording
{
    QString name;
    int id = 0;
    bool fullTurn = false; // turns without end stops: offset only, limits 0 to 4095
    qint32 currentOffset = 0; // the offset register while the joint was recorded
    CalibrationLimits limits;
    // MiddlePoseFirst: the present position read in the middle pose, before the recording.
    std::optional<int> middlePose;
    JointRangeRecorder range;
};

struct JointCalibration
{
    QString name;
    int id = 0;
    bool fullTurn = false;
    QString refusal; // why nothing may be written for this joint; empty when it may
    qint32 offset = 0; // the new position offset (register units)
    qint32 minimumLimit = 0; // the new limits, in the new present coordinates
    qint32 maximumLimit = kEncoderSteps - 1;

    bool ok() const { return refusal.isEmpty(); }
};

// The offset that makes the servo read `physical` (a position with no offset, in any turn) as
// `target`: present = physical - offset. Where the exact offset is outside what the register
// holds (-2048 on STS, whose offset ends at ±2047), the nearest it holds: the target is then
// missed by a step.
qint32 offsetPlacing(int physical, int target, const CalibrationLimits &limits);

// The offset and limits for one recorded joint, or the refusal: a servo that stopped answering,
// a joint that never moved, a range wider than the encoder less kRangeSafetyMargin, and (in
// LeRobot's order) a range that would still cross the seam from the middle pose.
//
// Full-turn joints get limits 0 to 4095 and an offset only: in ServoBench's order the one that
// puts the middle of the recorded motion at kEncoderMiddle while the motion spans less than a
// turn, and the one that puts the position where the recording ended there once it spans a turn
// or more (every position was then visited, and the last one is where the user left the joint:
// its chosen middle). In LeRobot's order the middle pose reads kLeRobotHalfTurn.
JointCalibration calibrateJoint(const JointRecording &joint, CalibrationOrder order);

// A recorded position (unwrapped, in the coordinates of the recording) in the coordinates the
// calibration gives the joint.
int inCalibratedCoordinates(const JointRecording &joint, const JointCalibration &result,
                            int recorded);

// The register writes that give a servo this offset and these limits, in register units (a
// LeRobot limit of 4096 as 4095, the register's largest value).
QVector<model::WriteItem> calibrationWrites(qint32 offset, qint32 minimumLimit,
                                            qint32 maximumLimit);
// What the servo read back differently from `items`, one "key: wrote W, the servo holds R" a
// register (empty when it holds every value).
QStringList calibrationMismatches(const QVector<model::WriteItem> &items,
                                  const QHash<QString, qint32> &readBack);
// What a servo holds differently from what a calibration file says, before anything is written:
// one "Position offset: the file says F, the servo holds H" a register, named as `table` names
// it in the user's language (empty when it holds every value).
QStringList calibrationDifferences(const RegisterTable &table,
                                   const QVector<model::WriteItem> &fileSays,
                                   const QHash<QString, qint32> &servoHolds);

} // namespace feetech
