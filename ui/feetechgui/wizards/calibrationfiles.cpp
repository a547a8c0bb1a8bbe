// LeRobot calibration files: the folders and names offered, the save dialog that makes LeRobot's
// folder.
#include "calibrationfiles.h"

#include "lerobotcalibration.h"
#include "recentfiles.h"
#include "robottemplate.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLineEdit>

namespace {

struct CalibrationFilesTr
{
    Q_DECLARE_TR_FUNCTIONS(CalibrationFiles)
};

const QString kArmFileName = QStringLiteral("my_arm.json");

// The folders of `folder` and above that do not exist, the deepest first.
QStringList missingFolders(const QString &folder)
{
    QStringList missing;
    for (QDir dir(folder); !dir.exists(); dir.setPath(QFileInfo(dir.path()).path())) {
        missing.append(dir.path());
        if (dir.isRoot())
            break;
    }
    return missing;
}

// What LeRobot's own examples call an arm of the template's kind.
QString defaultArmName(const feetech::RobotTemplate *robot)
{
    const bool leader = robot && robot->name.contains(QLatin1String("leader"), Qt::CaseInsensitive);
    return leader ? QStringLiteral("my_leader_arm") : QStringLiteral("my_follower_arm");
}

// A name as a file name: letters, digits, '-', '_' and '.' kept, anything else made '_'.
QString fileNameOf(const QString &name)
{
    QString file = name.trimmed();
    for (QChar &c : file) {
        if (!(c.isLetterOrNumber() || c == u'-' || c == u'_' || c == u'.'))
            c = u'_';
    }
    while (file.startsWith(u'.'))
        file.remove(0, 1);
    return file;
}

} // namespace

QString defaultCalibrationFolder(const feetech::RobotTemplate *robot)
{
    const QString root = feetech::leRobotCalibrationFolder();
    if (robot) {
        for (const QString &folder : feetech::leRobotArmFolders(robot->name)) {
            if (QDir(root).exists(folder))
                return QDir(root).filePath(folder);
        }
    }
    const QStringList recent = recentfiles::list(recentfiles::Kind::Calibration);
    if (!recent.isEmpty())
        return QFileInfo(recent.first()).absolutePath();
    return QDir(root).exists() ? root : QDir::homePath();
}

QString suggestedCalibrationFile(const feetech::RobotTemplate *robot)
{
    const QString armFolder = robot ? feetech::leRobotArmFolder(robot->name) : QString();
    if (armFolder.isEmpty())
        return QDir(defaultCalibrationFolder(robot)).filePath(kArmFileName);
    for (const QString &recent : recentfiles::list(recentfiles::Kind::Calibration)) {
        const QFileInfo used(recent);
        if (QDir::cleanPath(used.absolutePath()) == QDir::cleanPath(armFolder))
            return QDir(armFolder).filePath(used.fileName());
    }
    return QDir(armFolder).filePath(kArmFileName);
}

QString chooseCalibrationFileToSave(QWidget *parent, const QString &title,
                                    const feetech::RobotTemplate *robot)
{
    QString suggested = suggestedCalibrationFile(robot);
    if (QFileInfo(suggested).fileName() == kArmFileName) {
        // No file of this arm saved yet: LeRobot names the file after the arm (its --robot.id
        // or --teleop.id), so that is asked first rather than a name nobody chose.
        bool ok = false;
        const QString name = QInputDialog::getText(
            parent, title,
            CalibrationFilesTr::tr("The arm's name, as LeRobot's --robot.id (or --teleop.id) "
                                   "gives it; it names the file:"),
            QLineEdit::Normal, defaultArmName(robot), &ok);
        if (!ok)
            return {};
        const QString file = fileNameOf(name);
        if (!file.isEmpty())
            suggested = QDir(QFileInfo(suggested).path()).filePath(file + QStringLiteral(".json"));
    }
    const QStringList made = missingFolders(QFileInfo(suggested).path());
    if (!made.isEmpty())
        QDir().mkpath(QFileInfo(suggested).path()); // the dialog opens only in a folder that is
    const QString path = QFileDialog::getSaveFileName(
        parent, title, suggested, CalibrationFilesTr::tr("LeRobot calibration (*.json)"));
    const QString savedIn = path.isEmpty() ? QString() : QFileInfo(path).absolutePath();
    for (const QString &folder : made) {
        const QString clean = QDir::cleanPath(QFileInfo(folder).absoluteFilePath());
        if (!savedIn.isEmpty()
            && (savedIn == clean || savedIn.startsWith(clean + QLatin1Char('/'))))
            break; // it and the folders above it hold the file to be saved
        QDir().rmdir(folder); // only when empty: nothing anyone put there is lost
    }
    return path;
}
