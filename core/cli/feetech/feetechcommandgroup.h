// What every group of servoctl feetech commands shares: the arguments and output, the option
// checks, reaching the servo --id and writing to it with read-back.
#pragma once

#include "exitcode.h"
#include "feetechdevice.h"
#include "parametermodel.h"
#include "profile.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QStringList>
#include <QVector>

#include <chrono>
#include <memory>
#include <optional>

namespace cli {

// A group's commands take the command's name as `what` (for its messages) and its operands.
// One group object serves one command.
class FeetechCommandGroup
{
public:
    FeetechCommandGroup(const Arguments &args, const Output &output)
        : m_args(args)
        , m_output(output)
    { }

protected:
    // A device on --port with the servo at --id identified.
    struct Target
    {
        std::unique_ptr<FeetechDevice> device;
        ServoInfo servo;
        std::chrono::microseconds latency {0};
    };

    // What writing `items` to `servo` and reading them back came to.
    struct Programmed
    {
        QString failure; // the write did not go through (nothing verified)
        QJsonObject values; // as read back
        QJsonArray mismatches;
        QStringList described; // the mismatches in words
    };

    // Prints the failure; ExitDeviceFailure.
    int fail(const QString &message);
    void allowOptions(const QString &what, const QStringList &allowed) const;
    static void expectOperands(const QString &what, const QStringList &operands, int count,
                               const QString &names);
    qint32 busBaud() const;
    static qint32 parseBaud(const QString &what, const QString &text);
    quint8 servoId(const QString &what) const;
    static void checkFolder(const QString &path);
    // --ids LIST: the joints, each once.
    QVector<quint8> jointIds(const QString &what) const;

    // The servo --id at --baud; nothing, once the failure is printed, when it cannot be reached.
    std::optional<Target> identifyServo(const QString &what);
    // The same, refusing a servo of a model no table describes with `unknownModel` (%1: its ID,
    // %2: its model).
    std::optional<Target> identifyKnownServo(const QString &what, const QString &unknownModel);
    // The servo set and load write to.
    std::optional<Target> identifyServoToWrite(const QString &what);
    // Whether several servos answer at the servo's ID (then said, as the command's failure):
    // nothing is written to a shared ID.
    bool sharesItsId(FeetechDevice &device, const ServoInfo &servo);

    int program(Target &target, const QVector<model::WriteItem> &items,
                const QJsonObject &extra = {});
    Programmed writeVerified(FeetechDevice &device, const ServoInfo &servo,
                             const QVector<model::WriteItem> &items);
    // The servo's profile values as read now (save, and the backup before a factory reset).
    std::optional<profile::Profile> takeProfile(Target &target, QString *error);

    const Arguments &m_args;
    const Output &m_output;

private:
    // A note, once per servo and command, when its EEPROM lock is open.
    void noteIfUnlocked(Target &target);

    QSet<quint8> m_unlockedNoted; // servos whose open EEPROM lock was noted
};

} // namespace cli
