// The Monitor page's list of servos to stream: one tickable row per servo of the bus, its ticks
// kept across a rescan by ID and baud rate.
#pragma once

#include "jointnames.h"
#include "monitorreadouts.h"

#include <QHash>
#include <QListWidget>
#include <QVector>

namespace feetech {
class BusClient;
}

class MonitorServoList : public QListWidget
{
    Q_OBJECT

public:
    explicit MonitorServoList(QWidget *parent = nullptr);

    // One row per servo of `client` (a hint without one); ticks survive by ID and baud rate,
    // servos new to the list come ticked. Says nothing (no ticksChanged).
    void rebuild(const feetech::BusClient *client);

    // Servos by their index in the bus client.
    void setSelectedServos(const QVector<int> &indexes);
    QVector<int> selectedServos() const;
    QVector<feetech::ServoAddress> checkedKeys() const;
    bool isListed(const feetech::ServoAddress &key) const;
    // Ticked or not, for each servo the list names.
    QHash<feetech::ServoAddress, bool> ticks() const;
    // The joints the servos listed are, when they match a robot template (as of rebuild).
    const feetech::JointNames &jointNames() const { return m_names; }

signals:
    // The user ticked or unticked a servo, or setSelectedServos changed the ticks.
    void ticksChanged();

private:
    feetech::ServoAddress keyOf(const QListWidgetItem *item) const;

    bool m_updating = false; // our own check-state changes are not the user's
    feetech::JointNames m_names;
};
