// The guard's settings: on or off for the bus, and per servo its limits, hold time and action.
#pragma once

#include "overloadguard.h"

#include <QDialog>

class QCheckBox;
class QTableWidget;

namespace feetech {
class BusClient;
}

class GuardSettingsDialog : public QDialog
{
    Q_OBJECT

public:
    enum Column {
        ServoColumn,
        OnColumn,
        LoadColumn,
        HoldColumn,
        MaxTemperatureColumn,
        MarginColumn,
        ActionColumn,
        ColumnCount
    };

    explicit GuardSettingsDialog(feetech::BusClient *client, QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }
    // What the dialog shows, as the client would take it: a servo whose row equals its
    // defaults is left out, so its defaults keep following its registers.
    feetech::GuardSettings settings() const;

private:
    void fillRow(int row, const feetech::GuardLimits &limits);
    feetech::GuardLimits rowLimits(int row) const;
    void restoreDefaults();

    feetech::BusClient *m_client;
    QCheckBox *m_enabled = nullptr;
    QTableWidget *m_table = nullptr;
    QVector<int> m_indexes; // the client's index of each row's servo
};
