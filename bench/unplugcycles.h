// Unplug cycles: the port disappearing and coming back (the simulator stopped and started again
// on the same path) in the middle of each kind of work, through the clients the GUI uses and
// through servoctl; what each cycle found wrong, and the process's threads, open files and
// memory before and after.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVector>

namespace unplug {

enum class Work {
    PtkPolling, // ptk::Client polling
    PtkApply, // ptk::Client writing its twelve frames
    FeetechScan, // feetech::BusClient scanning IDs 0-253
    FeetechApply, // an EEPROM write (unlock, write, lock, read back)
    FeetechFlow, // the reboot flow, waiting for the servo to come back
    FeetechStream, // telemetry at 50 Hz
    ServoctlMonitor, // servoctl feetech monitor, in this process
    ServoctlSet, // servoctl feetech set (an EEPROM write), in this process
};

QVector<Work> allWork();
QString workName(Work work); // "ptk-polling", ...

// What this process holds now.
struct Resources
{
    int threads = 0;
    int openFiles = 0;
    double residentMb = 0;
};
Resources resourcesNow();

struct CycleReport
{
    Work work = Work::PtkPolling;
    int cycles = 0;
    int problems = 0; // cycles with something wrong: a hang, a wrong value, no reconnection
    QStringList examples; // the first few, in words
    // After the first cycle (the first connection opens what stays open) and after the last.
    Resources first;
    Resources last;
    QJsonObject toJson() const;
};

// Runs `cycles` unplug cycles of `work`, each on a simulator that is stopped in the middle of
// it and started again: nothing may hang, the client must see the port go and reconnect, and
// what it shows afterwards must be what the simulator holds.
CycleReport runCycles(Work work, int cycles);

} // namespace unplug
