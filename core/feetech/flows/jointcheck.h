// One joint of a robot as a check of the bus sees it: is its servo set up already?
#pragma once

#include "bustypes.h"

#include <QMap>
#include <QMetaType>
#include <QString>
#include <QStringList>

#include <optional>

namespace feetech {

// One joint as a check of the bus sees it: is its servo already set up, at its ID and rate?
struct JointCheck
{
    int id = 0;
    QString model; // the model the joint needs
    // The joint's settings; those kept in EEPROM are compared (RAM ones start afresh at
    // power-up, so they say nothing about an earlier set-up).
    QMap<QString, qint32> settings;
    std::optional<ServoInfo> found; // who answers at that ID at the template's rate
    QStringList differing; // "p_gain is 32, not 16": EEPROM settings that do not hold
    QMap<QString, quint32> clearedBits; // bits of EEPROM registers that must be clear

    bool done() const;
    // Why a servo at the joint's ID is not set up as the joint (empty when done or nothing
    // answers).
    QString problem() const;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::JointCheck)
