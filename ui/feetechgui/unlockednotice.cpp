// The unlocked-EEPROM bar: shown while the servo's last read says lock = 0; Lock closes it.
#include "feetechgui/unlockednotice.h"

#include "common/palette.h"
#include "common/widgethelpers.h"
#include "feetech/busclient.h"

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
    connect(m_lock, &QPushButton::clicked, this, [this] {
        QString error;
        if (m_index >= 0 && !m_client->lockEeprom(m_index, &error))
            emit problem(error);
    });
    connect(m_client, &feetech::BusClient::servoUpdated, this, [this](int index) {
        if (index == m_index)
            refresh();
    });
    connect(m_client, &feetech::BusClient::servosChanged, this, &UnlockedNotice::refresh);
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
    const bool unlocked =
        m_index >= 0 && m_index < m_client->servoCount() && m_client->eepromUnlocked(m_index);
    if (unlocked) {
        m_text->setText(tr("Servo %1's EEPROM is unlocked (lock = 0), as a write cut short "
                           "leaves it: anything written to its settings now stays after a power "
                           "cut, a stray write included. ServoBench locks it after each of its own "
                           "writes.")
                            .arg(m_client->servo(m_index).info.id));
        QPalette tinted = m_text->palette();
        tinted.setColor(QPalette::WindowText, palette::toneColor(palette::Tone::Warning, tinted));
        m_text->setPalette(tinted);
    }
    setVisible(unlocked);
}
