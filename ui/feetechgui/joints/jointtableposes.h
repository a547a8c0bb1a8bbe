// The joint table's pose files: its targets saved as a pose, a pose loaded into its targets,
// with the buttons that do it and the label naming the pose.
#pragma once

#include "posematch.h"

#include <QObject>

#include <optional>

class JointTable;
class QLabel;
class QPushButton;

class JointTablePoses : public QObject
{
    Q_OBJECT

public:
    // The buttons and the label have `table` as parent; the table lays them out.
    explicit JointTablePoses(JointTable *table);

    QPushButton *loadButton() const { return m_load; }
    QPushButton *saveButton() const { return m_save; }
    QLabel *poseLabel() const { return m_label; }
    QString poseName() const { return m_name; }

    // The table's targets as a pose file (rows without a target are left out); NothingToSave
    // when no row has one.
    bool savePose(const QString &path, util::FileError *error = nullptr);
    // Fills the targets of the rows the pose names (by ID and baud rate): nothing moves. The
    // match says which entries and rows did not meet; nothing and *error when the file is
    // not a valid pose (no target changed then).
    std::optional<feetech::PoseMatch> loadPose(const QString &path,
                                               util::FileError *error = nullptr);

    // Load needs rows, Save a target.
    void updateButtons();

private:
    void onSaveClicked();
    void onLoadClicked();
    void report(const feetech::PoseMatch &match);

    JointTable *m_table = nullptr;
    QPushButton *m_load = nullptr;
    QPushButton *m_save = nullptr;
    QLabel *m_label = nullptr;
    QString m_name;
};
