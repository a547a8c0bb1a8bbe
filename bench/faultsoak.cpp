// The fault soak's two runs, Feetech and PTK: the clients the GUI uses, a faulty simulated link,
// and after every operation a comparison with the simulator's own state.
#include "faultsoak.h"

#include "operationwait.h"

#include "busclient.h"
#include "ptkclient.h"
#include "simulatorthread.h"
#include "virtualfeetechbus.h"
#include "virtualptkservo.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTimer>

#include <functional>

namespace soak {

namespace {

constexpr int kServos = 6;
constexpr qint32 kFeetechBaud = 1000000;
constexpr int kOperationTimeoutMs = 20000;
constexpr int kMaxExamples = 10;

// Registers an apply may change without moving a horn whose torque is off: RAM and EEPROM.
const QStringList kFeetechKeys {
    QStringLiteral("acceleration"),    QStringLiteral("goal_speed"),
    QStringLiteral("torque_limit"),    QStringLiteral("p_gain"),
    QStringLiteral("d_gain"),          QStringLiteral("i_gain"),
    QStringLiteral("cw_dead_zone"),    QStringLiteral("ccw_dead_zone"),
    QStringLiteral("max_temperature"), QStringLiteral("min_startup_force")};

const QStringList kPtkKeys {QStringLiteral("gain"),           QStringLiteral("damping"),
                            QStringLiteral("deadband"),       QStringLiteral("max_power"),
                            QStringLiteral("overload_power"), QStringLiteral("overload_time_ms"),
                            QStringLiteral("soft_start")};

void note(SoakCounts &counts, const QString &text)
{
    if (counts.examples.size() < kMaxExamples)
        counts.examples.append(text);
}

// Runs the event loop until `done` is set by a signal or the time is up.
bool runUntil(const std::function<bool()> &done,
              const std::function<void(QEventLoop &)> &connectQuit, int timeoutMs)
{
    if (done())
        return true;
    QEventLoop loop;
    connectQuit(loop);
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    while (!done()) {
        loop.exec();
        if (!done())
            return false; // the timer ended it
    }
    return true;
}

// Starts an operation on `client` and waits for its final result.
std::optional<feetech::OperationResult>
runOperation(const std::function<feetech::OperationReply *()> &start)
{
    return soak::runOperation(start, kOperationTimeoutMs);
}

// A value in the register's range other than `current`.
qint64 otherValue(QRandomGenerator &random, const model::Definition &definition, qint64 current)
{
    const qint64 span = definition.maximum - definition.minimum + 1;
    qint64 value = current;
    while (value == current && span > 1)
        value = definition.minimum + qint64(random.bounded(quint32(span)));
    return value;
}

QStringList pickKeys(QRandomGenerator &random, const QStringList &keys, int count)
{
    QStringList chosen;
    while (chosen.size() < count) {
        const QString key = keys.at(int(random.bounded(quint32(keys.size()))));
        if (!chosen.contains(key))
            chosen.append(key);
    }
    return chosen;
}

// Settles what an apply reported for `key` against what the device holds.
void judgeWrite(SoakCounts &counts, const model::ParameterModel &parameters, const QString &key,
                qint64 asked, qint64 held, const QString &who, const QString &outcome)
{
    ++counts.writesAsked;
    switch (parameters.state(key)) {
    case model::State::Verified:
        if (held == asked) {
            ++counts.writesVerified;
        } else {
            ++counts.lostWrites;
            note(counts,
                 QStringLiteral("%1 %2: reported verified at %3, holds %4")
                     .arg(who, key)
                     .arg(asked)
                     .arg(held));
        }
        break;
    case model::State::Mismatch:
        ++counts.writesMismatch;
        if (parameters.deviceValue(key) != held) {
            ++counts.wrongValues;
            note(counts,
                 QStringLiteral("%1 %2: mismatch shows %3, holds %4, asked %5 (%6)")
                     .arg(who, key)
                     .arg(parameters.deviceValue(key).value_or(-1))
                     .arg(held)
                     .arg(asked)
                     .arg(outcome));
        }
        break;
    case model::State::Failed:
        if (held == asked) {
            ++counts.falseFailures;
            note(counts,
                 QStringLiteral("%1 %2: reported not written, holds the new value %3 (%4)")
                     .arg(who, key)
                     .arg(asked)
                     .arg(outcome));
        } else {
            ++counts.writesFailed;
        }
        break;
    case model::State::Unknown:
        ++counts.writesUnknown;
        break;
    default:
        ++counts.lostWrites;
        note(counts,
             QStringLiteral("%1 %2: left in state %3 after the apply")
                 .arg(who, key, model::ParameterModel::stateName(parameters.state(key))));
        break;
    }
}

// Every value `parameters` shows, against `held(key)`.
void checkShownValues(SoakCounts &counts, const model::ParameterModel &parameters,
                      const std::function<std::optional<qint64>(const QString &)> &held,
                      const QString &who)
{
    for (const model::Definition &definition : parameters.definitions()) {
        const auto shown = parameters.deviceValue(definition.key);
        const auto truth = held(definition.key);
        if (!shown || !truth)
            continue;
        ++counts.valuesChecked;
        if (*shown != *truth) {
            ++counts.wrongValues;
            note(counts,
                 QStringLiteral("%1 %2: shows %3, holds %4")
                     .arg(who, definition.key)
                     .arg(*shown)
                     .arg(*truth));
        }
    }
}

} // namespace

QJsonObject SoakCounts::toJson() const
{
    return {{QStringLiteral("transactions"), transactions},
            {QStringLiteral("reads_ok"), readsOk},
            {QStringLiteral("reads_failed"), readsFailed},
            {QStringLiteral("values_checked"), double(valuesChecked)},
            {QStringLiteral("wrong_values"), double(wrongValues)},
            {QStringLiteral("writes_asked"), writesAsked},
            {QStringLiteral("writes_verified"), writesVerified},
            {QStringLiteral("writes_mismatch"), writesMismatch},
            {QStringLiteral("writes_failed"), writesFailed},
            {QStringLiteral("writes_unknown"), writesUnknown},
            {QStringLiteral("lost_writes"), lostWrites},
            {QStringLiteral("false_failures"), falseFailures},
            {QStringLiteral("hangs"), hangs},
            {QStringLiteral("applies_refused_while_not_answering"), appliesRefused},
            {QStringLiteral("eeprom_left_unlocked"), eepromLeftUnlocked},
            {QStringLiteral("examples"), QJsonArray::fromStringList(examples)}};
}

SoakCounts soakFeetech(const SoakOptions &options)
{
    SoakCounts counts;
    QTemporaryDir dir;
    sim::SimulatorOptions bus;
    bus.kind = sim::SimulatorOptions::Kind::Feetech;
    bus.linkPath = dir.filePath(QStringLiteral("soak-feetech"));
    for (int id = 1; id <= kServos; ++id)
        bus.servos.append({quint8(id), QStringLiteral("STS3215"), kFeetechBaud});
    bus.logPath = qEnvironmentVariable("SERVOBENCH_SOAK_LOG"); // every frame, to study a failure
    sim::SimulatorThread simulator;
    QString error;
    if (!simulator.start(bus, &error)) {
        note(counts, QStringLiteral("the simulator did not start: %1").arg(error));
        ++counts.hangs;
        return counts;
    }
    const auto onBus = [&simulator](const std::function<void(sim::VirtualFeetechBus &)> &work) {
        simulator.call([&](sim::Simulator &running) {
            running.advanceNow();
            work(*running.feetechBus());
        });
    };
    // Idle servos settle at ambient + 0.75 °C: start them there, so that the temperature a read
    // shows is the one the simulator holds a moment later.
    onBus([](sim::VirtualFeetechBus &servos) {
        for (int index = 0; index < servos.servoCount(); ++index)
            servos.servo(index).setAmbientTemperature(servos.servo(index).temperature() - 0.75);
    });

    feetech::BusClient client;
    client.connectTo(bus.linkPath, kFeetechBaud);
    runUntil([&] { return client.link()->isConnected(); },
             [&](QEventLoop &loop) {
                 QObject::connect(&client, &feetech::BusClient::statusChanged, &loop,
                                  &QEventLoop::quit);
             },
             10000);
    feetech::ScanOptions scan;
    scan.firstId = 1;
    scan.lastId = kServos;
    bool scanned = false;
    client.scan(scan);
    runUntil([&] { return scanned; },
             [&](QEventLoop &loop) {
                 QObject::connect(&client, &feetech::BusClient::scanFinished, &loop, [&] {
                     scanned = true;
                     loop.quit();
                 });
             },
             20000);
    if (client.servos()->count() != kServos) {
        note(counts,
             QStringLiteral("the clean scan found %1 servos").arg(client.servos()->count()));
        ++counts.hangs;
        return counts;
    }
    for (int index = 0; index < kServos; ++index)
        runOperation([&] { return client.readServo(index); });

    simulator.call(
        [&](sim::Simulator &running) { running.setFaults(options.faults, options.seed); });
    QRandomGenerator random(options.seed);
    for (int transaction = 0; transaction < options.transactions; ++transaction) {
        ++counts.transactions;
        const int index = int(random.bounded(quint32(kServos)));
        const quint8 id = client.servos()->at(index).info.id;
        const QString who = QStringLiteral("ID %1").arg(id);
        model::ParameterModel &parameters = *client.servos()->parameters(index);
        const auto heldValue = [&](const QString &key) {
            std::optional<qint64> value;
            onBus([&](sim::VirtualFeetechBus &servos) {
                const sim::VirtualFeetechServo &servo = *servos.findServo(id);
                if (servo.table().find(key))
                    value = servo.value(key);
            });
            return value;
        };
        if (random.bounded(2u) == 0) {
            const auto result = runOperation([&] { return client.readServo(index); });
            if (!result) {
                ++counts.hangs;
                note(counts,
                     QStringLiteral("%1: a read never finished (busy %2, link %3, at %4)")
                         .arg(who)
                         .arg(client.isBusy())
                         .arg(int(client.link()->status().state))
                         .arg(transaction));
            } else if (result->ok) {
                ++counts.readsOk;
                checkShownValues(counts, parameters, heldValue, who);
            } else {
                ++counts.readsFailed;
            }
            continue;
        }
        const QStringList keys = pickKeys(random, kFeetechKeys, 1 + int(random.bounded(3u)));
        QHash<QString, qint64> asked;
        for (const QString &key : keys) {
            const model::Definition *definition = parameters.definition(key);
            const qint64 value =
                otherValue(random, *definition, parameters.deviceValue(key).value_or(0));
            parameters.edit(key, value);
            asked.insert(key, value);
        }
        feetech::Refusal refusal;
        const auto result = runOperation([&] { return client.apply(index, &refusal); });
        if (!result) {
            ++counts.hangs;
            note(counts,
                 QStringLiteral("%1: an apply never finished (%2)").arg(who, refusal.describe()));
        } else {
            for (const QString &key : keys)
                judgeWrite(counts, parameters, key, asked.value(key), heldValue(key).value_or(-1),
                           who, result->message);
        }
        parameters.revertAll(); // a failed edit is not carried into the next apply
    }

    simulator.call([](sim::Simulator &running) { running.setFaults({}, 1); });
    onBus([&](sim::VirtualFeetechBus &servos) {
        for (int index = 0; index < servos.servoCount(); ++index) {
            if (servos.servo(index).value(u"lock") == 0) {
                ++counts.eepromLeftUnlocked;
                note(counts,
                     QStringLiteral("ID %1: EEPROM left unlocked").arg(servos.servo(index).id()));
            }
        }
    });
    client.disconnectFrom();
    return counts;
}

SoakCounts soakPtk(const SoakOptions &options)
{
    SoakCounts counts;
    QTemporaryDir dir;
    sim::SimulatorOptions servoOptions;
    servoOptions.kind = sim::SimulatorOptions::Kind::Ptk;
    servoOptions.linkPath = dir.filePath(QStringLiteral("soak-ptk"));
    if (!qEnvironmentVariableIsEmpty("SERVOBENCH_SOAK_LOG"))
        servoOptions.logPath = qEnvironmentVariable("SERVOBENCH_SOAK_LOG") + QStringLiteral(".ptk");
    sim::SimulatorThread simulator;
    QString error;
    QElapsedTimer simulatorClock; // about the simulator log's clock
    simulatorClock.start();
    if (!simulator.start(servoOptions, &error)) {
        note(counts, QStringLiteral("the simulator did not start: %1").arg(error));
        ++counts.hangs;
        return counts;
    }
    const auto heldValue = [&simulator](const QString &key) {
        std::optional<qint64> value;
        const ptk::ParameterInfo *meta = ptk::findParameter(key);
        simulator.call([&](sim::Simulator &running) {
            if (const auto wire = running.ptkServo()->values().value(meta->parameter))
                value = *wire;
        });
        return value;
    };

    // The simulated servo needs none of the 50 ms the real one is given between write frames.
    ptk::SessionTiming timing;
    timing.writeGap = std::chrono::milliseconds(5);
    ptk::Client client(timing);
    client.connectTo(servoOptions.linkPath, 115200);
    runUntil([&] { return client.isConnected(); },
             [&](QEventLoop &loop) {
                 QObject::connect(&client, &ptk::Client::statusChanged, &loop, &QEventLoop::quit);
             },
             10000);
    client.setPolling(false);
    model::ParameterModel &parameters = *client.model();
    const auto read = [&]() -> std::optional<bool> {
        std::optional<bool> outcome;
        QEventLoop loop;
        const auto connection = QObject::connect(&client, &ptk::Client::readFinished, &loop,
                                                 [&](bool ok, const QString &) {
                                                     outcome = ok;
                                                     loop.quit();
                                                 });
        client.readAll();
        QTimer::singleShot(kOperationTimeoutMs, &loop, &QEventLoop::quit);
        if (!outcome)
            loop.exec();
        QObject::disconnect(connection);
        return outcome;
    };
    for (int attempt = 0; attempt < 5 && !read().value_or(false); ++attempt) { }

    simulator.call(
        [&](sim::Simulator &running) { running.setFaults(options.faults, options.seed); });
    QRandomGenerator random(options.seed);
    for (int transaction = 0; transaction < options.transactions; ++transaction) {
        ++counts.transactions;
        const QString who = QStringLiteral("PTK at %1 s")
                                .arg(double(simulatorClock.nsecsElapsed()) / 1e9, 0, 'f', 3);
        // After a query that got no answer the client says the servo does not answer and
        // refuses an Apply until one does: what the GUI's polling does then, a read, comes first.
        const bool answering = client.isConnected();
        if (!answering)
            ++counts.appliesRefused;
        if (!answering || random.bounded(2u) == 0) {
            const auto ok = read();
            if (!ok) {
                ++counts.hangs;
                note(counts, QStringLiteral("a read never finished"));
            } else if (*ok) {
                ++counts.readsOk;
                checkShownValues(counts, parameters, heldValue, who);
            } else {
                ++counts.readsFailed;
            }
            continue;
        }
        const QStringList keys = pickKeys(random, kPtkKeys, 1 + int(random.bounded(3u)));
        QHash<QString, qint64> asked;
        for (const QString &key : keys) {
            const qint64 value = otherValue(random, *parameters.definition(key),
                                            parameters.deviceValue(key).value_or(0));
            parameters.edit(key, value);
            asked.insert(key, value);
        }
        std::optional<bool> outcome;
        QEventLoop loop;
        const auto connection = QObject::connect(&client, &ptk::Client::applyFinished, &loop,
                                                 [&](bool ok, const QString &) {
                                                     outcome = ok;
                                                     loop.quit();
                                                 });
        QString refusal;
        if (client.apply(&refusal)) {
            QTimer::singleShot(kOperationTimeoutMs, &loop, &QEventLoop::quit);
            if (!outcome)
                loop.exec();
        }
        QObject::disconnect(connection);
        if (!outcome) {
            ++counts.hangs;
            note(counts, QStringLiteral("an apply never finished (%1)").arg(refusal));
        } else {
            for (const QString &key : keys)
                judgeWrite(counts, parameters, key, asked.value(key), heldValue(key).value_or(-1),
                           who, QString());
        }
        parameters.revertAll();
    }
    simulator.call([](sim::Simulator &running) { running.setFaults({}, 1); });
    client.disconnectFrom();
    return counts;
}

} // namespace soak
