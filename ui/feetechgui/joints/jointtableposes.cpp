// The joint table's pose files: its targets saved as a pose, a pose loaded into its targets,
// and what the table says about how the pose met its servos.
#include "jointtableposes.h"

#include "jointtable.h"
#include "recentfiles.h"
#include "registertable.h"
#include "widgethelpers.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>

using widgethelpers::actionButton;

JointTablePoses::JointTablePoses(JointTable *table)
    : QObject(table)
    , m_table(table)
{
    m_load =
        actionButton(tr("Load pose…"), "loadPoseButton",
                     tr("Fill the targets from a pose file; nothing moves until Move all"), table);
    m_save = actionButton(tr("Save pose…"), "savePoseButton", tr("Save the targets as a pose file"),
                          table);
    m_label = new QLabel(table);
    m_label->setObjectName(QStringLiteral("poseLabel"));
    m_label->setForegroundRole(QPalette::PlaceholderText);
    connect(m_load, &QPushButton::clicked, this, &JointTablePoses::onLoadClicked);
    connect(m_save, &QPushButton::clicked, this, &JointTablePoses::onSaveClicked);
}

bool JointTablePoses::savePose(const QString &path, util::FileError *error)
{
    const feetech::Pose pose = feetech::poseFromTargets(
        m_name.isEmpty() ? QFileInfo(path).baseName() : m_name, m_table->joints());
    if (pose.servos.isEmpty()) {
        util::report(error,
                     util::FileError(util::FileError::Code::NothingToSave,
                                     tr("No targets to save: set some first.")));
        return false;
    }
    if (!feetech::savePose(path, pose, error))
        return false;
    m_name = pose.name;
    updateButtons();
    m_table->setMessage(tr("Saved the pose “%1” with %2 targets to %3.")
                            .arg(pose.name)
                            .arg(pose.servos.size())
                            .arg(QDir::toNativeSeparators(path)),
                        JointTable::Tone::Success);
    return true;
}

std::optional<feetech::PoseMatch> JointTablePoses::loadPose(const QString &path,
                                                            util::FileError *error)
{
    const std::optional<feetech::Pose> pose = feetech::loadPose(path, error);
    if (!pose)
        return std::nullopt;
    const feetech::PoseMatch match =
        feetech::matchPose(*pose, m_table->joints(), QFileInfo(path).baseName());
    for (int row = 0; row < match.targets.size(); ++row) {
        if (match.targets.at(row))
            m_table->setTarget(row, *match.targets.at(row));
    }
    m_name = match.name;
    updateButtons();
    report(match);
    return match;
}

void JointTablePoses::updateButtons()
{
    bool anyTarget = false;
    for (int row = 0; row < m_table->rowCount(); ++row)
        anyTarget = anyTarget || m_table->target(row).has_value();
    m_load->setEnabled(m_table->rowCount() > 0);
    m_save->setEnabled(anyTarget);
    m_label->setText(m_name.isEmpty() ? QString() : tr("Pose: %1").arg(m_name));
}

void JointTablePoses::report(const feetech::PoseMatch &match)
{
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
            names.append(m_table->servoName(row));
        report.append(tr("Not in the pose (targets unchanged): %1.").arg(names.join(tr(", "))));
    }
    if (!match.rowsOutOfRange.isEmpty()) {
        QStringList names;
        for (const int row : std::as_const(match.rowsOutOfRange))
            names.append(m_table->servoName(row));
        report.append(tr("Outside their range (shown in red): %1.").arg(names.join(tr(", "))));
    }
    m_table->setMessage(report.join(u' '),
                        match.isClean() ? JointTable::Tone::Success : JointTable::Tone::Warning);
}

void JointTablePoses::onSaveClicked()
{
    const QString suggestion =
        QDir(recentfiles::directory(recentfiles::Kind::Pose))
            .filePath(m_name.isEmpty() ? tr("pose.json") : QString(m_name + u".json"));
    QString path = QFileDialog::getSaveFileName(m_table, tr("Save pose"), suggestion,
                                                tr("ServoBench poses (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    util::FileError error;
    if (savePose(path, &error))
        recentfiles::add(recentfiles::Kind::Pose, path);
    else
        m_table->setMessage(error.describe(), JointTable::Tone::Error);
}

void JointTablePoses::onLoadClicked()
{
    const QString path = QFileDialog::getOpenFileName(
        m_table, tr("Load pose"), recentfiles::directory(recentfiles::Kind::Pose),
        tr("ServoBench poses (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    util::FileError error;
    if (loadPose(path, &error))
        recentfiles::add(recentfiles::Kind::Pose, path);
    else
        m_table->setMessage(error.describe(), JointTable::Tone::Error);
}
