// A recorded motion: joints and their positions over time, and its CSV file (a time column in
// seconds, one column of position steps per joint, one header line).
#pragma once

#include "fileerror.h"
#include "motionjoint.h"

#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

struct MotionRecording
{
    // Far more than any hand-made recording: a file beyond it is a wrongly picked one.
    static constexpr qint64 kMaxFileBytes = 64 * 1024 * 1024;

    QVector<MotionJoint> joints;
    QVector<double> times; // seconds from the start of the recording, never going back
    QVector<QVector<qint32>> frames; // frames[i][j]: joint j's position at times[i], in steps

    bool isEmpty() const { return frames.isEmpty(); }
    double duration() const { return times.isEmpty() ? 0.0 : times.last() - times.first(); }
    // The frame at or just before `seconds` from the first; -1 when empty.
    int frameAt(double seconds) const;
};

QByteArray motionRecordingCsv(const MotionRecording &recording);
// The recording a CSV file holds: BadValue (the row or cell at fault named), MissingField (no
// header, no time column, no frame), Duplicate (a servo twice), all naming no file.
std::optional<MotionRecording> motionRecordingFromCsv(const QByteArray &csv,
                                                      util::FileError *error);
std::optional<MotionRecording> loadMotionRecording(const QString &path, util::FileError *error);
// Whole or not at all; NothingToSave for a recording without a frame.
bool saveMotionRecording(const QString &path, const MotionRecording &recording,
                         util::FileError *error);

} // namespace feetech
