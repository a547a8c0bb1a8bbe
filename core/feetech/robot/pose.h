// Poses: goal positions for several servos of a bus, kept as small JSON files.
#pragma once

#include "bustypes.h"
#include "fileerror.h"

#include <QByteArray>
#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

// The marker and format version every pose file carries; a higher version was written by a
// newer ServoBench and is refused rather than half-understood.
inline constexpr char kPoseFormatMarker[] = "servobench-pose";
inline constexpr int kPoseFormatVersion = 1;

// What a two-byte goal register can hold at most (15 bits of magnitude): the servo's own range
// is checked when the pose is moved to, since a file does not know the models.
inline constexpr qint32 kPoseMaxMagnitude = 32767;

struct PoseEntry
{
    quint8 id = 0;
    qint32 baud = 0; // bps: an ID is only unique at one baud rate
    qint32 position = 0; // register units (steps)

    bool operator==(const PoseEntry &other) const
    {
        return id == other.id && baud == other.baud && position == other.position;
    }
    bool operator!=(const PoseEntry &other) const { return !(*this == other); }
    ServoAddress address() const { return {id, baud}; }
};

struct Pose
{
    QString name; // optional, for the user
    QVector<PoseEntry> servos;

    // The entry of the servo at `servo`, or null.
    const PoseEntry *find(const ServoAddress &servo) const;

    bool operator==(const Pose &other) const
    {
        return name == other.name && servos == other.servos;
    }
    bool operator!=(const Pose &other) const { return !(*this == other); }
};

// The pose as an indented JSON document (entries in the pose's order).
QByteArray poseToJson(const Pose &pose);

// Reads a pose, validating all of it (syntax, format, version, every entry, no servo twice);
// on any problem, nothing and *error says what.
std::optional<Pose> poseFromJson(const QByteArray &json, util::FileError *error = nullptr);

// Writes atomically: the whole new file or the old one untouched. Refuses (writing nothing) a
// pose that poseFromJson would refuse. *error names the file.
bool savePose(const QString &path, const Pose &pose, util::FileError *error = nullptr);
std::optional<Pose> loadPose(const QString &path, util::FileError *error = nullptr);

} // namespace feetech
