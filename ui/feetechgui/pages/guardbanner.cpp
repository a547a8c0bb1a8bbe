// The Control page's guard banner: what the overload and thermal guard last said about the
// servo shown, its settings, and the recovery of a tripped overload.
#include "guardbanner.h"

#include "busclient.h"
#include "guardsettingsdialog.h"
#include "overloadrecoverydialog.h"
#include "palette.h"
#include "widgethelpers.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

using widgethelpers::actionButton;

GuardBanner::GuardBanner(feetech::BusClient *client, QWidget *parent)
    : QFrame(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("guardBanner"));
    setFrameShape(QFrame::StyledPanel);
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(10, 4, 10, 4);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("guardText"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(m_text, 1);
    m_recover = actionButton(tr("Recover…"), "guardRecoverButton",
                             tr("Walks you through clearing the servo's overload trip: "
                                "torque off and on, then a power cycle if needed."),
                             this);
    connect(m_recover, &QPushButton::clicked, this, &GuardBanner::openRecovery);
    row->addWidget(m_recover);
    m_settings = actionButton(tr("Guard…"), "guardSettingsButton",
                              tr("The overload and thermal guard's limits, hold time and "
                                 "action for each servo."),
                              this);
    connect(m_settings, &QPushButton::clicked, this, &GuardBanner::openGuardSettings);
    row->addWidget(m_settings);
    connect(m_client->guard(), &feetech::BusGuard::event, this, &GuardBanner::onGuardEvent);
    connect(m_client->servos(), &feetech::ServoList::servosChanged, this,
            &GuardBanner::onServosChanged);
    // A recovery of the servo shown clears the banner, from the recovery dialog or elsewhere.
    connect(m_client, &feetech::BusClient::submitted, this, [this](feetech::OperationReply *reply) {
        if (reply->operation() != feetech::Operation::RecoverOverload)
            return;
        connect(reply, &feetech::OperationReply::finished, this,
                [this](const feetech::OperationResult &result) {
                    if (result.ok && m_servo == result.servo.address()) {
                        m_text->setText(result.message);
                        m_text->setPalette(QPalette());
                        m_recover->hide();
                    }
                });
    });
}

void GuardBanner::setServo(int index)
{
    m_index = index;
    m_servo = index >= 0 ? std::make_optional(m_client->servos()->at(index).info.address())
                         : std::nullopt;
    showGuard();
}

QString GuardBanner::text() const
{
    return m_text->text();
}

void GuardBanner::onServosChanged()
{
    // The list was rebuilt or reordered: find the servo shown by its address.
    m_index = m_servo ? m_client->servos()->indexOf(*m_servo) : -1;
    if (m_index < 0)
        m_servo.reset();
}

void GuardBanner::onGuardEvent(const feetech::GuardEvent &event)
{
    if (m_servo == feetech::ServoAddress {event.id, event.baud})
        showGuard();
}

void GuardBanner::showGuard()
{
    const auto event = m_index >= 0 ? m_client->guard()->lastEvent(m_index) : std::nullopt;
    setVisible(m_index >= 0);
    m_settings->setEnabled(m_client->servos()->count() > 0);
    if (!event) {
        m_text->setText(m_client->guard()->settings().enabled
                            ? tr("Guard on: an overloaded servo is stopped (held where "
                                 "it stands, or its torque switched off, as set under "
                                 "Guard…); a hot one has its torque switched off.")
                            : tr("Guard off: nothing stops an overloaded servo but its own "
                                 "protection."));
        m_text->setPalette(QPalette());
        m_recover->hide();
        return;
    }
    m_text->setText(event->message);
    const bool alarm = event->stage == feetech::GuardStage::Acted
        || event->stage == feetech::GuardStage::StillLoaded
        || event->cause == feetech::GuardCause::LatchedOverload;
    QPalette colours = m_text->palette();
    colours.setColor(QPalette::WindowText,
                     palette::toneColor(event->stage == feetech::GuardStage::Cleared
                                            ? palette::Tone::Good
                                            : alarm ? palette::Tone::Error
                                                    : palette::Tone::Warning,
                                        palette()));
    m_text->setPalette(colours);
    m_recover->setVisible(event->cause == feetech::GuardCause::LatchedOverload
                          && event->stage == feetech::GuardStage::Warning);
}

void GuardBanner::openGuardSettings()
{
    GuardSettingsDialog dialog(m_client, this);
    if (dialog.exec() == QDialog::Accepted)
        showGuard();
}

void GuardBanner::openRecovery()
{
    // Connected, a servo with a known table: as the page asks before it moves one.
    if (!m_client->link()->isConnected() || m_index < 0 || m_index >= m_client->servos()->count()
        || !m_client->servos()->at(m_index).info.hasTable())
        return;
    auto *dialog = new OverloadRecoveryDialog(m_client, m_index, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->open();
}
