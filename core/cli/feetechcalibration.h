// What servoctl's calibration commands share: reading and writing a joint's calibration
// registers with read-back.
#pragma once

#include "cli/feetechdevice.h"
#include "model/parametermodel.h"

#include <QHash>
#include <QJsonObject>
#include <QStringList>

#include <optional>

namespace cli {

// Register values by key: the position offset, the angle limits and torque enable of `servo`.
std::optional<QHash<QString, qint32>> readCalibrationRegisters(FeetechDevice &device,
                                                               const ServoInfo &servo);

struct WriteOutcome
{
    QString error; // the write could not be done (nothing or not everything was written)
    QStringList mismatches; // written, but read back differently
    bool ok() const { return error.isEmpty() && mismatches.isEmpty(); }
    QString problem() const
    {
        return error.isEmpty() ? mismatches.join(QStringLiteral("; ")) : error;
    }
};

// Writes `items` through the session's write (EEPROM ones unlocked, written, locked again) and
// compares what the servo reads back.
WriteOutcome writeVerified(FeetechDevice &device, const ServoInfo &servo,
                           const QVector<model::WriteItem> &items);
// written, verified, mismatches (and error) of a write; both false when it was not attempted.
QJsonObject writeJson(const WriteOutcome &outcome, bool attempted);

} // namespace cli
