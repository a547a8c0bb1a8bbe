// What servoctl's calibration commands share: reading a joint's calibration registers, and
// reporting their verified writes.
#pragma once

#include "feetechdevice.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>

#include <optional>

namespace cli {

// Register values by key: the position offset, the angle limits and torque enable of `servo`.
std::optional<QHash<QString, qint32>> readCalibrationRegisters(FeetechDevice &device,
                                                               const ServoInfo &servo);

// What FeetechCommand::writeVerified came to, for the calibration commands' reports.
template<typename Programmed>
bool isVerified(const Programmed &outcome)
{
    return outcome.failure.isEmpty() && outcome.mismatches.isEmpty();
}
template<typename Programmed>
QString problemText(const Programmed &outcome)
{
    return outcome.failure.isEmpty() ? outcome.described.join(QStringLiteral("; "))
                                     : outcome.failure;
}
// written, verified, mismatches (and error); both false when the write was not attempted.
template<typename Programmed>
QJsonObject writeJson(const Programmed &outcome, bool attempted)
{
    QJsonObject object {{QStringLiteral("written"), attempted && outcome.failure.isEmpty()},
                        {QStringLiteral("verified"), attempted && isVerified(outcome)},
                        {QStringLiteral("mismatches"), outcome.mismatches}};
    if (!outcome.failure.isEmpty())
        object.insert(QStringLiteral("error"), outcome.failure);
    return object;
}

} // namespace cli
