// The files a user opened or saved lately, by kind, remembered in QSettings: file dialogs start
// where the last one was, and File > Recent profiles lists them.
#include "recentfiles.h"

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
        break;
    }
    return QStringLiteral("recent/packets");
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
    return files.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                           : QFileInfo(files.first()).absolutePath();
}

} // namespace recentfiles
