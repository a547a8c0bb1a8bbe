// The settings check: what keeps a servo from moving or makes it misbehave (multi-turn phase bit,
// torque limits at 0, a mode other than position, angle limits, a slow return delay, an open
// EEPROM, template differences, mixed firmware, voltage limits the supply breaks), each a finding
// with the value that fixes it where one does.
#pragma once

#include "bustypes.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QMap>
#include <QMetaType>
#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

// What the settings check read of one servo: every register of its table in the one READ the
// check makes (register units, by key), and the supply it measured.
struct SettingsReading
{
    ServoInfo servo;
    QString failure; // it could not be read: nothing else is known
    QMap<QString, qint32> values;
};

// What a robot template asks of each joint, by ID: register values in register units.
struct SettingsExpectations
{
    QString source; // the template's name, for the findings' reasons
    QMap<quint8, QMap<QString, qint32>> byId;
    QMap<quint8, QMap<QString, quint32>> clearedBitsById; // bits that must be clear, by key

    // Every register key they name: what the check must read beyond its own.
    QStringList keys() const;
};

struct SettingsFinding
{
    ServoInfo servo;
    // Stable: "multi-turn", "torque-limit-zero", "max-torque-zero", "mode", "angle-limits-zero",
    // "angle-limits-order", "return-delay", "unlocked", "template", "firmware-mismatch",
    // "voltage-limit", "unreadable".
    QString code;
    QString key; // the register; empty when the finding is about no one register
    std::optional<qint32> value; // as read, register units
    QString valueText; // what was read when it is no register value (the firmware)
    std::optional<qint32> expected; // what fixes it; none: nothing to write fixes it
    QString why; // translated
    // Writing it with torque on could move the horn (limits, offset, mode, torque limit, phase).
    bool needsTorqueOff = false;

    bool fixable() const { return expected.has_value(); }
};

// Registers whose change with torque on could move the horn: a fix refuses them then.
bool needsTorqueOff(const QString &key);

// The findings of each reading, in the readings' order and by register address within a servo.
// A template setting that a rule already covers gives that rule's finding, with the template's
// value as the one expected.
QVector<SettingsFinding> checkSettings(const QVector<SettingsReading> &readings,
                                       const SettingsExpectations &expected = {});

// How the fix of one finding went.
struct SettingsFixOutcome
{
    enum class Code {
        Verified, // written and read back as expected
        TorqueOn, // refused: torque is on, and the write could move the horn
        NotVerified, // written, but it reads back otherwise
        Failed, // the write or its read-back went unanswered, or the servo refused it
        NotFixable, // nothing to write fixes it
    };
    SettingsFinding finding;
    Code code = Code::Failed;
    std::optional<qint32> readBack;
    QString why; // translated; what happened, when not verified

    bool verified() const { return code == Code::Verified; }
};

// {"id", "baud", "code", "key", "value", "expected", "why"} (nulls for what is not known).
QJsonObject settingsFindingJson(const SettingsFinding &finding);
// The same with "fixed" (true when verified) and "result" (the outcome's sentence).
QJsonObject settingsFixJson(const SettingsFixOutcome &outcome);
// "verified", or why not.
QString fixOutcomeText(const SettingsFixOutcome &outcome);

} // namespace feetech

Q_DECLARE_METATYPE(feetech::SettingsReading)
Q_DECLARE_METATYPE(feetech::SettingsFinding)
Q_DECLARE_METATYPE(QVector<feetech::SettingsFixOutcome>)
