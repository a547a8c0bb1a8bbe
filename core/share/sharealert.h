// One alert from a shared bus's traffic: its code, the servo, its message, its time; as JSON.
#pragma once

#include <QJsonObject>
#include <QMetaType>
#include <QString>

namespace share {

struct ShareAlert
{
    QString code; // temperature-high, voltage-out-of-range, overload, reply-error, multi-turn,
                  // torque-jump, eeprom-unlocked, shared-id
    quint8 id = 0;
    QString message; // translated, says what it means for the arm
    qint64 timeUs = 0; // since the share began

    QJsonObject toJson() const; // {"alert": code, "id": N, "message": ...}
};

} // namespace share

Q_DECLARE_METATYPE(share::ShareAlert)
