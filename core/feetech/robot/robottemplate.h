// Robot templates: an arm's joints (name, ID, model, full turn) and the settings set-up applies.
#pragma once

#include "feetechpacket.h"
#include "fileerror.h"
#include "motorsetup.h"
#include "registertable.h"
#include "settingscheck.h"

#include <QByteArray>
#include <QMap>
#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

struct RobotJoint
{
    QString name; // snake_case, as LeRobot names its motors: "shoulder_pan"
    int id = 1;
    QString model; // as the model table names it: "STS3215"
    bool fullTurn = false; // turns without end stops (a wrist roll): calibrated 0-4095
    // Register values (register units, by key) written and verified at set-up: the template's
    // common settings with the joint's own on top.
    QMap<QString, qint32> settings;
    // Bits to clear (a mask per register key), the register's other bits kept: the template's
    // common ones with the joint's own on top. Phase bit 4 (multi-turn feedback), say.
    QMap<QString, quint32> clearedBits;
};

struct RobotTemplate
{
    QString name; // "SO-101 follower arm"
    qint32 baud = 1000000; // every joint's rate after set-up
    QVector<RobotJoint> joints;

    const RobotJoint *joint(QStringView name) const;
};

// Parses and validates a template: format, names, unique IDs, known models with a register
// table, and every setting a writable register of that model within its range (the ID, the baud
// rate, the lock and torque enable are set by the flows, never by a template); every bit to
// clear a bit of such a register. On failure
// nothing, and *error naming `source` and the joint and field at fault.
std::optional<RobotTemplate> robotTemplateFromJson(const QByteArray &json, const QString &source,
                                                   util::FileError *error);
// The file format robotTemplateFromJson reads; common settings are written out per joint.
// What motor set-up makes of `joint` of `robot`: its ID, the robot's rate, its model and settings.
MotorTarget motorTarget(const RobotTemplate &robot, const RobotJoint &joint);
// What a check of the robot's joints looks for: each joint's ID, model and settings.
QVector<JointCheck> jointChecks(const RobotTemplate &robot);

// What the settings check expects of each joint, by ID: its settings and its bits to clear.
SettingsExpectations settingsExpectations(const RobotTemplate &robot);

QByteArray robotTemplateToJson(const RobotTemplate &robot);

// The templates compiled into the application (SO-100 and SO-101 follower and leader arms).
const QVector<RobotTemplate> &builtInRobotTemplates();
// A template from a file a user saved; nothing and *error (naming the file) when unreadable.
std::optional<RobotTemplate> loadRobotTemplate(const QString &path, util::FileError *error);
// Saves atomically; false and *error (naming the file) when it could not.
bool saveRobotTemplate(const RobotTemplate &robot, const QString &path, util::FileError *error);

// A shipped template's name ("SO-101 follower arm") or joint name ("shoulder_pan") as the user's
// language shows it. Files, calibration data and lookups keep the names as they are; only what
// is shown goes through these. resources/translations/datastrings.cpp lists them for lupdate.
QString robotDisplayName(const QString &name);
QString jointDisplayName(const QString &name);

// Where templates a user saves live: <app data>/robots (ServoBench lists its *.json files).
QString userRobotTemplateFolder();
// The built-in templates, then every valid template in userRobotTemplateFolder() by file name;
// a file there that cannot be read adds its error to *problems and is skipped.
QVector<RobotTemplate> availableRobotTemplates(QStringList *problems = nullptr);
// The template every window offers first, so that the set-up wizard, Apply template and the
// calibration wizard name the same arm: the SO-101 follower (LeRobot's current arm, and the
// demo's) when it is among `templates`, else the first; -1 when there is none.
int defaultRobotTemplate(const QVector<RobotTemplate> &templates);
// That template itself, null when there is none.
const RobotTemplate *defaultRobotTemplateIn(const QVector<RobotTemplate> &templates);

} // namespace feetech
