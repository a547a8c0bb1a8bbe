// A file of servo settings to program into one servo or many: a profile (the same values for
// every servo of its family) or a robot template (each servo gets its joint's settings by ID).
#pragma once

#include "bustypes.h"
#include "fileerror.h"
#include "parametermodel.h"
#include "robottemplate.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <QVector>

#include <functional>
#include <optional>

namespace feetech {

class SettingsFile
{
public:
    // Reads and checks `path` before anything is sent: a robot template (its "format" says so)
    // checked as robotTemplateFromJson checks it, else a profile valid for at least one Feetech
    // family. Nothing and *error (naming the file and the problem) when it is neither.
    static std::optional<SettingsFile> load(const QString &path, util::FileError *error);
    // The same check of a file's contents; `source` names it in messages.
    static std::optional<SettingsFile> fromJson(const QByteArray &json, const QString &source,
                                                util::FileError *error);
    static SettingsFile fromTemplate(const RobotTemplate &robot);

    bool isTemplate() const { return m_robot.has_value(); }
    const std::optional<RobotTemplate> &robot() const { return m_robot; }
    const QString &source() const { return m_source; }

    // The register values (register units, by key) `servo` should hold. Nothing and *error
    // when the file does not fit it: a profile of another family, a template with no joint of
    // the servo's ID, or a joint of another model.
    std::optional<QVector<model::WriteItem>> valuesFor(const ServoInfo &servo,
                                                       QString *error) const;
    // valuesFor when several servos are programmed: a profile's position_offset is one servo's
    // calibration, not a setting to copy, so it is left out (its key added to *leftOut).
    std::optional<QVector<model::WriteItem>>
    batchValuesFor(const ServoInfo &servo, QStringList *leftOut, QString *error) const;
    // The bits the template's joint of `servo`'s ID clears (a mask per register key); none for a
    // profile.
    QMap<QString, quint32> clearedBitsFor(const ServoInfo &servo) const;

private:
    QString m_source; // the file, for messages
    QByteArray m_profile; // a profile's JSON, parsed again per family
    std::optional<RobotTemplate> m_robot;
};

// The values of `wanted` that `current` (the servo's value of a key, none when unknown) does not
// already hold, then each register of `cleared` whose current value has any of its bits set,
// with them cleared: what programming the servo writes.
QVector<model::WriteItem>
changedValues(const QVector<model::WriteItem> &wanted,
              const std::function<std::optional<qint64>(const QString &key)> &current,
              const QMap<QString, quint32> &cleared = {});

// Why `changed` may not be written to `servo` whose torque_enable holds `torque` (none when it was
// not read): under torque a new offset, limit, goal or phase moves the horn. Empty when it may.
QString torqueRefusal(const ServoInfo &servo, const QVector<model::WriteItem> &changed,
                      std::optional<qint64> torque);

// What programming one servo of many came to.
struct ProgramOutcome
{
    enum class Status { Ok, Unchanged, Failed };
    quint8 id = 0;
    qint32 baud = 0;
    Status status = Status::Failed;
    QStringList changed; // the keys written (or that were to be, when it failed)
    QString error; // why it failed, for the user
    QStringList leftOut; // the file's keys not written to any servo (a profile's offset)
};
// What the outcomes left out of the file and why, for the result (empty when nothing was).
QString leftOutNote(const QVector<ProgramOutcome> &outcomes);
// "ok", "unchanged", "failed": the words servoctl's JSON uses.
QString statusKey(ProgramOutcome::Status status);
// The same for people (translated).
QString statusText(ProgramOutcome::Status status);

} // namespace feetech
