// Alerts a shared bus raises from what its traffic shows: heat, supply, overload, risky writes.
#pragma once

#include "observedservos.h"
#include "sharealert.h"
#include "sharedtransaction.h"

#include <QHash>
#include <QJsonObject>
#include <QMetaType>
#include <QSet>
#include <QString>
#include <QVector>

namespace share {

// An alert is raised once and stays quiet until its condition has cleared (a servo that cooled
// down, a reply without the bit); writes that are risky in themselves (phase bit 4, torque on
// far from the goal) raise one each time.
class ShareAlerts
{
public:
    // How far the goal may be from the present position when torque goes on (steps).
    static constexpr int kJumpSteps = 100;
    // Degrees Celsius below the servo's maximum at which its temperature is reported.
    static constexpr int kTemperatureMargin = 5;
    // How long an EEPROM may stay unlocked after a program unlocked it.
    static constexpr qint64 kUnlockedUs = 3000000;
    // Garbled answers at one ID before it counts as shared by two servos.
    static constexpr int kGarbledAnswers = 3;

    // What the transaction (already learned by `servos`) shows.
    QVector<ShareAlert> inspect(const SharedTransaction &transaction, const ObservedServos &servos);
    // What time passing shows: an EEPROM still unlocked.
    QVector<ShareAlert> tick(qint64 nowUs);

    int raisedCount() const { return m_raised; }

private:
    // Raises `code` for `id` unless it is raised already; `when` false clears it.
    void set(QVector<ShareAlert> &alerts, bool when, const QString &code, quint8 id,
             const QString &message, qint64 timeUs);
    void raise(QVector<ShareAlert> &alerts, const QString &code, quint8 id, const QString &message,
               qint64 timeUs);
    void inspectServo(QVector<ShareAlert> &alerts, quint8 id, const ObservedServos &servos,
                      qint64 timeUs);
    void inspectWrites(QVector<ShareAlert> &alerts, const SharedTransaction &transaction,
                       const ObservedServos &servos);

    QSet<QString> m_active; // "code/id"
    QHash<quint8, qint64> m_unlockedSinceUs;
    QHash<quint8, int> m_garbled;
    int m_raised = 0;
};

} // namespace share
