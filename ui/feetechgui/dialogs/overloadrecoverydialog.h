// The guided recovery of a servo whose overload protection tripped: torque off and on, then,
// when the overload bit stays set, the power cycle step by step and a check afterwards.
#pragma once

#include "bustypes.h"

#include <QDialog>
#include <QPointer>

class QLabel;
class QPushButton;

namespace feetech {
class BusClient;
struct OperationResult;
} // namespace feetech

class OverloadRecoveryDialog : public QDialog
{
    Q_OBJECT

public:
    OverloadRecoveryDialog(feetech::BusClient *client, int index, QWidget *parent = nullptr);

    QString text() const; // what the dialog says now
    QPushButton *actionButton() const { return m_action; }

private:
    void start();
    void onOperationFinished(const feetech::OperationResult &result);

    QPointer<feetech::BusClient> m_client;
    feetech::ServoAddress m_servo;
    bool m_checkOnly = false; // the next press checks after a power cycle
    bool m_running = false;
    QLabel *m_text = nullptr;
    QPushButton *m_action = nullptr;
};
