// The settings check's reads and fixes, built from BusExchange steps.
#include "settingsbus.h"

#include "feetechvalue.h"
#include "registerkeys.h"
#include "settingschecktr.h"

#include <QCoreApplication>

#include <algorithm>
#include <memory>

namespace feetech {

namespace {

const QString kLockKey = QStringLiteral("lock");

struct FixRun
{
    std::shared_ptr<ServoInfo> servo;
    QVector<SettingsFixOutcome> outcomes;
    std::function<void(const QVector<SettingsFixOutcome> &)> done;
    std::optional<qint32> torque;
};

void failUnsettled(FixRun &run, const QString &message)
{
    for (SettingsFixOutcome &outcome : run.outcomes) {
        if (outcome.code == SettingsFixOutcome::Code::Failed && outcome.why.isEmpty())
            outcome.why = message;
    }
}

void writeFixes(BusExchange &bus, std::shared_ptr<FixRun> run)
{
    const bool torqueOn = run->torque.value_or(0) != 0;
    QVector<int> toWrite;
    bool eeprom = false;
    for (int i = 0; i < run->outcomes.size(); ++i) {
        SettingsFixOutcome &outcome = run->outcomes[i];
        if (outcome.code != SettingsFixOutcome::Code::Failed)
            continue;
        if (outcome.finding.needsTorqueOff && torqueOn) {
            outcome.code = SettingsFixOutcome::Code::TorqueOn;
            outcome.why = SettingsCheckTr::tr(
                              "not written: torque is on, and writing %1 could move the horn; "
                              "switch the torque off first")
                              .arg(outcome.finding.key);
            continue;
        }
        toWrite.append(i);
        const Register *reg = registerAt(*run->servo, outcome.finding.key);
        if (reg && reg->storage == Storage::Eeprom)
            eeprom = true;
    }
    if (toWrite.isEmpty()) {
        run->done(run->outcomes);
        return;
    }
    std::vector<Step> steps;
    bool closeLock = eeprom;
    if (eeprom)
        steps.push_back(bus.lock(run->servo, false));
    QStringList keys;
    for (const int i : std::as_const(toWrite)) {
        const SettingsFinding &finding = run->outcomes.at(i).finding;
        keys.append(finding.key);
        if (finding.key == kLockKey)
            closeLock = true; // the lock step below is its write
        else
            steps.push_back(bus.writeValue(run->servo, finding.key, *finding.expected, [] {}));
    }
    if (closeLock)
        steps.push_back(bus.lock(run->servo, true));
    for (Step &step : bus.readValues(run->servo, keys, [run](const QString &key, qint32 value) {
             for (SettingsFixOutcome &outcome : run->outcomes) {
                 if (outcome.finding.key == key)
                     outcome.readBack = value;
             }
         }))
        steps.push_back(std::move(step));
    bus.runSteps(std::move(steps), [&bus, run, toWrite, eeprom](bool ok, const QString &message) {
        for (const int i : toWrite) {
            SettingsFixOutcome &outcome = run->outcomes[i];
            if (!outcome.readBack)
                continue;
            if (*outcome.readBack == *outcome.finding.expected) {
                outcome.code = SettingsFixOutcome::Code::Verified;
            } else {
                outcome.code = SettingsFixOutcome::Code::NotVerified;
                outcome.why = SettingsCheckTr::tr("written, but it reads back %1, not %2")
                                  .arg(*outcome.readBack)
                                  .arg(*outcome.finding.expected);
            }
        }
        if (ok) {
            run->done(run->outcomes);
            return;
        }
        failUnsettled(*run, SettingsCheckTr::tr("not verified: %1").arg(message));
        if (!eeprom) {
            run->done(run->outcomes);
            return;
        }
        // A write that failed after the unlock must not leave the EEPROM open.
        bus.runSteps({BusExchange::tolerant(bus.lock(run->servo, true))},
                     [run](bool, const QString &) { run->done(run->outcomes); });
    });
}

} // namespace

void readSettings(BusExchange &bus, const ServoInfo &servo, const QStringList &keys,
                  std::function<void(const SettingsReading &)> done)
{
    auto reading = std::make_shared<SettingsReading>();
    reading->servo = servo;
    if (!servo.hasTable()) {
        reading->failure = SettingsCheckTr::tr("ServoBench has no register table for model %1.")
                               .arg(servo.model.name);
        done(*reading);
        return;
    }
    const RegisterTable &table = servo.table();
    int end = 0;
    for (const QString &key : QStringList {QStringLiteral("present_voltage")} + keys) {
        if (const Register *reg = table.find(key))
            end = std::max(end, reg->end());
    }
    auto target = std::make_shared<ServoInfo>(servo);
    std::vector<Step> steps {bus.setBaud(servo.baud)};
    // Block by block: a servo may refuse one READ of everything.
    for (const Block &block : table.blocks()) {
        if (block.address >= end)
            continue;
        const int first = block.address;
        steps.push_back(bus.read(
            target, first, block.size, ReadSource::Read, [reading, first](const QByteArray &bytes) {
                const RegisterTable &table = reading->servo.table();
                for (const Register &reg : table.registers()) {
                    if (reg.address < first || reg.end() > first + bytes.size())
                        continue;
                    reading->values.insert(
                        reg.key,
                        decodeValue(bytes.mid(reg.address - first, reg.size), table.format(reg)));
                }
            }));
    }
    bus.runSteps(std::move(steps), [reading, done](bool ok, const QString &message) {
        if (!ok) {
            reading->values.clear();
            reading->failure = message;
        }
        done(*reading);
    });
}

void fixSettings(BusExchange &bus, const QVector<SettingsFinding> &findings,
                 std::function<void(const QVector<SettingsFixOutcome> &)> done)
{
    auto run = std::make_shared<FixRun>();
    run->done = std::move(done);
    bool anyFixable = false;
    for (const SettingsFinding &finding : findings) {
        SettingsFixOutcome outcome;
        outcome.finding = finding;
        if (!finding.fixable()) {
            outcome.code = SettingsFixOutcome::Code::NotFixable;
            outcome.why = SettingsCheckTr::tr("nothing to write fixes this");
        }
        anyFixable = anyFixable || finding.fixable();
        run->outcomes.append(outcome);
    }
    if (!anyFixable) {
        run->done(run->outcomes);
        return;
    }
    run->servo = std::make_shared<ServoInfo>(findings.first().servo);
    std::vector<Step> steps {bus.setBaud(run->servo->baud)};
    for (Step &step : bus.readValues(run->servo, {registerkeys::kTorqueEnable},
                                     [run](const QString &, qint32 value) { run->torque = value; }))
        steps.push_back(std::move(step));
    bus.runSteps(std::move(steps), [&bus, run](bool ok, const QString &message) {
        if (!ok) {
            failUnsettled(
                *run,
                SettingsCheckTr::tr("not written: servo %1 does not answer (%2); check its "
                                    "cable and power")
                    .arg(run->servo->id)
                    .arg(message));
            run->done(run->outcomes);
            return;
        }
        writeFixes(bus, run);
    });
}

} // namespace feetech
