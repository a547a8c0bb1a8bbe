// The joint table's pose actions: targets from the present positions, and pose files saved
// from and loaded into the targets.
#include "jointtable.h"

#include "busclient.h"
#include "recentfiles.h"
#include "registerkeys.h"
#include "servoparameters.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>

using namespace feetech::registerkeys;

int JointTable::capturePositions()
{
    int filled = 0;
    QStringList missing;
    for (int row = 0; row < rowCount(); ++row) {
        if (!targetRange(row))
            continue; // a servo that cannot be moved needs no target
        if (const std::optional<qint32> value = position(row)) {
            setTarget(row, *value);
            ++filled;
        } else {
            missing.append(servoName(row));
        }
    }
    if (missing.isEmpty())
        setMessage(tr("Targets set to the present positions of %1 servos.").arg(filled),
                   Tone::Success);
    else
        setMessage(tr("Targets set for %1 servos. No position is known yet for %2: read the "
                      "positions first.")
                       .arg(filled)
                       .arg(missing.join(tr(", "))),
                   Tone::Warning);
    return filled;
}

bool JointTable::savePose(const QString &path, QString *error)
{
    feetech::Pose pose;
    pose.name = m_poseName.isEmpty() ? QFileInfo(path).baseName() : m_poseName;
    for (const Row &row : std::as_const(m_rows)) {
        if (row.target)
            pose.servos.append({row.id, row.baud, *row.target});
    }
    if (pose.servos.isEmpty()) {
        if (error)
            *error = tr("No targets to save: set some first.");
        return false;
    }
    if (!feetech::savePose(path, pose, error))
        return false;
    m_poseName = pose.name;
    refreshButtons();
    setMessage(tr("Saved the pose “%1” with %2 targets to %3.")
                   .arg(pose.name)
                   .arg(pose.servos.size())
                   .arg(QDir::toNativeSeparators(path)),
               Tone::Success);
    return true;
}

std::optional<JointTable::PoseMatch> JointTable::loadPose(const QString &path, QString *error)
{
    const std::optional<feetech::Pose> pose = feetech::loadPose(path, error);
    if (!pose)
        return std::nullopt;
    PoseMatch match;
    match.name = pose->name.isEmpty() ? QFileInfo(path).baseName() : pose->name;
    for (const feetech::PoseEntry &entry : pose->servos) {
        if (rowOf(entry.id, entry.baud) < 0)
            match.notOnBus.append(entry);
    }
    for (int row = 0; row < rowCount(); ++row) {
        const feetech::PoseEntry *entry = pose->find(m_rows.at(row).id, m_rows.at(row).baud);
        if (!entry) {
            match.rowsWithoutEntry.append(row);
            continue;
        }
        setTarget(row, entry->position);
        ++match.filled;
        const std::optional<feetech::PositionRange> range = targetRange(row);
        if (range && !range->contains(entry->position))
            match.rowsOutOfRange.append(row);
    }
    m_poseName = match.name;
    refreshButtons();

    QStringList report;
    report.append(tr("Loaded the pose “%1”: %2 targets filled. Nothing moves until you press "
                     "Move all.")
                      .arg(match.name)
                      .arg(match.filled));
    if (!match.notOnBus.isEmpty()) {
        QStringList names;
        for (const feetech::PoseEntry &entry : std::as_const(match.notOnBus))
            names.append(tr("ID %1 at %2").arg(entry.id).arg(feetech::baudText(entry.baud)));
        report.append(tr("Not on the bus: %1.").arg(names.join(tr(", "))));
    }
    if (!match.rowsWithoutEntry.isEmpty()) {
        QStringList names;
        for (const int row : std::as_const(match.rowsWithoutEntry))
            names.append(servoName(row));
        report.append(tr("Not in the pose (targets unchanged): %1.").arg(names.join(tr(", "))));
    }
    if (!match.rowsOutOfRange.isEmpty()) {
        QStringList names;
        for (const int row : std::as_const(match.rowsOutOfRange))
            names.append(servoName(row));
        report.append(tr("Outside their range (shown in red): %1.").arg(names.join(tr(", "))));
    }
    const bool clean = match.notOnBus.isEmpty() && match.rowsWithoutEntry.isEmpty()
        && match.rowsOutOfRange.isEmpty();
    setMessage(report.join(u' '), clean ? Tone::Success : Tone::Warning);
    return match;
}

void JointTable::onCaptureClicked()
{
    capturePositions();
}

void JointTable::onSaveClicked()
{
    const QString suggestion =
        QDir(recentfiles::directory(recentfiles::Kind::Pose))
            .filePath(m_poseName.isEmpty() ? tr("pose.json") : QString(m_poseName + u".json"));
    QString path = QFileDialog::getSaveFileName(this, tr("Save pose"), suggestion,
                                                tr("ServoBench poses (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    QString error;
    if (savePose(path, &error))
        recentfiles::add(recentfiles::Kind::Pose, path);
    else
        setMessage(error, Tone::Error);
}

void JointTable::onLoadClicked()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Load pose"), recentfiles::directory(recentfiles::Kind::Pose),
        tr("ServoBench poses (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (loadPose(path, &error))
        recentfiles::add(recentfiles::Kind::Pose, path);
    else
        setMessage(error, Tone::Error);
}
