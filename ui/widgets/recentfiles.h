// The files a user opened or saved lately, by kind, remembered in QSettings: file dialogs start
// where the last one was, and File > Recent profiles lists them.
#pragma once

#include <QString>
#include <QStringList>

namespace recentfiles {

// Each kind keeps its own folder: a packet log exported does not open where calibrations are.
enum class Kind {
    Profile,
    Pose,
    Calibration,
    PacketSequence,
    PacketLog,
    ShareRecording,
    MotionRecording,
    TelemetryRecording,
    HealthReport,
    PlotImage,
};

constexpr int kMaxFiles = 8;

// Newest first, at most kMaxFiles, only those that still exist.
QStringList list(Kind kind);
void add(Kind kind, const QString &path);
// Where a file dialog for this kind starts: the newest file's folder, else Documents (Pictures
// for images), else the home folder: always a folder that exists, never the working directory.
QString directory(Kind kind);
// `fileName` in that folder: what a save dialog suggests.
QString suggestedPath(Kind kind, const QString &fileName);

} // namespace recentfiles
