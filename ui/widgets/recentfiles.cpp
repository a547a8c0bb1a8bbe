// The files a user opened or saved lately, by kind, remembered in QSettings: file dialogs start
// where the last one was, and File > Recent profiles lists them.
#include "recentfiles.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace recentfiles {

namespace {

QString key(Kind kind)
{
    switch (kind) {
    case Kind::Profile:
        return QStringLiteral("recent/profiles");
    case Kind::Pose:
        return QStringLiteral("recent/poses");
    case Kind::Calibration:
        return QStringLiteral("recent/calibrations");
    case Kind::PacketSequence:
        return QStringLiteral("recent/packets");
    case Kind::PacketLog:
        return QStringLiteral("recent/packetLogs");
    case Kind::ShareRecording:
        return QStringLiteral("recent/shareRecordings");
    case Kind::MotionRecording:
        return QStringLiteral("recent/motionRecordings");
    case Kind::TelemetryRecording:
        return QStringLiteral("recent/telemetry");
    case Kind::HealthReport:
        return QStringLiteral("recent/healthReports");
    case Kind::PlotImage:
        break;
    }
    return QStringLiteral("recent/plotImages");
}

} // namespace

QStringList list(Kind kind)
{
    QStringList files;
    for (const QString &path : QSettings().value(key(kind)).toStringList()) {
        if (QFileInfo::exists(path) && !files.contains(path))
            files.append(path);
    }
    return files.mid(0, kMaxFiles);
}

void add(Kind kind, const QString &path)
{
    if (path.isEmpty())
        return;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList files = QSettings().value(key(kind)).toStringList();
    files.removeAll(absolute);
    files.prepend(absolute);
    QSettings().setValue(key(kind), files.mid(0, kMaxFiles));
}

QString directory(Kind kind)
{
    const QStringList files = list(kind);
    if (!files.isEmpty())
        return QFileInfo(files.first()).absolutePath();
    // A dialog given a folder that does not exist opens wherever the last one was.
    const QString usual = QStandardPaths::writableLocation(kind == Kind::PlotImage
                                                               ? QStandardPaths::PicturesLocation
                                                               : QStandardPaths::DocumentsLocation);
    return QFileInfo(usual).isDir() ? usual : QDir::homePath();
}

QString suggestedPath(Kind kind, const QString &fileName)
{
    return QDir(directory(kind)).filePath(fileName);
}

} // namespace recentfiles
