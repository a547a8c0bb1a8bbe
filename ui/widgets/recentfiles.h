// The files a user opened or saved lately, by kind, remembered in QSettings: file dialogs start
// where the last one was, and File > Recent profiles lists them.
#pragma once

#include <QString>
#include <QStringList>

namespace recentfiles {

enum class Kind { Profile, Pose, Calibration, PacketSequence };

constexpr int kMaxFiles = 8;

// Newest first, at most kMaxFiles, only those that still exist.
QStringList list(Kind kind);
void add(Kind kind, const QString &path);
// Where a file dialog for this kind starts: the newest file's folder, else Documents.
QString directory(Kind kind);

} // namespace recentfiles
