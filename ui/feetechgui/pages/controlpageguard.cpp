// The Control page's guard banner: what the overload and thermal guard last said about the
// servo shown, its settings, and the recovery of a tripped overload.
#include "controlpage.h"

#include "busclient.h"
#include "guardsettingsdialog.h"
#include "overloadrecoverydialog.h"
#include "palette.h"
#include "widgethelpers.h"

#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

using widgethelpers::actionButton;

QWidget *ControlPage::buildGuardBanner()
{
    auto *banner = new QFrame(this);
    banner->setObjectName(QStringLiteral("guardBanner"));
    banner->setFrameShape(QFrame::StyledPanel);
    auto *row = new QHBoxLayout(banner);
    row->setContentsMargins(10, 4, 10, 4);
    m_guardText = new QLabel(banner);
    m_guardText->setObjectName(QStringLiteral("guardText"));
    m_guardText->setWordWrap(true);
    m_guardText->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(m_guardText, 1);
    m_guardRecover = actionButton(tr("Recover…"), "guardRecoverButton",
                                  tr("Walks you through clearing the servo's overload trip: "
                                     "torque off and on, then a power cycle if needed."),
                                  banner);
    connect(m_guardRecover, &QPushButton::clicked, this, &ControlPage::openRecovery);
    row->addWidget(m_guardRecover);
    m_guardSettings = actionButton(tr("Guard…"), "guardSettingsButton",
                                   tr("The overload and thermal guard's limits, hold time and "
                                      "action for each servo."),
                                   banner);
    connect(m_guardSettings, &QPushButton::clicked, this, &ControlPage::openGuardSettings);
    row->addWidget(m_guardSettings);
    m_guardBanner = banner;
    connect(m_client->guard(), &feetech::BusGuard::event, this, &ControlPage::onGuardEvent);
    // A recovery of the servo shown clears its banner, from the recovery dialog or elsewhere.
    connect(m_client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        if (reply->operation() != feetech::Operation::RecoverOverload)
            return;
        connect(reply, &feetech::OperationReply::finished, this,
                [this](const feetech::OperationResult &result) {
                    if (result.ok && m_servo == std::pair(result.servo.id, result.servo.baud)) {
                        m_guardText->setText(result.message);
                        m_guardText->setPalette(QPalette());
                        m_guardRecover->hide();
                    }
                });
    });
    return banner;
}

QString ControlPage::guardText() const
{
    return m_guardText->text();
}

void ControlPage::onGuardEvent(const feetech::GuardEvent &event)
{
    if (m_servo == std::pair(event.id, event.baud))
        showGuard();
}

void ControlPage::showGuard()
{
    const auto event = m_index >= 0 ? m_client->guard()->lastEvent(m_index) : std::nullopt;
    m_guardBanner->setVisible(m_index >= 0);
    m_guardSettings->setEnabled(m_client->servoCount() > 0);
    if (!event) {
        m_guardText->setText(m_client->guard()->settings().enabled
                                 ? tr("Guard on: an overloaded servo is stopped (held where "
                                      "it stands, or its torque switched off, as set under "
                                      "Guard…); a hot one has its torque switched off.")
                                 : tr("Guard off: nothing stops an overloaded servo but its own "
                                      "protection."));
        m_guardText->setPalette(QPalette());
        m_guardRecover->hide();
        return;
    }
    m_guardText->setText(event->message);
    const bool alarm = event->stage == feetech::GuardStage::Acted
        || event->stage == feetech::GuardStage::StillLoaded
        || event->cause == feetech::GuardCause::LatchedOverload;
    QPalette colours = m_guardText->palette();
    colours.setColor(QPalette::WindowText,
                     palette::toneColor(event->stage == feetech::GuardStage::Cleared
                                            ? palette::Tone::Good
                                            : alarm ? palette::Tone::Error
                                                    : palette::Tone::Warning,
                                        palette()));
    m_guardText->setPalette(colours);
    m_guardRecover->setVisible(event->cause == feetech::GuardCause::LatchedOverload
                               && event->stage == feetech::GuardStage::Warning);
}

void ControlPage::openGuardSettings()
{
    GuardSettingsDialog dialog(m_client, this);
    if (dialog.exec() == QDialog::Accepted)
        showGuard();
}

void ControlPage::openRecovery()
{
    if (!ready())
        return;
    auto *dialog = new OverloadRecoveryDialog(m_client, m_index, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}
