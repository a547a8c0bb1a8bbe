// servoctl feetech's commands as one object: each command group is defined in its own file
// (feetech*commands.cpp, feetechmonitorcommand.cpp), the shared steps in feetechcommands.cpp.
#pragma once

#include "armcalibration.h"
#include "exitcode.h"
#include "feetechdevice.h"
#include "parametermodel.h"
#include "profile.h"
#include "servohealth.h"
#include "settingsfile.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QStringList>
#include <QVector>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>

namespace cli {

class FeetechCommand
{
public:
    FeetechCommand(const Arguments &args, const Output &output)
        : m_args(args)
        , m_output(output)
    { }

    // `rest` is what follows "feetech": the command and its operands.
    int run(const QStringList &rest);

private:
    // A device on --port with the servo at --id identified.
    struct Target
    {
        std::unique_ptr<FeetechDevice> device;
        ServoInfo servo;
        std::chrono::microseconds latency {0};
    };

    // Shared steps (feetechcommands.cpp).
    int fail(const QString &message);
    void allowOptions(const QString &what, const QStringList &allowed) const;
    static void expectOperands(const QString &what, const QStringList &operands, int count,
                               const QString &names);
    qint32 busBaud() const;
    static qint32 parseBaud(const QString &what, const QString &text);
    quint8 servoId(const QString &what) const;
    static void checkFolder(const QString &path);
    // The servo --id at --baud; nothing, once the failure is printed, when it cannot be reached.
    std::optional<Target> identifyServo(const QString &what);
    // A warning on stderr when the servo's EEPROM lock was found open.
    // What a scan row warns of: a shared ID, error bits in the servo's answer.
    static QStringList scanWarnings(const ServoInfo &servo);
    // A note, once per servo and command, when its EEPROM lock is open.
    void noteIfUnlocked(Target &target);
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
    // What writing `items` to `servo` and reading them back came to.
    struct Programmed
    {
        QString failure; // the write did not go through (nothing verified)
        QJsonObject values; // as read back
        QJsonArray mismatches;
        QStringList described; // the mismatches in words
    };
    Programmed writeVerified(FeetechDevice &device, const ServoInfo &servo,
                             const QVector<model::WriteItem> &items);

    // Finding servos and their registers (feetechregistercommands.cpp).
    int scan(const QString &what, const QStringList &operands);
    int ping(const QString &what, const QStringList &operands);
    int read(const QString &what, const QStringList &operands);
    int get(const QString &what, const QStringList &operands);
    int set(const QString &what, const QStringList &operands);

    // Profiles (feetechprofilecommands.cpp).
    std::optional<profile::Profile> takeProfile(Target &target, QString *error);
    QJsonObject profileJson(const profile::Profile &saved) const;
    int save(const QString &what, const QStringList &operands);
    static feetech::SettingsFile checkSettingsFile(const QString &path);
    int load(const QString &what, const QStringList &operands);

    // Arms of several servos (feetechrobotcommands.cpp).
    int identify(const QString &what, const QStringList &operands);
    int loadMany(const feetech::SettingsFile &file, const QString &path);
    // The values of `wanted` that `servo` does not hold yet (it is read whole); nothing and
    // *error when it cannot be read.
    static std::optional<QVector<model::WriteItem>>
    changedOn(FeetechDevice &device, const ServoInfo &servo,
              const QVector<model::WriteItem> &wanted, QString *error,
              std::optional<qint64> *torque = nullptr);
    feetech::ProgramOutcome programOne(FeetechDevice &device, quint8 id,
                                       const feetech::SettingsFile &file);

    // Guided flows (feetechflowcommands.cpp).
    int report(Target &target, const std::function<void()> &start,
               const std::function<void(QJsonObject &, const Memory &)> &more = {});
    int alreadyDone(const ServoInfo &servo, const QString &message);
    int setId(const QString &what, const QStringList &operands);
    int setBaud(const QString &what, const QStringList &operands);
    int calibrateMiddle(const QString &what, const QStringList &operands);
    int factoryReset(const QString &what, const QStringList &operands);
    int reboot(const QString &what, const QStringList &operands);
    int lock(const QString &what, const QStringList &operands);
    int recover(const QString &what, const QStringList &operands);

    // Setting up one motor of a robot (feetechsetupcommand.cpp).
    feetech::MotorTarget motorTarget(const QString &what) const;
    int setupMotor(const QString &what, const QStringList &operands);
    // Arm calibration and LeRobot calibration files (feetechcalibrationcommands.cpp,
    // feetechcalibrationfilecommands.cpp).
    QVector<quint8> jointIds(const QString &what) const;
    QStringList jointNames(const QVector<quint8> &ids) const;
    std::optional<QVector<ServoInfo>> identifyJoints(FeetechDevice &device,
                                                     const QVector<quint8> &ids);
    int calibrate(const QString &what, const QStringList &operands);
    bool recordJoints(FeetechDevice &device, const QVector<ServoInfo> &servos,
                      QVector<feetech::JointRecording> &joints, std::optional<double> duration);
    void printRecording(const QVector<feetech::JointRecording> &joints, bool live);
    int calibration(const QString &what, const QStringList &operands);
    int saveCalibration(const QString &what, const QStringList &operands);
    int loadCalibration(const QString &what, const QStringList &operands);

    // The health check (feetechhealthcommand.cpp).
    int health(const QString &what, const QStringList &operands);
    void printHealth(const feetech::ServoHealth &health, bool moveAsked);

    // Live feedback (feetechmonitorcommand.cpp).
    int monitor(const QString &what, const QStringList &operands);
    double monitorRate() const;
    void printSample(const feetech::FeedbackSample &sample, qint64 startUs,
                     const QVector<ServoInfo> &servos);

    const Arguments &m_args;
    const Output &m_output;
    QSet<quint8> m_unlockedNoted; // servos whose open EEPROM lock was noted
};

} // namespace cli
