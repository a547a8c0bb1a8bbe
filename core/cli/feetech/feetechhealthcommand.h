// servoctl feetech health and check: the health check of servos --ids (with --move-test their
// move test), and the settings check (with --robot against a template, with --fix the fixes).
#pragma once

#include "feetechcommandgroup.h"
#include "servohealth.h"
#include "settingscheck.h"

namespace cli {

class FeetechHealthCommand : public FeetechCommandGroup
{
public:
    using FeetechCommandGroup::FeetechCommandGroup;

    int health(const QString &what, const QStringList &operands);
    int check(const QString &what, const QStringList &operands);

private:
    // Each of `ids` identified at the bus's rate: its ServoInfo, or why it could not be.
    struct Identified
    {
        ServoInfo servo;
        QString failure;
    };
    QVector<Identified> identifyEach(FeetechDevice &device, const QVector<quint8> &ids);
    // What a reading operation (the health check's, the settings check's) reported of each of
    // `ids`, in their order, and the servos that answered; a servo that did not keeps its
    // failure. Nothing, once the failure is printed, when the operation failed.
    template<typename Reading>
    struct Readings
    {
        QVector<Reading> readings;
        QVector<ServoInfo> reachable;
    };
    template<typename Reading>
    std::optional<Readings<Reading>>
    readEach(FeetechDevice &device, const QVector<quint8> &ids,
             const std::function<feetech::BusOperation(const QVector<ServoInfo> &)> &operation);
    // --robot: a built-in template's file name without .json ("so101-follower") or a file.
    feetech::SettingsExpectations expectations(const QString &what) const;
    void printFindings(const QVector<feetech::SettingsFinding> &findings, int servos);
    void printFixes(const QVector<feetech::SettingsFixOutcome> &outcomes);
    void printHealth(const feetech::ServoHealth &health, bool moveAsked);
};

} // namespace cli
