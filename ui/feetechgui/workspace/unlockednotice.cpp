// The unlocked-EEPROM bar: shown while the servo's last read says lock = 0; Lock closes it.
#include "unlockednotice.h"

#include "busclient.h"
#include "palette.h"
#include "widgethelpers.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

UnlockedNotice::UnlockedNotice(feetech::BusClient *client, QWidget *parent)
    : QFrame(parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("unlockedNotice"));
    setFrameShape(QFrame::StyledPanel);
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(10, 4, 10, 4);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("unlockedText"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    row->addWidget(m_text, 1);
    m_lock = widgethelpers::actionButton(
        tr("Lock EEPROM"), "lockEepromButton",
        tr("Writes the lock register (1) and reads it back. Nothing else "
           "changes."),
        this);
    row->addWidget(m_lock);
    m_dismiss = widgethelpers::actionButton(
        tr("Dismiss"), "dismissUnlockedButton",
        tr("Hides this note for this servo until the next connection; the lock stays open."), this);
    row->addWidget(m_dismiss);
    connect(m_dismiss, &QPushButton::clicked, this, [this] {
        if (m_index >= 0 && m_index < m_client->servos()->count()) {
            m_dismissed.insert(m_client->servos()->at(m_index).info.address());
        }
        refresh();
    });
    connect(m_client, &feetech::BusClient::statusChanged, this, [this] {
        if (!m_client->link()->isConnected())
            m_dismissed.clear();
    });
    connect(m_lock, &QPushButton::clicked, this, [this] {
        feetech::Refusal refusal;
        if (m_index >= 0 && !m_client->commands()->lockEeprom(m_index, &refusal))
            emit problem(refusal.describe());
    });
    connect(m_client->servos(), &feetech::ServoList::servoUpdated, this, [this](int index) {
        if (index == m_index)
            refresh();
    });
    connect(m_client->servos(), &feetech::ServoList::servosChanged, this, &UnlockedNotice::refresh);
    hide();
}

void UnlockedNotice::showServo(int index)
{
    m_index = index;
    refresh();
}

QString UnlockedNotice::text() const
{
    return m_text->text();
}

void UnlockedNotice::refresh()
{
    const bool unlocked = m_index >= 0 && m_index < m_client->servos()->count()
        && m_client->servos()->eepromUnlocked(m_index);
    const bool noted =
        unlocked && !m_dismissed.contains(m_client->servos()->at(m_index).info.address());
    if (noted) {
        m_text->setText(tr("Note: servo %1's EEPROM is unlocked (lock = 0), as some programs "
                           "(LeRobot among them) leave it: anything written to its settings now "
                           "stays after a power cut. ServoBench locks it after each of its own "
                           "writes; Lock EEPROM locks it now.")
                            .arg(m_client->servos()->at(m_index).info.id));
        QPalette tinted = m_text->palette();
        tinted.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Accent, tinted));
        m_text->setPalette(tinted);
    }
    setVisible(noted);
}
