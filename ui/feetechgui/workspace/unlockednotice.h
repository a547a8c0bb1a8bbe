// A bar above a servo's pages when its EEPROM lock reads open, with a button that closes it.
#pragma once

#include "bustypes.h"

#include <QFrame>
#include <QSet>

class QLabel;
class QPushButton;

namespace feetech {
class BusClient;
}

// A servo whose lock is open (another program such as LeRobot leaves it so, as does a write cut
// short) keeps whatever anything writes to its EEPROM. The bar says so, as a note, as soon as a
// read shows it; Lock closes it and reads it back, Dismiss hides the note for that servo until
// the next connection. Nothing is written until the user asks.
class UnlockedNotice : public QFrame
{
    Q_OBJECT

public:
    explicit UnlockedNotice(feetech::BusClient *client, QWidget *parent = nullptr);

    void showServo(int index); // -1: none
    QPushButton *lockButton() const { return m_lock; }
    QString text() const;

signals:
    void problem(const QString &message);

private:
    void refresh();

    feetech::BusClient *m_client = nullptr;
    int m_index = -1;
    QLabel *m_text = nullptr;
    QPushButton *m_lock = nullptr;
    QPushButton *m_dismiss = nullptr;
    QSet<feetech::ServoAddress> m_dismissed; // servos noted this connection
};
