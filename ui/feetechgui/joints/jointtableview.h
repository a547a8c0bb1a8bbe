// The joint table's grid: one row per servo, its cells drawn and coloured from the values the
// joint table gives, and the user's edits of a target or a torque tick reported back.
#pragma once

#include "goalrange.h"
#include "tablefacts.h"

#include <QTableWidget>

#include <optional>

namespace feetech {
struct ServoInfo;
}

class JointTableView : public QTableWidget
{
    Q_OBJECT

public:
    enum Column {
        IdColumn,
        ModelColumn,
        BaudColumn,
        PositionColumn,
        TargetColumn,
        RangeColumn,
        TorqueColumn,
        MovingColumn,
        IdentifyColumn, // a button: wiggle the servo to see which one it is
        ColumnCount
    };

    // What a row's torque cell shows: what the servo reports, or what was just asked of it.
    struct Torque
    {
        std::optional<qint64> device; // the torque enable register as read
        std::optional<feetech::TorqueMode> mode; // its meaning for the servo's model
        std::optional<feetech::TorqueMode> requested; // written, not yet read back
    };

    explicit JointTableView(QWidget *parent = nullptr);

    // Empty rows (the identify column left to the caller); the old ones go.
    void resetRows(int count);
    void showServo(int row, const feetech::ServoInfo &info, const Torque &torque);
    // The present position, live from the monitor or last read, and whether the servo moves.
    void showPosition(int row, std::optional<qint32> position, bool live,
                      std::optional<bool> moving);
    void showTarget(int row, std::optional<feetech::PositionRange> range,
                    std::optional<qint32> target);

signals:
    // Edits by the user only, not the cells being filled.
    void targetEdited(int row, qint32 target);
    void torqueToggled(int row, bool on);

private:
    void onItemChanged(QTableWidgetItem *item);

    bool m_filling = false; // the cells are being filled by code, not edited by the user
};
