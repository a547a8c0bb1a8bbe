// The Feetech bus operations: each the steps it runs on the bus, the flow it hands itself to,
// and the result it ends with.
#include "busoperations.h"

#include "busexchange.h"
#include "busscan.h"
#include "feetechdescription.h"
#include "feetechsessiontr.h"
#include "guardkeeper.h"
#include "guidedflows.h"
#include "healthcheck.h"
#include "healthmovetest.h"
#include "jointidentify.h"
#include "operationcontext.h"
#include "overloadrecovery.h"
#include "settingsbus.h"
#include "sharedidcheck.h"
#include "transport.h"

#include <QCoreApplication>

#include <algorithm>
#include <memory>

namespace {

// A hand-built frame whose answers cannot be named in advance (broadcast, SYNC READ) is listened
// to this long; what comes back shows in the packet log.
constexpr std::chrono::milliseconds kListenWindow {150};

} // namespace

namespace feetech::operations {

namespace {

BusOperation operation(Operation kind, std::function<void(OperationContext &)> start,
                       bool powersServos = false)
{
    BusOperation made;
    made.kind = kind;
    made.powersServos = powersServos;
    made.start = std::move(start);
    return made;
}

// The torque-enable register and its "off" value, as the tables of the servos at `baud` give
// them; the STS table's where none is known (a broadcast also reaches servos not scanned).
QVector<std::pair<int, qint32>> torqueOffWrites(const QVector<ServoInfo> &servos, qint32 baud)
{
    QVector<std::pair<int, qint32>> writes;
    const auto add = [&writes](const RegisterTable &table) {
        const Register *torque = table.find(u"torque_enable");
        const auto off = table.torqueValue(TorqueMode::Off);
        if (torque && off && !writes.contains(std::pair(torque->address, *off)))
            writes.append({torque->address, *off});
    };
    for (const ServoInfo &servo : servos) {
        if (servo.baud == baud && servo.hasTable())
            add(servo.table());
    }
    if (writes.isEmpty())
        add(RegisterTable::forFamily(Family::Sts));
    return writes;
}

// Reads torque enable back after All torque off; counts the servos that confirm it.
Step confirmTorqueOff(OperationContext &context, const ServoInfo &servo,
                      std::shared_ptr<int> confirmed)
{
    return [&context, servo, confirmed](StepDone next) {
        const Register *torque = registerAt(servo, u"torque_enable");
        const auto off =
            servo.hasTable() ? servo.table().torqueValue(TorqueMode::Off) : std::nullopt;
        if (!torque || !off) {
            context.bus().fail(
                next, OperationFailure::Unsupported,
                FeetechSessionTr::tr("%1 is of an unknown model; its torque was not read back.")
                    .arg(feetech::servoName(servo)));
            return;
        }
        Exchange ask;
        ask.request = feetech::read(servo.id, quint8(torque->address), 1);
        ask.replyId = servo.id;
        ask.replyDataSize = 1;
        const int address = torque->address;
        const qint32 offValue = *off;
        context.bus().exchange(
            ask,
            [&context, servo, confirmed, next, address, offValue](
                const seriallink::TransactionResult &answer, const std::optional<Packet> &reply) {
                if (!reply) {
                    context.bus().fail(next, failureKind(answer),
                                       FeetechSessionTr::tr("%1 did not confirm (no reply).")
                                           .arg(feetech::servoName(servo)));
                    return;
                }
                context.noteMemory(servo.id, servo.baud, address, reply->parameters, reply->code);
                if (quint8(reply->parameters.at(0)) != offValue) {
                    context.bus().fail(next, OperationFailure::NotVerified,
                                       FeetechSessionTr::tr("%1 still has torque on.")
                                           .arg(feetech::servoName(servo)));
                    return;
                }
                ++*confirmed;
                next(true, {});
            });
    };
}

// Sets the bus to `baud`, then runs `then` with `result`; a rate that cannot be set ends the
// operation with `result`, not ok, saying why.
void atBaud(OperationContext &context, qint32 baud, const OperationResult &result,
            std::function<void(OperationResult)> then)
{
    context.bus().setBaud(baud)(
        [&context, result, then = std::move(then)](bool ok, const QString &message) {
            if (ok) {
                then(result);
                return;
            }
            OperationResult failed = result;
            failed.ok = false;
            failed.message = message;
            failed.failure = context.bus().stepFailure();
            context.finish(failed);
        });
}

// The health check's next servo, or its end.
void checkNextServo(OperationContext &context, QVector<ServoInfo> servos, int done, int reads)
{
    const int total = int(servos.size());
    if (done >= total || context.health().isCancelled()) {
        const bool stopped = done < total;
        OperationResult result {
            Operation::HealthCheck,
            !stopped,
            stopped ? FeetechSessionTr::tr("The health check was stopped after %1 of %n "
                                           "servo(s).",
                                           nullptr, total)
                          .arg(done)
                    : FeetechSessionTr::tr("%n servo(s) checked.", nullptr, total),
            {},
            {}};
        if (stopped)
            result.failure = OperationFailure::Stopped;
        context.finish(result);
        return;
    }
    context.health().read(
        servos.at(done), reads, [&context, servos, done, reads](const HealthReading &reading) {
            if (!context.isLinkOpen())
                return; // the session has ended the check with the link
            context.reportProgress(
                {0, done + 1, int(servos.size()), {}, QVariant::fromValue(reading)});
            // Between two servos the bus is free: All torque off never waits for a whole check.
            context.continueLater(Operation::HealthCheck, [&context, servos, done, reads] {
                checkNextServo(context, servos, done + 1, reads);
            });
        });
}

// The settings check's next servo, or its end.
void readNextSettings(OperationContext &context, QVector<ServoInfo> servos, QStringList keys,
                      int done)
{
    const int total = int(servos.size());
    if (done >= total) {
        context.finish({Operation::CheckSettings,
                        true,
                        FeetechSessionTr::tr("The settings of %n servo(s) read.", nullptr, total),
                        {},
                        {}});
        return;
    }
    readSettings(context.bus(), servos.at(done), keys,
                 [&context, servos, keys, done](const SettingsReading &reading) {
                     if (!context.isLinkOpen())
                         return; // the session has ended the check with the link
                     context.reportProgress(
                         {0, done + 1, int(servos.size()), {}, QVariant::fromValue(reading)});
                     context.continueLater(Operation::CheckSettings,
                                           [&context, servos, keys, done] {
                                               readNextSettings(context, servos, keys, done + 1);
                                           });
                 });
}

// The fixes of the next servo among `findings` (grouped by servo), or the end.
void fixNextServo(OperationContext &context, QVector<QVector<SettingsFinding>> servos, int done,
                  QVector<SettingsFixOutcome> outcomes)
{
    if (done >= servos.size()) {
        const int verified = int(
            std::count_if(outcomes.begin(), outcomes.end(),
                          [](const SettingsFixOutcome &outcome) { return outcome.verified(); }));
        const bool ok = verified == outcomes.size();
        OperationResult result {Operation::FixSettings,
                                ok,
                                FeetechSessionTr::tr("%1 of %n setting(s) fixed and verified.",
                                                     nullptr, int(outcomes.size()))
                                    .arg(verified),
                                servos.isEmpty() ? ServoInfo {} : servos.first().first().servo,
                                {}};
        if (!ok)
            result.failure = OperationFailure::NotVerified;
        result.writesSent = true;
        result.detail = QVariant::fromValue(outcomes);
        context.finish(result);
        return;
    }
    context.reportProgress({0, done, int(servos.size()), {}, {}});
    fixSettings(context.bus(), servos.at(done),
                [&context, servos, done, outcomes](const QVector<SettingsFixOutcome> &fixed) {
                    if (!context.isLinkOpen())
                        return;
                    context.continueLater(
                        Operation::FixSettings, [&context, servos, done, outcomes, fixed] {
                            fixNextServo(context, servos, done + 1, outcomes + fixed);
                        });
                });
}

} // namespace

BusOperation scan(const ScanOptions &options)
{
    return operation(Operation::Scan,
                     [options](OperationContext &context) { context.scan().start(options); });
}

BusOperation ping(quint8 id, qint32 baud)
{
    return operation(Operation::Ping, [id, baud](OperationContext &context) {
        OperationResult pinged {Operation::Ping, false, {}, {}, {}};
        pinged.servo.id = id;
        pinged.servo.baud = baud;
        atBaud(context, baud, pinged, [&context, id](OperationResult result) {
            Exchange ask;
            ask.request = feetech::ping(id);
            ask.replyId = id;
            context.bus().exchange(
                ask,
                [&context, result](const seriallink::TransactionResult &answer,
                                   const std::optional<Packet> &reply) mutable {
                    result.ok = reply.has_value();
                    result.failure = reply ? OperationFailure::None : failureKind(answer);
                    result.latency = answer.latency;
                    result.message = reply
                        ? FeetechSessionTr::tr("Servo %1 answers.").arg(result.servo.id)
                        : FeetechSessionTr::tr("Servo %1 does not answer: %2")
                              .arg(result.servo.id)
                              .arg(failureText(answer));
                    if (reply)
                        context.noteStatus(result.servo.id, result.servo.baud, reply->code);
                    context.finish(result);
                });
        });
    });
}

BusOperation checkSharedId(const ServoInfo &servo)
{
    return operation(Operation::CheckSharedId, [servo](OperationContext &context) {
        atBaud(context, servo.baud, {Operation::CheckSharedId, false, {}, servo, {}},
               [&context, servo](const OperationResult &) {
                   feetech::checkSharedId(
                       context.bus(), servo, false,
                       [&context, servo](SharedIdVerdict verdict,
                                         const seriallink::TransactionResult &last) {
                           OperationResult result {Operation::CheckSharedId, true, {}, servo, {}};
                           result.servo.sharedId = verdict == SharedIdVerdict::Shared;
                           if (result.servo.sharedId)
                               result.message = sharedIdRefusal(servo.id);
                           if (verdict == SharedIdVerdict::Failed
                               || verdict == SharedIdVerdict::Silent) {
                               result.ok = false;
                               result.failure = verdict == SharedIdVerdict::Failed
                                   ? failureKind(last)
                                   : OperationFailure::NoAnswer;
                               result.message = verdict == SharedIdVerdict::Failed
                                   ? failureText(last)
                                   : FeetechSessionTr::tr(
                                         "%1 stopped answering: check the power and the cable, "
                                         "then look again.")
                                         .arg(servoName(servo));
                           }
                           context.finish(result);
                       });
               });
    });
}

BusOperation read(const ServoInfo &servo, const QVector<Block> &blocks, ReadSource source)
{
    BusOperation made =
        operation(Operation::Read, [servo, blocks, source](OperationContext &context) {
            auto target = std::make_shared<ServoInfo>(servo);
            std::vector<Step> steps {context.bus().setBaud(servo.baud)};
            QVector<Block> toRead = blocks;
            if (toRead.isEmpty())
                toRead = servo.hasTable() ? servo.table().blocks()
                                          : QVector<Block> {{0, RegisterTable::kRawViewSize}};
            steps.push_back(context.bus().readBlocks(target, toRead, source));
            context.bus().runSteps(
                std::move(steps), [&context, servo](bool ok, const QString &message) {
                    OperationResult result {
                        Operation::Read,
                        ok,
                        ok ? FeetechSessionTr::tr("Read %1.").arg(feetech::servoName(servo))
                           : message,
                        servo,
                        {}};
                    if (!ok)
                        result.failure = context.bus().stepFailure();
                    context.finish(result);
                });
        });
    // The guard learns of every servo read, as early as it is asked for.
    made.submitted = [servo](OperationContext &context) {
        context.guard().noteServo(servo);
    };
    return made;
}

BusOperation write(const ServoInfo &servo, const QVector<RegisterWrite> &writes)
{
    return operation(
        Operation::Write,
        [servo, writes](OperationContext &context) {
            context.guard().noteWrites(servo, writes);
            context.apply().write(servo, writes, context.finisher());
        },
        true);
}

BusOperation apply(const ServoInfo &servo, const ApplyPlan &plan)
{
    return operation(
        Operation::Write,
        [servo, plan](OperationContext &context) {
            context.guard().noteWrites(servo, plan.writes);
            // Each step's result is reported as it comes; the last one ends the operation.
            context.apply().apply(
                servo, plan, [&context](const OperationResult &step) { context.reportStep(step); },
                context.finisher(),
                [&context](Operation next, std::function<void()> resume) {
                    context.continueLater(next, std::move(resume));
                });
        },
        true);
}

BusOperation changeId(const ServoInfo &servo, int newId, const QVector<int> &idsInUse)
{
    return operation(Operation::ChangeId, [servo, newId, idsInUse](OperationContext &context) {
        context.flows().changeId(servo, newId, idsInUse, context.finisher());
    });
}

BusOperation changeBaud(const ServoInfo &servo, qint32 newBaud)
{
    return operation(Operation::ChangeBaud, [servo, newBaud](OperationContext &context) {
        context.flows().changeBaud(servo, newBaud, context.finisher());
    });
}

BusOperation calibrateMiddle(const ServoInfo &servo)
{
    return operation(Operation::CalibrateMiddle, [servo](OperationContext &context) {
        context.flows().calibrateMiddle(servo, context.finisher());
    });
}

BusOperation factoryReset(const ServoInfo &servo)
{
    return operation(Operation::FactoryReset, [servo](OperationContext &context) {
        context.flows().factoryReset(servo, context.finisher());
    });
}

BusOperation reboot(const ServoInfo &servo)
{
    return operation(Operation::Reboot, [servo](OperationContext &context) {
        context.flows().reboot(servo, context.finisher());
    });
}

BusOperation clearStatus(const ServoInfo &servo)
{
    return operation(Operation::ClearStatus, [servo](OperationContext &context) {
        auto target = std::make_shared<ServoInfo>(servo);
        std::vector<Step> steps {
            context.bus().setBaud(servo.baud),
            context.bus().instruction(servo.id, feetech::reset(servo.id), servo.repliesToWrites(),
                                      FeetechSessionTr::tr("Clearing the status"))};
        if (const Register *status = registerAt(servo, u"status"))
            steps.push_back(
                context.bus().read(target, status->address, status->size, ReadSource::ReadBack));
        context.bus().runSteps(
            std::move(steps), [&context, servo](bool ok, const QString &message) {
                OperationResult result {
                    Operation::ClearStatus,
                    ok,
                    ok ? FeetechSessionTr::tr("Status of servo %1 cleared.").arg(servo.id)
                       : message,
                    servo,
                    {}};
                if (!ok)
                    result.failure = context.bus().stepFailure();
                context.finish(result);
            });
    });
}

BusOperation lockEeprom(const ServoInfo &servo)
{
    return operation(Operation::LockEeprom, [servo](OperationContext &context) {
        const Register *lock = registerAt(servo, u"lock");
        if (!lock) {
            OperationResult result {
                Operation::LockEeprom,
                false,
                FeetechSessionTr::tr("The servo's model has no known EEPROM lock register."),
                servo,
                {}};
            result.failure = OperationFailure::Unsupported;
            context.finish(result);
            return;
        }
        auto target = std::make_shared<ServoInfo>(servo);
        // What the servo says after the write, not that the write was answered, is the result.
        auto readBack = std::make_shared<std::optional<int>>();
        std::vector<Step> steps {
            context.bus().setBaud(servo.baud), context.bus().lock(target, true),
            context.bus().read(target, lock->address, lock->size, ReadSource::ReadBack,
                               [readBack](const QByteArray &bytes) {
                                   if (!bytes.isEmpty())
                                       *readBack = quint8(bytes.at(0));
                               })};
        context.bus().runSteps(
            std::move(steps), [&context, servo, readBack](bool ok, const QString &message) {
                const bool locked = ok && readBack->has_value() && **readBack != 0;
                QString text = message;
                if (locked)
                    text = FeetechSessionTr::tr("Servo %1's EEPROM is locked (read back).")
                               .arg(servo.id);
                else if (ok)
                    text = FeetechSessionTr::tr(
                               "Servo %1 still reads back unlocked after the lock was written.")
                               .arg(servo.id);
                OperationResult result {Operation::LockEeprom, locked, text, servo, {}};
                if (!ok)
                    result.failure = context.bus().stepFailure();
                else if (!locked)
                    result.failure = OperationFailure::NotVerified;
                context.finish(result);
            });
    });
}

BusOperation sendPacket(const QByteArray &frame, qint32 baud, std::optional<quint8> replyId,
                        int replyDataSize)
{
    // Like any write: one asked for before All torque off must not power the servos again.
    return operation(
        Operation::SendPacket,
        [frame, baud, replyId, replyDataSize](OperationContext &context) {
            OperationResult sent {Operation::SendPacket, false, {}, {}, {}};
            sent.servo.baud = baud;
            atBaud(context, baud, sent,
                   [&context, frame, replyId, replyDataSize](OperationResult result) {
                       Exchange ask;
                       ask.request = frame;
                       ask.retryCount = 0; // sent once, as the user built it
                       if (replyId) {
                           ask.replyId = replyId;
                           ask.replyDataSize = replyDataSize;
                           result.servo.id = *replyId;
                       } else {
                           ask.listenOnly = true;
                           ask.silenceExpected = true;
                           ask.replyTimeout = kListenWindow;
                       }
                       context.bus().exchange(
                           ask,
                           [&context, result, replyId](const seriallink::TransactionResult &answer,
                                                       const std::optional<Packet> &reply) mutable {
                               result.latency = answer.latency;
                               if (answer.failure == seriallink::Failure::LinkDown) {
                                   result.failure = OperationFailure::LinkLost;
                                   result.message = failureText(answer);
                               } else if (!replyId) {
                                   result.ok = true;
                                   result.message = FeetechSessionTr::tr(
                                       "Sent; its answers, if any, are in the packet log.");
                               } else {
                                   result.ok = reply.has_value();
                                   if (!reply)
                                       result.failure = failureKind(answer);
                                   result.message = reply
                                       ? FeetechSessionTr::tr("Servo %1 answered.").arg(*replyId)
                                       : FeetechSessionTr::tr("Sent; servo %1 did not answer: %2")
                                             .arg(*replyId)
                                             .arg(failureText(answer));
                               }
                               context.finish(result);
                           });
                   });
        },
        true);
}

BusOperation identifyJoint(const ServoInfo &servo)
{
    BusOperation made = operation(
        Operation::Identify,
        [servo](OperationContext &context) {
            context.guard().noteDriven(servo);
            context.identify().run(servo, context.finisher(),
                                   [&context](std::chrono::milliseconds delay,
                                              std::function<void(bool torqueOff)> resume) {
                                       context.pauseFor(delay, std::move(resume));
                                   });
        },
        true);
    made.submitted = [](OperationContext &context) {
        context.identify().clearCancel();
    };
    return made;
}

BusOperation torqueOffAll(const QVector<qint32> &bauds, const QVector<ServoInfo> &servos)
{
    BusOperation made = operation(Operation::TorqueOff, [bauds, servos](OperationContext &context) {
        // Every step goes on whatever failed before it: one silent servo or an odd rate must not
        // keep the others powered.
        auto problems = std::make_shared<QStringList>();
        auto confirmed = std::make_shared<int>(0);
        const auto tolerant = [problems](Step step) -> Step {
            return [problems, step = std::move(step)](StepDone next) {
                step([problems, next](bool ok, const QString &message) {
                    if (!ok)
                        problems->append(message);
                    next(true, {});
                });
            };
        };
        std::vector<Step> steps;
        for (const qint32 baud : bauds) {
            steps.push_back(tolerant(context.bus().setBaud(baud)));
            for (const auto &[address, value] : torqueOffWrites(servos, baud))
                steps.push_back(tolerant(context.bus().write(
                    kBroadcastId, address, QByteArray(1, char(value)), false,
                    FeetechSessionTr::tr("Torque off at %1").arg(baudText(baud)))));
            for (const ServoInfo &servo : servos) {
                if (servo.baud == baud)
                    steps.push_back(tolerant(confirmTorqueOff(context, servo, confirmed)));
            }
        }
        context.bus().runSteps(
            std::move(steps), [&context, problems, confirmed](bool, const QString &) {
                const QString message = problems->isEmpty()
                    ? FeetechSessionTr::tr(
                        "Torque off: sent to the whole bus; %n servo(s) confirmed it.", nullptr,
                        *confirmed)
                    : FeetechSessionTr::tr("Torque off was sent to the whole bus, but: %1")
                          .arg(problems->join(QLatin1Char(' ')));
                OperationResult result {Operation::TorqueOff, problems->isEmpty(), message, {}, {}};
                // Sent to the whole bus either way: what failed is the confirmation.
                if (!result.ok)
                    result.failure = OperationFailure::NotVerified;
                context.finish(result);
            });
    });
    made.priority = BusOperation::Priority::Emergency;
    return made;
}

BusOperation syncWrite(qint32 baud, int address, int length, const QVector<SyncWriteEntry> &entries)
{
    return operation(
        Operation::SyncWrite,
        [baud, address, length, entries](OperationContext &context) {
            context.guard().noteSyncWrite(baud, address, entries);
            const auto frame = feetech::syncWrite(quint8(address), quint8(length), entries);
            if (!frame) {
                OperationResult result {
                    Operation::SyncWrite,
                    false,
                    FeetechSessionTr::tr("The SYNC WRITE does not fit in one packet."),
                    {},
                    {}};
                result.failure = OperationFailure::InvalidRequest;
                context.finish(result);
                return;
            }
            std::vector<Step> steps {
                context.bus().setBaud(baud),
                context.bus().instruction(
                    kBroadcastId, *frame, false,
                    FeetechSessionTr::tr("SYNC WRITE at %1").arg(baudText(baud)))};
            context.bus().runSteps(
                std::move(steps), [&context, entries](bool ok, const QString &message) {
                    OperationResult result {
                        Operation::SyncWrite,
                        ok,
                        ok ? FeetechSessionTr::tr("Sent to %n servo(s) in one SYNC WRITE.", nullptr,
                                                  int(entries.size()))
                           : message,
                        {},
                        {}};
                    if (!ok)
                        result.failure = context.bus().stepFailure();
                    context.finish(result);
                });
        },
        true);
}

BusOperation recoverOverload(const ServoInfo &servo, bool checkOnly)
{
    // Only a recovery switches the torque on again: a check after a power cycle reads only.
    return operation(
        Operation::RecoverOverload,
        [servo, checkOnly](OperationContext &context) {
            auto target = std::make_shared<ServoInfo>(servo);
            auto latched = std::make_shared<std::optional<bool>>();
            context.bus().runSteps(
                {context.bus().setBaud(servo.baud),
                 feetech::recoverOverload(context.bus(), target, checkOnly, latched)},
                [&context, servo, checkOnly, latched](bool ok, const QString &message) {
                    OperationResult result {Operation::RecoverOverload, ok, message, servo, {}};
                    if (!ok) {
                        result.failure = context.bus().stepFailure();
                    } else if (latched->value_or(false)) {
                        result.ok = false;
                        result.failure = OperationFailure::StillLatched;
                        result.message = powerCycleSteps(servo).join(QLatin1Char('\n'));
                    } else {
                        result.message = checkOnly
                            ? FeetechSessionTr::tr(
                                  "Servo ID %1: the overload bit is clear; switch its torque "
                                  "on when you are ready.")
                                  .arg(servo.id)
                            : FeetechSessionTr::tr(
                                  "Servo ID %1 recovered: the overload bit is clear and it "
                                  "holds where it stands with torque on.")
                                  .arg(servo.id);
                        if (!checkOnly) {
                            const Register *torque = registerAt(servo, u"torque_enable");
                            const auto on = servo.table().torqueValue(TorqueMode::On);
                            if (torque && on)
                                context.guard().noteWrites(
                                    servo, {{torque->address, QByteArray(1, char(*on))}});
                        }
                    }
                    context.bus().logNote(result.message, !result.ok);
                    context.finish(result);
                });
        },
        !checkOnly);
}

BusOperation findMotor(const MotorTarget &target)
{
    BusOperation made = operation(Operation::FindMotor, [target](OperationContext &context) {
        context.motorSetup().find(target, [&context](const MotorSearch &search) {
            MotorSetupResult result;
            result.ok = search.foundOne();
            result.search = search;
            result.stopped = search.stopped;
            result.from = result.to = search.servo;
            result.message = search.message;
            result.failure = search.failure();
            OperationResult finished {
                Operation::FindMotor, result.ok, result.message, search.servo, {}};
            finished.failure = result.failure;
            finished.detail = QVariant::fromValue(result);
            context.finish(finished);
        });
    });
    made.submitted = [](OperationContext &context) {
        context.motorSetup().clearCancel();
    };
    return made;
}

BusOperation setUpMotor(const MotorTarget &target)
{
    BusOperation made = operation(
        Operation::SetUpMotor,
        [target](OperationContext &context) {
            context.motorSetup().setUp(target, [&context](const MotorSetupResult &result) {
                OperationResult finished {
                    Operation::SetUpMotor, result.ok, result.message, result.to, {}};
                finished.failure = result.failure;
                finished.detail = QVariant::fromValue(result);
                context.finish(finished);
            });
        },
        true);
    made.submitted = [](OperationContext &context) {
        context.motorSetup().clearCancel();
    };
    return made;
}

BusOperation checkJoints(qint32 baud, const QVector<JointCheck> &joints)
{
    BusOperation made =
        operation(Operation::CheckJoints, [baud, joints](OperationContext &context) {
            context.motorSetup().check(
                baud, joints, [&context](const QVector<JointCheck> &checked) {
                    const auto done =
                        std::count_if(checked.begin(), checked.end(),
                                      [](const JointCheck &joint) { return joint.done(); });
                    OperationResult finished {
                        Operation::CheckJoints,
                        true,
                        FeetechSessionTr::tr("%1 of %n joint(s) already set up.", nullptr,
                                             int(checked.size()))
                            .arg(done),
                        {},
                        {}};
                    finished.detail = QVariant::fromValue(checked);
                    context.finish(finished);
                });
        });
    made.submitted = [](OperationContext &context) {
        context.motorSetup().clearCancel();
    };
    return made;
}

BusOperation checkHealth(const QVector<ServoInfo> &servos, int reads)
{
    BusOperation made =
        operation(Operation::HealthCheck, [servos, reads](OperationContext &context) {
            checkNextServo(context, servos, 0, reads);
        });
    made.submitted = [](OperationContext &context) {
        context.health().clearCancel();
    };
    return made;
}

BusOperation moveTest(const ServoInfo &servo)
{
    return operation(
        Operation::MoveTest,
        [servo](OperationContext &context) {
            context.guard().noteDriven(servo); // the guard watches the move as it does any other
            context.moveTest().run(
                servo,
                [&context](std::chrono::milliseconds delay,
                           std::function<void(bool torqueOff)> resume) {
                    context.pauseFor(delay, std::move(resume));
                },
                [&context, servo](const MoveTestResult &result) {
                    OperationResult finished {
                        Operation::MoveTest, result.ok, result.message, servo, {}};
                    finished.failure = result.failure;
                    finished.detail = QVariant::fromValue(result);
                    context.finish(finished);
                });
        },
        true);
}

BusOperation checkSettings(const QVector<ServoInfo> &servos, const QStringList &keys)
{
    return operation(Operation::CheckSettings, [servos, keys](OperationContext &context) {
        readNextSettings(context, servos, keys, 0);
    });
}

BusOperation fixSettings(const QVector<SettingsFinding> &findings)
{
    QVector<QVector<SettingsFinding>> servos;
    for (const SettingsFinding &finding : findings) {
        auto same = std::find_if(servos.begin(), servos.end(), [&finding](const auto &group) {
            return group.first().servo.address() == finding.servo.address();
        });
        if (same == servos.end())
            servos.append({finding});
        else
            same->append(finding);
    }
    // A torque limit raised with torque on would move the horn: it needs torque off, and is
    // refused then; so the fix itself does not power the servos.
    return operation(Operation::FixSettings,
                     [servos](OperationContext &context) { fixNextServo(context, servos, 0, {}); });
}

BusOperation replayMotion(const ReplayPlan &plan)
{
    BusOperation made = operation(
        Operation::Replay,
        [plan](OperationContext &context) {
            for (const ServoInfo &servo : plan.servos)
                context.guard().noteDriven(servo); // the guard watches the move as any other
            MotionReplay::Hooks hooks;
            hooks.finish = context.finisher();
            hooks.pause = [&context](std::chrono::milliseconds delay,
                                     std::function<void(bool torqueOff)> resume) {
                context.pauseFor(delay, std::move(resume));
            };
            hooks.progress = [&context](const OperationProgress &progress) {
                context.reportProgress(progress);
            };
            hooks.sent = [&context](qint32 baud, int address,
                                    const QVector<SyncWriteEntry> &entries) {
                context.guard().noteSyncWrite(baud, address, entries);
            };
            context.replay().run(plan, std::move(hooks));
        },
        true);
    made.submitted = [](OperationContext &context) {
        context.replay().clearCancel();
    };
    return made;
}

} // namespace feetech::operations
