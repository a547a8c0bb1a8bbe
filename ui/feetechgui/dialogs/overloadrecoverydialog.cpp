// The overload recovery dialog: one button that walks through the recovery's steps.
#include "overloadrecoverydialog.h"

#include "busclient.h"
#include "overloadrecovery.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

OverloadRecoveryDialog::OverloadRecoveryDialog(feetech::BusClient *client, int index,
                                               QWidget *parent)
    : QDialog(parent)
    , m_client(client)
    , m_servo(client->servos()->at(index).info.address())
{
    setObjectName(QStringLiteral("overloadRecoveryDialog"));
    setWindowTitle(tr("Recover servo ID %1").arg(m_servo.id));
    m_text = new QLabel(
        tr("The overload protection of servo ID %1 tripped: its torque is off.\n\n"
           "First free the horn (remove what blocks it). Then ServoBench switches its torque "
           "off and on again, with the goal at the present position so nothing moves, and "
           "reads the overload bit.")
            .arg(m_servo.id),
        this);
    m_text->setObjectName(QStringLiteral("recoveryText"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_action = buttons->addButton(tr("Torque off and on"), QDialogButtonBox::ActionRole);
    m_action->setObjectName(QStringLiteral("recoveryActionButton"));
    connect(m_action, &QPushButton::clicked, this, &OverloadRecoveryDialog::start);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_text, 1);
    layout->addWidget(buttons);
    const int em = fontMetrics().horizontalAdvance(u'm');
    resize(em * 45, em * 18);
}

QString OverloadRecoveryDialog::text() const
{
    return m_text->text();
}

void OverloadRecoveryDialog::start()
{
    if (!m_client)
        return;
    feetech::Refusal refusal;
    const int index = m_client->servos()->indexOf(m_servo);
    feetech::OperationReply *reply =
        index < 0 ? nullptr : m_client->guard()->recoverOverload(index, m_checkOnly, &refusal);
    if (!reply) {
        m_text->setText(index < 0 ? tr("Servo ID %1 is no longer on the bus.").arg(m_servo.id)
                                  : refusal.describe());
        return;
    }
    connect(reply, &feetech::OperationReply::finished, this,
            &OverloadRecoveryDialog::onOperationFinished);
    m_running = true;
    m_action->setEnabled(false);
    m_text->setText(m_checkOnly ? tr("Reading the status…") : tr("Torque off and on…"));
}

void OverloadRecoveryDialog::onOperationFinished(const feetech::OperationResult &result)
{
    if (!m_running)
        return;
    m_running = false;
    m_action->setEnabled(true);
    if (result.ok) {
        m_text->setText(result.message);
        m_action->hide();
        return;
    }
    if (result.failure == feetech::OperationFailure::StillLatched) {
        // Only a power cycle clears it: the steps, then a check that switches nothing on.
        m_checkOnly = true;
        m_text->setText(result.message);
        m_action->setText(tr("Check again"));
        return;
    }
    m_text->setText(tr("The recovery failed: %1").arg(result.message));
}
